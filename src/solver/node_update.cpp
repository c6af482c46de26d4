// The field nodes' phases of Stepper::step, done body by body: the internal forces, the
// velocity update (free nodes, driven nodes and load-driven carriers) and the position
// update. See stepper.h.
#include <chrono>
#include <cmath>
#include <exception>

#include <omp.h>

#include "core/error.h"
#include "core/parallel.h"
#include "solver/implicit_viscosity.h"
#include "solver/stepper.h"

namespace sg {

namespace {

// Per body, the sums of the velocity update (NodeUpdate's node fields, in this order, and the
// IMEX damping correction).
constexpr std::size_t kBodySums = 6;
// Per node drive: the imposed velocities at t_n+1/2 (2: the drive's history, or the carrier's
// new velocity under load), the reaction (2) and R . v_n-1/2, R . v_n+1/2 (2, velocity-driven
// components only). A drive's nodes are in one body: one thread writes its sums.
constexpr std::size_t kDriveSums = 6;

}  // namespace

namespace {

// Per body: kinetic energy (time-centred), power of gravity, f_v . v_n+1/2, and of the total
// force F_n on each parameter F_n . v_n+1/2 and F_n . F_n / m (the kinetic energies K_n^+ and
// K_n^- of the header, as corrections of the time-centred one); IMEX: the damping correction.
struct BodySums {
  double kinetic = 0.0, external_power = 0.0, viscous_power = 0.0, force_power = 0.0,
         force_square = 0.0, damping_correction = 0.0;
  // Node i after its update from (vx_old, vy_old); (bgx, bgy): the body's gravity.
  void add_node(const NodeState& n, std::size_t i, double vx_old, double vy_old, double bgx,
                double bgy) {
    kinetic += 0.5 * n.mass[i] * (vx_old * n.vx[i] + vy_old * n.vy[i]);
    force_power += n.fx[i] * n.vx[i] + n.fy[i] * n.vy[i];
    force_square += n.inverse_mass[i] * (n.fx[i] * n.fx[i] + n.fy[i] * n.fy[i]);
    viscous_power += n.viscous_fx[i] * n.vx[i] + n.viscous_fy[i] * n.vy[i];
    external_power += n.mass[i] * (bgx * n.vx[i] + bgy * n.vy[i]);
  }
};

// The explicit update of one body's nodes. Two instances: grains (no driven nodes, the hot
// case) never look at NodeState::drive; a strip with a driven back face checks each node.
template <bool kHasDrivenNodes>
void advance_body_explicitly(const Model& model, NodeState& n, const Body& body, double h,
                             double* drive_data, BodySums& sums) {
  const double bgx = model.gravity.x() / body.mass_scale, bgy = model.gravity.y() / body.mass_scale;
  for (int k = body.node_begin; k < body.node_end; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double vx_old = n.vx[i], vy_old = n.vy[i];
    const int drive = kHasDrivenNodes ? n.drive[i] : -1;
    if (drive < 0) {
      n.vx[i] += h * n.inverse_mass[i] * n.fx[i];
      n.vy[i] += h * n.inverse_mass[i] * n.fy[i];
    } else {
      // Driven component: v_n+1/2 imposed, the reaction R_I = m_I (v_n+1/2 - v_n-1/2) / h - f_I
      // added to the force (header).
      const NodeDrive& nd = model.node_drives[static_cast<std::size_t>(drive)];
      double* drive_sums = drive_data + kDriveSums * static_cast<std::size_t>(drive);
      double* velocity[2] = {&n.vx[i], &n.vy[i]};
      double* force[2] = {&n.fx[i], &n.fy[i]};
      for (std::size_t c = 0; c < 2; ++c) {
        if (nd.mode[c] == DriveMode::free) {
          *velocity[c] += h * n.inverse_mass[i] * *force[c];
          continue;
        }
        const double v_old = *velocity[c], v_new = drive_sums[c];
        const double reaction = n.mass[i] * (v_new - v_old) / h - *force[c];
        *force[c] += reaction;  // fx, fy: the total force on the parameter
        *velocity[c] = v_new;
        drive_sums[2 + c] += reaction;
        if (nd.mode[c] == DriveMode::velocity) {  // a carrier's work: as a servo load's
          drive_sums[4] += reaction * v_old;
          drive_sums[5] += reaction * v_new;
        }
      }
    }
    sums.add_node(n, i, vx_old, vy_old, bgx, bgy);
  }
}

// The internal forces of body b at u_n, v_n-1/2 (model/internal_forces.h), with the IMEX
// solve's `carried` viscous force if it has one and that holds at v_n-1/2 and h
// (implicit_viscosity.h): then the kernel computes the elastic forces alone, the carried force
// is added to them, and the damping power is -f_v . v_n-1/2.
BodyForceResult add_internal_forces_of(Model& model, BodyId b, double h,
                                       CarriedViscousForce* carried, Mat2* gradients) {
  if (!carried) return add_body_internal_forces(model, b, gradients);
  NodeState& n = model.nodes;
  const Body& body = model.body(b);
  const auto o = static_cast<std::size_t>(body.node_begin);
  if (!carried->use_at(n.vx.data() + o, n.vy.data() + o, h))
    return add_body_internal_forces(model, b, gradients);
  BodyForceResult result =
      add_body_internal_forces(model, b, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o,
                               n.vy.data() + o, n.fx.data() + o, n.fy.data() + o, false);
  double power = 0.0;
  for (std::size_t j = 0; j < carried->fx.size(); ++j) {
    const std::size_t i = o + j;
    n.viscous_fx[i] = carried->fx[j];
    n.viscous_fy[i] = carried->fy[j];
    n.fx[i] += carried->fx[j];
    n.fy[i] += carried->fy[j];
    power -= carried->fx[j] * n.vx[i] + carried->fy[j] * n.vy[i];
  }
  result.damping_power = power;
  return result;
}

// IMEX (implicit_viscosity.h): the body's increments dv from (M + h/2 C) dv = h F, the force
// applied F* = M dv / h; the viscous force booked becomes f_v + F* - F, whose power against
// v_n-1/2 corrects the closing half of the damping dissipation. `carried` (if not null) gets
// the viscous force at v_n+1/2, f_v + 2 (F* - F) (implicit_viscosity.h).
void advance_body_implicitly(const Model& model, NodeState& n, BodyId b, double h,
                             ImplicitViscosity& viscosity, double* increment_x, double* increment_y,
                             CarriedViscousForce* carried, BodySums& sums) {
  const Body& body = model.body(b);
  const double bgx = model.gravity.x() / body.mass_scale, bgy = model.gravity.y() / body.mass_scale;
  const auto o = static_cast<std::size_t>(body.node_begin);
  double* dvx = increment_x + o;
  double* dvy = increment_y + o;
  // (The force phase of this step left F at u_n in the solve's store: gradients_given.)
  viscosity.solve(model, b, h, n.ux.data() + o, n.uy.data() + o, n.fx.data() + o, n.fy.data() + o,
                  dvx, dvy, true);
  for (int k = body.node_begin; k < body.node_end; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double vx_old = n.vx[i], vy_old = n.vy[i];
    const double ax = dvx[i - o], ay = dvy[i - o];
    const double fx = n.mass[i] * ax / h, fy = n.mass[i] * ay / h;
    const double change_x = fx - n.fx[i], change_y = fy - n.fy[i];  // F* - F
    sums.damping_correction += change_x * vx_old + change_y * vy_old;
    if (carried) {
      carried->fx[i - o] = n.viscous_fx[i] + 2.0 * change_x;
      carried->fy[i - o] = n.viscous_fy[i] + 2.0 * change_y;
    }
    n.viscous_fx[i] += change_x;
    n.viscous_fy[i] += change_y;
    n.fx[i] = fx;
    n.fy[i] = fy;
    n.vx[i] = vx_old + ax;
    n.vy[i] = vy_old + ay;
    sums.add_node(n, i, vx_old, vy_old, bgx, bgy);
  }
  if (carried) carried->carried_to(n.vx.data() + o, n.vy.data() + o, h);
}

// u_n+1 = u_n + dt v_n+1/2 for the body's nodes; returns a probe that is NaN iff some updated
// value is not finite (0 * inf = NaN).
double advance_body_positions(NodeState& n, const Body& body, double dt) {
  double finite_probe = 0.0;
  for (int k = body.node_begin; k < body.node_end; ++k) {
    const auto i = static_cast<std::size_t>(k);
    n.ux[i] += dt * n.vx[i];
    n.uy[i] += dt * n.vy[i];
    finite_probe += 0.0 * (n.ux[i] + n.uy[i] + n.vx[i] + n.vy[i]);
  }
  return finite_probe;
}

}  // namespace

void Stepper::apply_body_gravity(const Body& body) {
  // With lumped (row-sum) masses, the consistent gravity load on the parameter I is
  // integral(N_I rho g) = m_I g. Gravity acts on the physical mass (mass scaling changes the
  // inertia only).
  NodeState& n = model_.nodes;
  const double bgx = model_.gravity.x() / body.mass_scale,
               bgy = model_.gravity.y() / body.mass_scale;
  for (int k = body.node_begin; k < body.node_end; ++k) {
    const auto i = static_cast<std::size_t>(k);
    n.fx[i] = n.mass[i] * bgx;
    n.fy[i] = n.mass[i] * bgy;
  }
}

bool Stepper::waits_for_carrier(const Body& body) const {
  if (body.node_drive < 0) return false;
  const NodeDrive& nd = model_.node_drives[static_cast<std::size_t>(body.node_drive)];
  return nd.mode[0] == DriveMode::load || nd.mode[1] == DriveMode::load;
}

void Stepper::advance_body(BodyId b, const StepSizes& steps, double* drive_data) {
  const Body& body = model_.body(b);
  NodeState& n = model_.nodes;
  const double h = steps.velocity_interval;
  BodySums sums;
  if (implicit_ && has_implicit_viscosity(model_, b))
    advance_body_implicitly(model_, n, b, h, *implicit_, increment_x_.data(), increment_y_.data(),
                            implicit_->carried_viscous_force(b), sums);
  else if (body.node_drive < 0)
    advance_body_explicitly<false>(model_, n, body, h, drive_data, sums);
  else
    advance_body_explicitly<true>(model_, n, body, h, drive_data, sums);
  body_probes_[static_cast<std::size_t>(b)] = advance_body_positions(n, body, steps.next);
  double* out = body_sums_.data() + kBodySums * static_cast<std::size_t>(b);
  out[0] = sums.kinetic;
  out[1] = sums.external_power;
  out[2] = sums.viscous_power;
  out[3] = sums.force_power;
  out[4] = sums.force_square;
  out[5] = sums.damping_correction;
}

// The forces, velocities and positions of the field nodes, body by body (stepper.h); the
// carriers' bodies after the carriers.
Stepper::FieldNodeUpdate Stepper::advance_field_nodes(const StepSizes& steps, PhaseTimer& timer) {
  double* const drive_data = prepare_field_node_update(steps);
  advance_bodies(steps, drive_data, timer);
  FieldNodeUpdate update;
  try {  // an invalid deformation first, as when the forces were a phase of their own
    update.internal = sum_internal_forces(model_, body_forces_);
  } catch (const Error& e) {
    SG_THROW(e.what() << " at step " << state_.step << ", time " << state_.time);
  }
  body_error_.rethrow_if_any();
  update.nodes.carriers = advance_node_carriers(steps.velocity_interval, drive_data);
  for (int b = 0; b < static_cast<int>(model_.bodies.size()); ++b)
    if (waits_for_carrier(model_.body(b))) advance_body(b, steps, drive_data);
  add_node_sums(drive_data, update.nodes);
  return update;
}

double* Stepper::prepare_field_node_update(const StepSizes& steps) {
  const std::size_t drive_count = model_.node_drives.size();
  body_sums_.assign(kBodySums * model_.bodies.size() + kDriveSums * drive_count, 0.0);
  double* const drive_data = body_sums_.data() + kBodySums * model_.bodies.size();
  const double t_mid = state_.time + 0.5 * steps.next;  // velocities live at half steps
  for (std::size_t d = 0; d < drive_count; ++d)
    for (int c = 0; c < 2; ++c)
      if (model_.node_drives[d].mode[c] == DriveMode::velocity)
        drive_data[kDriveSums * d + static_cast<std::size_t>(c)] =
            model_.node_drives[d].velocity[c](t_mid);
  if (implicit_) {
    increment_x_.resize(model_.nodes.vx.size());
    increment_y_.resize(model_.nodes.vy.size());
  }
  body_forces_.assign(model_.bodies.size(), BodyForceResult{});
  body_probes_.assign(model_.bodies.size(), 0.0);
  body_error_ = LowestIndexError{};
  force_kernel();  // chosen here, outside the threads: a bad SOFTGRAIN_SIMD throws to the caller
  return drive_data;
}

void Stepper::advance_bodies(const StepSizes& steps, double* drive_data, PhaseTimer& timer) {
  // Each body's forces (gravity, the contact forces evaluated before, its internal forces),
  // velocities and positions one after the other, by the same thread while its nodes are in
  // that core's cache: nothing in between reads another body's nodes (a body's forces are its
  // own nodes'; a velocity drive's imposed velocities are set before). A node's force is
  // summed in the same order as by phases (gravity, contacts, internal): the same bits.
  //
  // Done as two phases, each with its own dynamic schedule, half the bodies changed core
  // between them: on the 400-grain cell (corotational, 2 threads) the velocity update's stores
  // of the nodes' forces and velocities waited for the other core's cache lines, and the
  // velocity phase took 3.0-4.0 s against 4.55 s on 1 thread.
  //
  // A body whose node drive carries a load waits for the carriers (advance_field_nodes), and
  // one with an invalid deformation is not advanced (the step stops with its name). Each thread
  // takes a contiguous range of bodies of about equal cost, the bodies' times at the previous
  // step (core/cost_balanced_ranges.h): a body keeps its thread, and its nodes that core's
  // cache, from one step to the next, and the objective model's uneven solves stay balanced.
  // The error of the lowest body is kept (core/parallel.h), the sums per body: nothing depends
  // on the thread count or on which thread ran a body.
  const std::vector<Mat2*>* gradients = implicit_ ? &implicit_->gradient_outputs() : nullptr;
  body_ranges_.resize(model_.bodies.size());
  double applied_seconds = 0.0, force_seconds = 0.0, update_seconds = 0.0;
#pragma omp parallel reduction(+ : applied_seconds, force_seconds, update_seconds)
  {
#pragma omp single
    body_ranges_.plan(omp_get_num_threads());
    using clock = std::chrono::steady_clock;
    clock::time_point last = clock::now();
    const auto book = [&last](double& seconds) {
      const clock::time_point now = clock::now();
      const double elapsed = std::chrono::duration<double>(now - last).count();
      seconds += elapsed;
      last = now;
      return elapsed;
    };
    const int thread = omp_get_thread_num();
    for (std::size_t k = body_ranges_.next(thread); k != CostBalancedRanges::none();
         k = body_ranges_.next(thread)) {
      const auto b = static_cast<BodyId>(k);
      double body_seconds = 0.0;
      try {
        apply_body_gravity(model_.body(b));
        if (contacts_) contacts_->add_body_contact_forces(model_, b);
        body_seconds += book(applied_seconds);
        body_forces_[k] =
            add_internal_forces_of(model_, b, steps.velocity_interval,
                                   implicit_ ? implicit_->carried_viscous_force(b) : nullptr,
                                   gradients ? (*gradients)[k] : nullptr);
        body_seconds += book(force_seconds);
        if (body_forces_[k].bad_gauss_point < 0 && !waits_for_carrier(model_.body(b)))
          advance_body(b, steps, drive_data);
      } catch (...) {
        body_error_.record(b, std::current_exception());
      }
      body_ranges_.record(k, body_seconds + book(update_seconds));
    }
  }
  timer.stamp_split({{StepPhase::contacts, applied_seconds},
                     {StepPhase::internal_forces, force_seconds},
                     {StepPhase::velocities, update_seconds}});
}

void Stepper::add_node_sums(const double* drive_data, NodeUpdate& nodes) {
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const double* sums = body_sums_.data() + kBodySums * b;
    nodes.kinetic += sums[0];
    nodes.external_power += sums[1];
    nodes.viscous_power += sums[2];
    nodes.force_power += sums[3];
    nodes.force_square += sums[4];
    if (implicit_) nodes.damping_correction -= sums[5];
  }
  for (std::size_t d = 0; d < model_.node_drives.size(); ++d) {
    const double* sums = drive_data + kDriveSums * d;
    model_.node_drives[d].reaction = Vec2(sums[2], sums[3]);
    nodes.drive_work_old += sums[4];
    nodes.drive_work_new += sums[5];
  }
}

ServoPower Stepper::advance_node_carriers(double h, double* drive_data) const {
  ServoPower power;
  const NodeState& n = model_.nodes;
  for (std::size_t d = 0; d < model_.node_drives.size(); ++d) {
    const NodeDrive& nd = model_.node_drives[d];
    for (std::size_t c = 0; c < 2; ++c) {
      SG_VERIFY(nd.mode[c] != DriveMode::force,
                "body '" << model_.body(nd.body).name
                         << "': a node drive cannot impose a constant force (use load)");
      if (nd.mode[c] != DriveMode::load) continue;
      SG_VERIFY(!nd.nodes.empty(), "body '" << model_.body(nd.body).name
                                            << "': a load-driven node drive has no nodes");
      // The carrier: mass, momentum and received force of its nodes, summed in node order
      // (serial: the same bits on any number of threads).
      const std::vector<double>& v = c == 0 ? n.vx : n.vy;
      const std::vector<double>& f = c == 0 ? n.fx : n.fy;
      double mass = 0.0, momentum = 0.0, received = 0.0;
      for (int k : nd.nodes) {
        const auto i = static_cast<std::size_t>(k);
        mass += n.mass[i];
        momentum += n.mass[i] * v[i];
        received += f[i];
      }
      // M (v_n+1/2 - v_n-1/2) = h (received + F(t_n) - c v_n+1/2), as a servo-loaded rigid
      // degree of freedom (advance_rigid_bodies), with M v_n-1/2 the carrier's momentum.
      const double load = nd.load[c](state_.time);
      const double damping = nd.load_damping[c];
      const double v_old = momentum / mass;
      const double v_new = (momentum + h * (received + load)) / (mass + h * damping);
      drive_data[kDriveSums * d + c] = v_new;
      power.load_old += load * v_old;
      power.load_new += load * v_new;
      power.servo_old += damping * v_new * v_old;
      power.servo_new += damping * v_new * v_new;
    }
  }
  return power;
}

void Stepper::finish_step(double dt) {
  state_.previous_dt = dt;
  state_.time += dt;
  ++state_.step;
  double finite_probe = 0.0;
  for (double p : body_probes_)
    finite_probe += p;
  if (finite_probe != 0.0 || !std::isfinite(finite_probe)) check_finite_velocities();
}

void Stepper::wrap_periodic_bodies() {
  const double period = model_.x_max - model_.x_min;
  NodeState& n = model_.nodes;
  for (const Body& body : model_.bodies) {
    double shift = 0.0;
    if (body.kind == BodyKind::rigid) {
      double& x = model_.rigid.x[static_cast<std::size_t>(body.rigid_index)];
      if (x < model_.x_min)
        shift = period;
      else if (x >= model_.x_max)
        shift = -period;
      x += shift;
      continue;
    }
    // A deformable body is moved by one period through its reference positions: u, v and
    // every precomputed row are invariant under a translation of the reference frame.
    const auto first = static_cast<std::size_t>(body.node_begin);
    double x = n.ref_x[first] + n.ux[first];
    if (body.open_contour) {
      // A strip spans the cell: its first contour node sits at one end, where round-off would
      // wrap it back and forth every step. Its middle (between its two ends) is kept in the
      // cell instead: a strip drifting along x moves by a period once it has drifted L/2.
      const auto last = static_cast<std::size_t>(body.boundary_end - 1);
      x = 0.5 * (x + n.ref_x[last] + n.ux[last]);
    }
    if (x < model_.x_min)
      shift = period;
    else if (x >= model_.x_max)
      shift = -period;
    if (shift != 0.0)
      for (int i = body.node_begin; i < body.node_end; ++i)
        n.ref_x[static_cast<std::size_t>(i)] += shift;
  }
}

void Stepper::check_finite_velocities() const {
  const NodeState& n = model_.nodes;
  for (const Body& body : model_.bodies)
    for (int i = body.node_begin; i < body.node_end; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!std::isfinite(n.vx[k]) || !std::isfinite(n.vy[k]) || !std::isfinite(n.ux[k]) ||
          !std::isfinite(n.uy[k]))
        SG_THROW("body '" << body.name << "', node " << i - body.node_begin
                          << ": non-finite velocity or displacement after step " << state_.step
                          << " (time " << state_.time
                          << "): the time step is too large or the input is inconsistent");
    }
}

}  // namespace sg
