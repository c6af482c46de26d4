#pragma once
// The contact stage of a time step (docs/method.md §Contact; paper 000 §2, paper 001 §2.1):
// two-pass node-to-segment penalty contact between every pair of distinct bodies.
//
//   1. contour positions of all bodies (deformable: MLS-evaluated boundary nodes; rigid:
//      moved contour points);
//   2. broad phase (Verlet cell grid, periodic in x), rebuilt only when a point moved by more
//      than half the skin;
//   3. narrow phase per (slave contour point, master body): closest segment of the master
//      among the candidates, signed gap, slip increment since the last evaluation;
//   4. law (per material pair, strengths halved for each pass) with the history of that
//      (slave point, master body) contact, the time since the previous evaluation, the two
//      bodies' effective mass and the point's initial tributary length (contact damping), and
//      whether this is the run's first evaluation (where bonded laws form their bonds);
//   5. force f = l (p_n n + p_t t) on the slave point (l its current tributary length, or
//      its initial one for a law with length = initial), -f on
//      the master segment's end points with weights (1 - s, s): action equals reaction;
//      forces on a deformable body's contour point are spread to the MLS parameters with the
//      transpose of its position's derivative (its contact-consistent row, model/kinematics.h
//      add_contour_node_force), on a rigid body they add to its force and torque.
//
// Determinism: narrow phase and laws run in parallel per candidate group into per-group
// results; forces are scattered serially in candidate order.
//
// Why a class, where docs/architecture.md §Conventions 5 prefers pure functions over plain data:
// the physics of a contact is pure and lives apart (contact_law.h, node_segment.h); what this
// class adds is state that must stay consistent across steps (histories sorted by (slave point,
// master body), which one merge walk per step relies on; the previous positions the slip
// increments are measured from; the broad phase built from them) and scratch buffers reused
// from step to step so that a step allocates nothing (§Conventions 2). Its evolving state is
// exposed as the plain struct ContactSystemState (capture / restore), which checkpoints and
// rollbacks copy as is.
#include <span>
#include <vector>

#include "contact/broad_phase.h"
#include "contact/contact_law.h"
#include "contact/material_pair_table.h"
#include "contact/node_segment.h"
#include "model/kinematics.h"
#include "model/model.h"

namespace sg {

struct ContactSettings {
  // Pairs whose gap is below `cutoff` are evaluated: at least the largest adhesive reach
  // sigma_c / k_n of any cohesive law, and a fraction of the node spacing for the others.
  double cutoff = 0.0;
  double skin = 0.0;  // Verlet margin (length); 0: cutoff
};

// One evaluated contact, for output (VTK contact network) and tests.
struct ContactRecord {
  int slave_point = 0;  // global contour point
  BodyId slave_body = 0, master_body = 0;
  int master_segment = 0;        // global segment index (= its first contour point)
  double t = 0.0;                // projection parameter on the segment
  Vec2 position = Vec2::Zero();  // slave point
  Vec2 normal = Vec2::Zero();    // master outward normal
  double gap = 0.0;
  double length = 0.0;       // tributary length of the slave point
  ContactTraction traction;  // per unit length
  bool active = false;       // the law carries load (or a bond holds)
};

// Persistent per-contact memory, keyed by (slave contour point, master body).
struct ContactHistoryEntry {
  int slave_point = 0;
  BodyId master_body = 0;
  ContactHistory history;
};

// Everything a ContactSystem carries from one step to the next: what a checkpoint saves and
// a rejected step restores (solver/state_snapshot.h). Positions, segments and tributary
// lengths are recomputed from the model at each evaluation and are not part of it.
struct ContactSystemState {
  std::vector<ContactHistoryEntry> histories;
  std::vector<Vec2> previous_positions;
  std::vector<ContactRecord> records;  // the last evaluation (written to contacts/*.vtu)
  BroadPhaseState broad_phase;
};

struct ContactStepResult {
  double dissipated = 0.0;     // energy dissipated at contacts during this evaluation
  double stored_energy = 0.0;  // elastic energy held by the contact springs now
  int active_contacts = 0;
};

// What an evaluation of the contacts needs to know of the step it belongs to.
struct ContactEvaluation {
  // The time since the previous evaluation, t_n - t_n-1: contact damping turns the slip and
  // gap increments into rates with it (0: no damping rates).
  double previous_step = 0.0;
  // The run's first evaluation: where bonded and cohesive-zone laws form their initial bonds.
  bool first = false;
};

class ContactSystem {
 public:
  // `laws` holds whole-contact strengths (halved internally for the two passes). Verifies
  // that every pair of materials present has a law.
  ContactSystem(const Model& model, const MaterialPairTable& laws, const ContactSettings& settings);

  // Evaluates all contacts at the model's current state and adds their forces to the node
  // forces (fx, fy) and rigid forces (fx, fy, torque). Call once per step, with the step's
  // `evaluation` context.
  ContactStepResult add_contact_forces(Model& model, const ContactEvaluation& evaluation = {});
  // The same in two parts, for a caller that visits every body once afterwards (the Stepper's
  // loop over bodies, solver/node_update.cpp, which spreads a body's contact forces while its
  // nodes are in that core's cache): evaluate_contacts applies the forces on rigid bodies and
  // holds those on deformable bodies' contour points, add_body_contact_forces adds one body's
  // to its nodes. Each body gets the same sums, bit for bit, as from add_contact_forces.
  ContactStepResult evaluate_contacts(Model& model, const ContactEvaluation& evaluation = {});
  void add_body_contact_forces(Model& model, BodyId body) const;

  const std::vector<ContactRecord>& records() const { return records_; }
  const std::vector<ContactHistoryEntry>& histories() const { return histories_; }
  void set_histories(std::vector<ContactHistoryEntry> histories) {
    histories_ = std::move(histories);
  }
  // Previous contour positions (for slip increments); part of the restartable state.
  const std::vector<Vec2>& previous_positions() const { return previous_positions_; }
  void set_previous_positions(std::vector<Vec2> p) { previous_positions_ = std::move(p); }
  const BroadPhase& broad_phase() const { return broad_phase_; }
  // Copies the evolving state into `state`, reusing its buffers (no allocation once they
  // have grown), and back.
  void capture(ContactSystemState& state) const {
    state.histories = histories_;
    state.previous_positions = previous_positions_;
    state.records = records_;
    broad_phase_.capture(state.broad_phase);
  }
  void restore(const ContactSystemState& state) {
    broad_phase_.restore(state.broad_phase);
    histories_ = state.histories;
    previous_positions_ = state.previous_positions;
    records_ = state.records;
  }
  const ContactSettings& settings() const { return settings_; }
  // Largest penalty stiffness of any law (normal or tangential), for the stable step.
  double max_stiffness() const { return max_stiffness_; }

 private:
  MaterialPairTable per_pass_laws_;
  ContactSettings settings_;
  BroadPhase broad_phase_;
  double max_stiffness_ = 0.0;
  std::vector<Vec2> positions_, previous_positions_;
  std::vector<Vec2> segment_start_, segment_end_;
  std::vector<int> segment_body_, node_body_;
  std::vector<double> tributary_;
  std::vector<ContactHistoryEntry> histories_;
  std::vector<ContactRecord> records_;
  // Per-step scratch (reused, never checkpointed).
  struct ContactGroup {
    std::size_t begin, end;  // candidates of one (slave point, master body)
  };
  std::vector<ContactGroup> groups_;
  std::vector<ContactRecord> results_;
  std::vector<ContactHistory> new_history_;
  std::vector<double> stored_;
  std::vector<ContactHistoryEntry> next_histories_;
  std::vector<BodyRotation> rotations_;  // of each body at this evaluation (kinematics.h)
  // The scatter's forces on deformable bodies' contour points, in scatter order, then sorted by
  // body (body_force_start_: each body's range; body_force_fill_: scratch).
  struct PointForce {
    int point = 0;
    Vec2 force = Vec2::Zero();
  };
  std::vector<PointForce> point_forces_, sorted_point_forces_;
  std::vector<std::size_t> body_force_start_, body_force_fill_;
  std::vector<int> group_history_;  // per group: its entry in histories_, -1: none (scratch)
  // Contact damping and bond formation (contact_law.h): the initial tributary length L0 of
  // each contour point, each body's mass (filled at the first evaluation when a law is
  // damped).
  std::vector<double> initial_tributary_;
  std::vector<double> body_mass_;
  bool damped_ = false;
  void update_body_masses(const Model& model);
  double effective_mass(BodyId a, BodyId b) const;

  // The phases of add_contact_forces, in order.
  void update_geometry(const Model& model);
  // Throws sg::Error naming the body and contour point of the first non-finite position.
  void check_finite_positions(const Model& model) const;
  // Periodic models: throws sg::Error naming the body and contour segment wider in x than the
  // period allows (a body that exploded; the broad phase would only say that the cell is too
  // short for "the widest segment", issue #26).
  void check_segment_widths(const Model& model) const;
  void group_candidates(std::span<const ContactCandidate> candidates);
  // Narrow phase and law of one group (parallel over groups: writes only its own slots).
  void evaluate_group(const Model& model, std::span<const ContactCandidate> candidates,
                      std::size_t group, const ContactEvaluation& evaluation);
  ContactStepResult scatter_forces(Model& model);

  // The closest projection of a group's slave point on its master, and the periodic image
  // (x shift of the slave point) it was found with.
  struct GroupProjection {
    NodeProjection projection;
    double shift = 0.0;
  };
  GroupProjection project_group(const Model& model, std::span<const ContactCandidate> candidates,
                                const ContactGroup& group, const Body& master_body) const;
  // Slip increment ds of the slave point relative to the master since the last evaluation.
  double slip_increment(const Model& model, int slave, const Body& master_body,
                        const GroupProjection& projection) const;
  // Adds force f, applied at `at`, to the contour point's body: a rigid body's force and
  // torque at once, a deformable body's point forces for add_body_contact_forces.
  void add_force_at_point(Model& model, int point, const Vec2& f, const Vec2& at);
  // The deformable bodies' point forces sorted by body (stable: in scatter order within each
  // body), for add_body_contact_forces.
  void sort_point_forces_by_body(const Model& model);
};

}  // namespace sg
