#include "solver/state_snapshot.h"

#include "core/error.h"

namespace sg {

// Friend of Stepper (declared there): the one place that reads and writes its private
// members for a snapshot. A member added to the solver that carries state from one step to
// the next belongs here too.
struct SolverSnapshotAccess {
  static const Model& model(const Stepper& s) { return s.model_; }
  static SolverPendingIncrements pending(const Stepper& s) { return s.pending_; }
  static void set_pending(Stepper& s, const SolverPendingIncrements& p) { s.pending_ = p; }
};

void capture_state(const Stepper& solver, const ContactSystem* contacts, StateSnapshot& snapshot) {
  const Model& model = SolverSnapshotAccess::model(solver);
  // Vector assignment reuses the destination's capacity: no allocation once grown.
  for (const StateArray<NodeState>& a : kNodeStateArrays)
    snapshot.*a.snapshot = model.nodes.*a.model;
  for (const StateArray<RigidState>& a : kRigidStateArrays)
    snapshot.*a.snapshot = model.rigid.*a.model;
  snapshot.drive_reaction.resize(2 * model.node_drives.size());
  for (std::size_t d = 0; d < model.node_drives.size(); ++d) {
    snapshot.drive_reaction[2 * d] = model.node_drives[d].reaction.x();
    snapshot.drive_reaction[2 * d + 1] = model.node_drives[d].reaction.y();
  }
  snapshot.solver = solver.state();
  snapshot.pending = SolverSnapshotAccess::pending(solver);
  snapshot.has_contacts = contacts != nullptr;
  if (contacts) contacts->capture(snapshot.contacts);
}

StateSnapshot capture_state(const Stepper& solver, const ContactSystem* contacts) {
  StateSnapshot snapshot;
  capture_state(solver, contacts, snapshot);
  return snapshot;
}

void restore_state(const StateSnapshot& snapshot, Stepper& solver, ContactSystem* contacts) {
  Model& model = solver.model();
  const std::size_t nodes = model.nodes.size(), rigid = model.rigid.size();
  for (const StateArray<NodeState>& a : kNodeStateArrays)
    SG_VERIFY((snapshot.*a.snapshot).size() == nodes,
              "state snapshot: " << (snapshot.*a.snapshot).size() << " node values for a model of "
                                 << nodes << " nodes");
  for (const StateArray<RigidState>& a : kRigidStateArrays)
    SG_VERIFY((snapshot.*a.snapshot).size() == rigid,
              "state snapshot: " << (snapshot.*a.snapshot).size()
                                 << " rigid-body values for a model of " << rigid
                                 << " rigid bodies");
  SG_VERIFY(snapshot.drive_reaction.size() == 2 * model.node_drives.size(),
            "state snapshot: " << snapshot.drive_reaction.size() / 2
                               << " node drives for a model of " << model.node_drives.size());
  SG_VERIFY(snapshot.has_contacts == (contacts != nullptr),
            "state snapshot: taken " << (snapshot.has_contacts ? "with" : "without")
                                     << " contacts, restored into a run "
                                     << (contacts ? "with" : "without") << " contacts");
  if (contacts) {
    const std::size_t points = model.contour_point_count();
    const std::size_t previous = snapshot.contacts.previous_positions.size();
    SG_VERIFY(previous == 0 || previous == points,
              "state snapshot: " << previous << " previous contour positions for a model of "
                                 << points << " contour points");
    SG_VERIFY(snapshot.contacts.broad_phase.built_nodes.size() == 0 ||
                  snapshot.contacts.broad_phase.built_nodes.size() == points,
              "state snapshot: broad phase built on "
                  << snapshot.contacts.broad_phase.built_nodes.size()
                  << " contour points, the model has " << points);
    contacts->restore(snapshot.contacts);
  }
  for (const StateArray<NodeState>& a : kNodeStateArrays)
    model.nodes.*a.model = snapshot.*a.snapshot;
  for (const StateArray<RigidState>& a : kRigidStateArrays)
    model.rigid.*a.model = snapshot.*a.snapshot;
  for (std::size_t d = 0; d < model.node_drives.size(); ++d)
    model.node_drives[d].reaction =
        Vec2(snapshot.drive_reaction[2 * d], snapshot.drive_reaction[2 * d + 1]);
  solver.state() = snapshot.solver;
  SolverSnapshotAccess::set_pending(solver, snapshot.pending);
}

}  // namespace sg
