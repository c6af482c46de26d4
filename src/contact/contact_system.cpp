#include "contact/contact_system.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/parallel.h"
#include "core/rounding.h"
#include "model/kinematics.h"

namespace sg {

namespace {

ContourView contour_view(const Body& body, const std::vector<Vec2>& positions) {
  ContourView view;
  view.points = std::span<const Vec2>(positions.data() + body.contour_begin,
                                      static_cast<std::size_t>(body.contour_count()));
  view.closed = true;
  if (body.open_contour) view.closing_shift = Vec2(body.closing_shift_x, 0.0);
  return view;
}

}  // namespace

ContactSystem::ContactSystem(const Model& model, const MaterialPairTable& laws,
                             const ContactSettings& settings)
    : per_pass_laws_(laws.per_pass()), settings_(settings), broad_phase_([&] {
        BroadPhaseParams p;
        p.cutoff = settings.cutoff;
        p.skin = settings.skin > 0.0 ? settings.skin : settings.cutoff;
        p.periodic_x = model.periodic_x;
        p.x_min = model.x_min;
        p.x_max = model.x_max;
        validate(p);
        return p;
      }()) {
  SG_VERIFY(laws.material_count() == static_cast<int>(model.materials.size()),
            "contact laws are defined for " << laws.material_count() << " materials, the model has "
                                            << model.materials.size());
  std::vector<int> present;
  for (const Body& b : model.bodies)
    present.push_back(b.material);
  laws.verify_covers(present);
  for (int a = 0; a < laws.material_count(); ++a)
    for (int b = a; b < laws.material_count(); ++b)
      if (laws.has(a, b))
        max_stiffness_ =
            std::max({max_stiffness_, laws.at(a, b).normal_stiffness,
                      laws.at(a, b).tangential_stiffness, laws.at(a, b).bond_normal_stiffness});
  for (std::size_t k = 0; k < model.contour_point_count(); ++k)
    node_body_.push_back(model.contour_body[k]);
  for (int a = 0; a < laws.material_count(); ++a)
    for (int b = a; b < laws.material_count(); ++b)
      damped_ = damped_ || (laws.has(a, b) && laws.at(a, b).damping_ratio > 0.0);
  // The initial tributary lengths L0 (the model is built, not yet stepped or restored).
  update_geometry(model);
  initial_tributary_ = tributary_;
  previous_positions_.clear();
}

void ContactSystem::update_body_masses(const Model& model) {
  // The inertia the contact damping sees (contact_law.h): nodal masses (as scaled) of a
  // deformable body, the mass of a rigid one, infinite for a rigid body whose translation is
  // imposed. Read at the first evaluation: mass scaling is applied after construction.
  body_mass_.assign(model.bodies.size(), 0.0);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.kind == BodyKind::rigid) {
      const auto r = static_cast<std::size_t>(body.rigid_index);
      const RigidDrive& drive = model.rigid.drive[r];
      const bool imposed =
          drive.mode[0] == DriveMode::velocity || drive.mode[1] == DriveMode::velocity;
      body_mass_[b] = imposed ? std::numeric_limits<double>::infinity() : model.rigid.mass[r];
    } else {
      for (int i = body.node_begin; i < body.node_end; ++i)
        body_mass_[b] += model.nodes.mass[static_cast<std::size_t>(i)];
    }
  }
}

double ContactSystem::effective_mass(BodyId a, BodyId b) const {
  if (body_mass_.empty()) return 0.0;
  const double ma = body_mass_[static_cast<std::size_t>(a)];
  const double mb = body_mass_[static_cast<std::size_t>(b)];
  // Two bodies moved at imposed velocities: nothing for a damper to act on.
  if (std::isinf(ma) && std::isinf(mb)) return 0.0;
  if (std::isinf(ma)) return mb;
  if (std::isinf(mb)) return ma;
  return ma * mb / (ma + mb);
}

void ContactSystem::update_geometry(const Model& model) {
  compute_contour_positions(model, positions_, &rotations_);
  check_finite_positions(model);
  if (previous_positions_.size() != positions_.size()) previous_positions_ = positions_;
  const std::size_t n = positions_.size();
  segment_start_.resize(n);
  segment_end_.resize(n);
  segment_body_.resize(n);
  tributary_.resize(n);
  // Segment k runs from contour point k to the next point of its body (global numbering:
  // a body's segments are [contour_begin, contour_end), like its points). Each body writes
  // its own range: in parallel, on models with enough points to pay for a parallel loop.
  const auto body_count = static_cast<std::ptrdiff_t>(model.bodies.size());
#pragma omp parallel for schedule(static) if (n >= kParallelContourPoints)
  for (std::ptrdiff_t b = 0; b < body_count; ++b) {
    const Body& body = model.bodies[static_cast<std::size_t>(b)];
    const ContourView view = contour_view(body, positions_);
    for (int s = 0; s < body.contour_count(); ++s) {
      const auto k = static_cast<std::size_t>(body.contour_begin + s);
      segment_start_[k] = view.segment_start(s);
      segment_end_[k] = view.segment_end(s);
      segment_body_[k] = static_cast<int>(b);
    }
    tributary_lengths(view, std::span<double>(tributary_.data() + body.contour_begin,
                                              static_cast<std::size_t>(body.contour_count())));
  }
}

void ContactSystem::check_finite_positions(const Model& model) const {
  for (const Body& body : model.bodies)
    for (int k = body.contour_begin; k < body.contour_end; ++k) {
      const Vec2& p = positions_[static_cast<std::size_t>(k)];
      if (!p.allFinite())
        SG_THROW("body '" << body.name << "', contour point " << k - body.contour_begin
                          << ": position (" << p.x() << ", " << p.y()
                          << ") is not finite: the step exploded or the input is inconsistent");
    }
}

void ContactSystem::check_segment_widths(const Model& model) const {
  const double period = model.x_max - model.x_min;
  const double allowed = period - 2.0 * (broad_phase_.params().cutoff + broad_phase_.params().skin);
  if (!(allowed > 0.0)) return;  // the reach itself: the broad phase says so (and the scenario)
  for (const Body& body : model.bodies)
    for (int k = body.contour_begin; k < body.contour_end; ++k) {
      const auto s = static_cast<std::size_t>(k);
      const double width = std::abs(segment_end_[s].x() - segment_start_[s].x());
      if (!(width < allowed))
        SG_THROW("body '" << body.name << "', contour segment " << k - body.contour_begin
                          << " spans " << width << " in x, more than the periodic cell (length "
                          << period << ") allows (" << allowed
                          << " = the period less 2 (cutoff + skin)): the body has exploded; "
                             "check its material and the contact laws acting on it (cohesion, "
                             "normal_stiffness), or the step");
    }
}

ContactStepResult ContactSystem::add_contact_forces(Model& model,
                                                    const ContactEvaluation& evaluation) {
  const ContactStepResult result = evaluate_contacts(model, evaluation);
  // Bodies are independent (a contour point's row holds nodes of its own body only).
  const auto bodies = static_cast<std::ptrdiff_t>(model.bodies.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (std::ptrdiff_t b = 0; b < bodies; ++b)
    add_body_contact_forces(model, static_cast<BodyId>(b));
  return result;
}

ContactStepResult ContactSystem::evaluate_contacts(Model& model,
                                                   const ContactEvaluation& evaluation) {
  if (damped_ && body_mass_.empty()) update_body_masses(model);
  update_geometry(model);
  const BroadPhaseInput input{positions_, node_body_, segment_start_, segment_end_, segment_body_};
  if (broad_phase_.needs_rebuild(input)) {
    if (model.periodic_x) check_segment_widths(model);
    broad_phase_.build(input);
  }
  const std::span<const ContactCandidate> candidates = broad_phase_.candidates();
  group_candidates(candidates);

  // Scratch arrays are members reused from step to step: no allocation in the step once
  // their capacity has grown. Not cleared: evaluate_group writes every group's result
  // (r.active at least) and history, and its stored energy whenever the scatter reads it
  // (r.active). Clearing them rewrote 160 bytes per group each step (46 MB on 10,000 grains,
  // far beyond the cache).
  results_.resize(groups_.size());
  new_history_.resize(groups_.size());
  stored_.resize(groups_.size());
  const int group_count = static_cast<int>(groups_.size());
#pragma omp parallel for schedule(static)
  for (int g = 0; g < group_count; ++g)
    evaluate_group(model, candidates, static_cast<std::size_t>(g), evaluation);

  const ContactStepResult result = scatter_forces(model);
  // A swap, not a copy: positions_ is recomputed in full at the next evaluation.
  previous_positions_.swap(positions_);
  return result;
}

void ContactSystem::group_candidates(std::span<const ContactCandidate> candidates) {
  // Group candidates by (slave point, master body): contiguous, since candidates are sorted
  // by (node, segment) and a body's segments are contiguous.
  groups_.clear();
  // Each group's previous history (index into histories_, -1: none). The groups come in
  // increasing (slave point, master body) order (a body's segments are contiguous and
  // numbered in body order), and so do the histories (written by the scatter in group
  // order): one merge walk finds them all, O(1) per group. A binary search per group cost
  // O(log n) (bench_contacts: ~60 more instructions per boundary node on 10,000 grains than
  // on 100).
  group_history_.clear();
  std::size_t cursor = 0;
  for (std::size_t i = 0; i < candidates.size();) {
    std::size_t j = i + 1;
    const int body = segment_body_[static_cast<std::size_t>(candidates[i].segment)];
    while (j < candidates.size() && candidates[j].node == candidates[i].node &&
           segment_body_[static_cast<std::size_t>(candidates[j].segment)] == body)
      ++j;
    groups_.push_back({i, j});
    const int slave = candidates[i].node;
    while (cursor < histories_.size() &&
           std::make_pair(histories_[cursor].slave_point, histories_[cursor].master_body) <
               std::make_pair(slave, body))
      ++cursor;
    const bool found = cursor < histories_.size() && histories_[cursor].slave_point == slave &&
                       histories_[cursor].master_body == body;
    group_history_.push_back(found ? static_cast<int>(cursor) : -1);
    i = j;
  }
  SG_VALIDATE(std::is_sorted(histories_.begin(), histories_.end(),
                             [](const ContactHistoryEntry& a, const ContactHistoryEntry& b) {
                               return std::make_pair(a.slave_point, a.master_body) <
                                      std::make_pair(b.slave_point, b.master_body);
                             }),
              "contact histories are not sorted by (slave point, master body)");
}

ContactSystem::GroupProjection ContactSystem::project_group(
    const Model& model, std::span<const ContactCandidate> candidates, const ContactGroup& group,
    const Body& master_body) const {
  // Nearest periodic image of the node relative to EACH candidate segment, recomputed from
  // current positions (the broad-phase shift is from build time). One shift per group is
  // not enough: a first body spans the whole period, so a node near the seam can have
  // candidates at both ends of the strip (the closing segment near x_min and segment 0
  // near x_max), each needing its own image; projecting with the first segment's shift
  // put the node on the far end and reported a deep false penetration at the corner.
  //
  // The candidates are compared by distance alone (is_closer: ties go to the lower segment), and
  // the normals are computed for the closest only (most of a projection's cost; the 400-grain
  // imex cell has 1.8 candidates per group).
  const Vec2 unshifted = positions_[static_cast<std::size_t>(candidates[group.begin].node)];
  const ContourView view = contour_view(master_body, positions_);
  NodeProjection nearest;  // segment and distance only, for is_closer
  double nearest_shift = 0.0;
  for (std::size_t c = group.begin; c < group.end; ++c) {
    const auto segment = static_cast<std::size_t>(candidates[c].segment);
    const double candidate_shift =
        model.periodic_x ? nearest_image_shift(broad_phase_.params(), unshifted,
                                               segment_start_[segment], segment_end_[segment])
                         : 0.0;
    NodeProjection candidate;
    candidate.segment = candidates[c].segment - master_body.contour_begin;
    candidate.distance =
        contour_segment_distance(unshifted + Vec2(candidate_shift, 0.0), view, candidate.segment);
    if (is_closer(candidate, nearest)) {
      nearest = candidate;
      nearest_shift = candidate_shift;
    }
  }
  GroupProjection best;
  if (nearest.segment < 0) return best;
  best.projection =
      project_on_contour_segment(unshifted + Vec2(nearest_shift, 0.0), view, nearest.segment);
  best.shift = nearest_shift;
  return best;
}

double ContactSystem::slip_increment(const Model& model, int slave, const Body& master_body,
                                     const GroupProjection& projection) const {
  const NodeProjection& proj = projection.projection;
  const double period = model.x_max - model.x_min;
  const ContourView view = contour_view(master_body, positions_);
  const Vec2 node = positions_[static_cast<std::size_t>(slave)] + Vec2(projection.shift, 0.0);
  // Slip increment: relative tangential motion of the node and its projection since the
  // previous evaluation (previous positions shifted by the same image).
  const ContourView old_view = contour_view(master_body, previous_positions_);
  Vec2 node_old = previous_positions_[static_cast<std::size_t>(slave)];
  node_old.x() += projection.shift;
  // If the node or the body wrapped across the seam between evaluations, the displacement
  // is taken modulo the period.
  if (model.periodic_x) {
    const double dx = (node.x() - node_old.x());
    node_old.x() += period * round_half_away(dx / period);
  }
  // The master may have wrapped across the seam too: bring its old segment next to the new one.
  Vec2 old_start = old_view.segment_start(proj.segment),
       old_end = old_view.segment_end(proj.segment);
  if (model.periodic_x) {
    const double wrap =
        period * round_half_away((view.segment_start(proj.segment).x() - old_start.x()) / period);
    old_start.x() += wrap;
    old_end.x() += wrap;
  }
  // On the interior of a segment the slip is measured along the segment (ds = 0 for any
  // rigid motion of node and segment together). When the closest point is a vertex, the
  // normal is the direction from the vertex to the node and the tangential force acts along
  // perp(normal), which is not the tangent of either adjacent segment; measuring the slip
  // along the segment then made the tangential spring non-conservative, and at two corners
  // that coincide (a block bonded to a grip of the same width) the projection alternates
  // between the two segments of the vertex, each time reinterpreting the stored slip along
  // the other segment. Bonded blocks measured: the grips' corner springs slid at their
  // threshold ~100 times per time unit, ledger residual -1e-3 (energy created), interface
  // noise as large as the mean traction. At a vertex the slip is therefore the relative
  // motion of the node and the vertex along the contact's own tangent, which is the same
  // whichever segment of the vertex was picked.
  if (proj.t > 0.0 && proj.t < 1.0)
    return tangential_slip_increment(node_old, old_start, old_end, node,
                                     view.segment_start(proj.segment),
                                     view.segment_end(proj.segment), proj.t);
  const Vec2 vertex_old = proj.t >= 1.0 ? old_end : old_start;
  return proj.tangent.dot((node - node_old) - (proj.point - vertex_old));
}

void ContactSystem::evaluate_group(const Model& model, std::span<const ContactCandidate> candidates,
                                   std::size_t g, const ContactEvaluation& evaluation) {
  const ContactGroup& group = groups_[g];
  const int slave = candidates[group.begin].node;
  const BodyId master = segment_body_[static_cast<std::size_t>(candidates[group.begin].segment)];
  const Body& master_body = model.body(master);
  const BodyId slave_body = node_body_[static_cast<std::size_t>(slave)];
  const GroupProjection projection = project_group(model, candidates, group, master_body);
  const NodeProjection& proj = projection.projection;
  ContactRecord& r = results_[g];
  const int previous = group_history_[g];
  ContactHistory h =
      previous >= 0 ? histories_[static_cast<std::size_t>(previous)].history : ContactHistory{};
  if (proj.segment < 0 || (proj.gap >= settings_.cutoff && !h.active)) {
    r.active = false;
    new_history_[g] = ContactHistory{};
    return;
  }
  const double ds = slip_increment(model, slave, master_body, projection);
  const ContactLawParams& law =
      per_pass_laws_.at(model.body(slave_body).material, master_body.material);
  ContactKinematics kin;
  kin.normal_gap = proj.gap;
  kin.slip_increment = h.active ? ds : 0.0;
  kin.interval = evaluation.previous_step;
  kin.effective_mass = law.damping_ratio > 0.0 ? effective_mass(slave_body, master) : 0.0;
  kin.initial_length = initial_tributary_[static_cast<std::size_t>(slave)];
  kin.first_evaluation = evaluation.first;
  const ContactTraction tr = evaluate_contact_law(law, kin, h);
  new_history_[g] = h;
  r.slave_point = slave;
  r.slave_body = slave_body;
  r.master_body = master;
  r.master_segment = master_body.contour_begin + proj.segment;
  r.t = proj.t;
  r.position = positions_[static_cast<std::size_t>(slave)];
  r.normal = proj.normal;
  r.gap = proj.gap;
  r.length = law.length == ContactLength::initial ? kin.initial_length
                                                  : tributary_[static_cast<std::size_t>(slave)];
  r.traction = tr;
  r.active = h.active || tr.normal != 0.0 || tr.tangential != 0.0 || tr.dissipated != 0.0;
  stored_[g] = r.length * stored_energy(law, proj.gap, h);
}

void ContactSystem::add_force_at_point(Model& model, int point, const Vec2& f, const Vec2& at) {
  const BodyId b = node_body_[static_cast<std::size_t>(point)];
  const Body& body = model.body(b);
  if (body.kind != BodyKind::rigid) {
    point_forces_.push_back({point, f});  // spread to the nodes by spread_point_forces
    return;
  }
  const auto r = static_cast<std::size_t>(body.rigid_index);
  model.rigid.fx[r] += f.x();
  model.rigid.fy[r] += f.y();
  Vec2 arm = at - Vec2(model.rigid.x[r], model.rigid.y[r]);
  if (model.periodic_x) {
    const double period = model.x_max - model.x_min;
    arm.x() -= period * round_half_away(arm.x() / period);
  }
  model.rigid.torque[r] += cross(arm, f);
}

void ContactSystem::sort_point_forces_by_body(const Model& model) {
  // A stable counting sort: each body then receives its forces in the order the serial
  // scatter gave them, and a node's sum is the same bit for bit, whatever the thread count.
  const std::size_t body_count = model.bodies.size();
  const auto body_of = [&](const PointForce& pf) {
    return static_cast<std::size_t>(node_body_[static_cast<std::size_t>(pf.point)]);
  };
  body_force_start_.assign(body_count + 1, 0);
  for (const PointForce& pf : point_forces_)
    ++body_force_start_[body_of(pf) + 1];
  for (std::size_t b = 0; b < body_count; ++b)
    body_force_start_[b + 1] += body_force_start_[b];
  sorted_point_forces_.resize(point_forces_.size());
  body_force_fill_.assign(body_force_start_.begin(), body_force_start_.end() - 1);
  for (const PointForce& pf : point_forces_)
    sorted_point_forces_[body_force_fill_[body_of(pf)]++] = pf;
}

void ContactSystem::add_body_contact_forces(Model& model, BodyId body_id) const {
  const auto b = static_cast<std::size_t>(body_id);
  const Body& body = model.bodies[b];
  if (body.kind == BodyKind::rigid) return;  // applied by the scatter
  // The point forces onto the body's MLS parameters, then the moment of their hat offsets
  // (kinematics.h), spread once per body.
  double moment = 0.0;
  for (std::size_t k = body_force_start_[b]; k < body_force_start_[b + 1]; ++k) {
    const PointForce& pf = sorted_point_forces_[k];
    moment += add_contour_node_force(model, body, body.node_begin + (pf.point - body.contour_begin),
                                     pf.force, rotations_[b]);
  }
  add_body_rotation_moment(model, body, moment, rotations_[b]);
}

ContactStepResult ContactSystem::scatter_forces(Model& model) {
  // Serial in candidate order (deterministic whatever the thread count); the deformable
  // bodies' point forces are spread to their nodes body by body (add_body_contact_forces).
  ContactStepResult result;
  std::vector<ContactHistoryEntry>& next = next_histories_;
  next.clear();
  records_.clear();
  point_forces_.clear();
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const ContactRecord& r = results_[g];
    if (!r.active) continue;
    const Vec2 tangent = perp(r.normal);
    const Vec2 f = r.length * (r.traction.normal * r.normal + r.traction.tangential * tangent);
    const Body& master = model.body(r.master_body);
    const int local = r.master_segment - master.contour_begin;
    const int a = r.master_segment;
    const int b = master.contour_begin + (local + 1) % master.contour_count();
    add_force_at_point(model, r.slave_point, f,
                       positions_[static_cast<std::size_t>(r.slave_point)]);
    add_force_at_point(model, a, -(1.0 - r.t) * f, segment_start_[static_cast<std::size_t>(a)]);
    add_force_at_point(model, b, -r.t * f, segment_end_[static_cast<std::size_t>(a)]);
    result.dissipated += r.length * r.traction.dissipated;
    result.stored_energy += stored_[g];
    ++result.active_contacts;
    records_.push_back(r);
    if (new_history_[g].active || new_history_[g].stored_slip != 0.0)
      next.push_back({r.slave_point, r.master_body, new_history_[g]});
  }
  sort_point_forces_by_body(model);
  histories_.swap(next);
  return result;
}

}  // namespace sg
