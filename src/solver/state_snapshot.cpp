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
  const NodeState& n = model.nodes;
  // Vector assignment reuses the destination's capacity: no allocation once grown.
  snapshot.ref_x = n.ref_x;
  snapshot.ux = n.ux;
  snapshot.uy = n.uy;
  snapshot.vx = n.vx;
  snapshot.vy = n.vy;
  const RigidState& r = model.rigid;
  snapshot.rigid_x = r.x;
  snapshot.rigid_y = r.y;
  snapshot.rigid_theta = r.theta;
  snapshot.rigid_vx = r.vx;
  snapshot.rigid_vy = r.vy;
  snapshot.rigid_omega = r.omega;
  snapshot.rigid_fx = r.fx;
  snapshot.rigid_fy = r.fy;
  snapshot.rigid_torque = r.torque;
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
  NodeState& n = model.nodes;
  const std::size_t nodes = n.size(), rigid = model.rigid.size();
  for (const std::vector<double>* a :
       {&snapshot.ref_x, &snapshot.ux, &snapshot.uy, &snapshot.vx, &snapshot.vy})
    SG_VERIFY(a->size() == nodes, "state snapshot: " << a->size() << " node values for a model of "
                                                     << nodes << " nodes");
  for (const std::vector<double>* a :
       {&snapshot.rigid_x, &snapshot.rigid_y, &snapshot.rigid_theta, &snapshot.rigid_vx,
        &snapshot.rigid_vy, &snapshot.rigid_omega, &snapshot.rigid_fx, &snapshot.rigid_fy,
        &snapshot.rigid_torque})
    SG_VERIFY(a->size() == rigid, "state snapshot: " << a->size()
                                                     << " rigid-body values for a model of "
                                                     << rigid << " rigid bodies");
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
  n.ref_x = snapshot.ref_x;
  n.ux = snapshot.ux;
  n.uy = snapshot.uy;
  n.vx = snapshot.vx;
  n.vy = snapshot.vy;
  RigidState& r = model.rigid;
  r.x = snapshot.rigid_x;
  r.y = snapshot.rigid_y;
  r.theta = snapshot.rigid_theta;
  r.vx = snapshot.rigid_vx;
  r.vy = snapshot.rigid_vy;
  r.omega = snapshot.rigid_omega;
  r.fx = snapshot.rigid_fx;
  r.fy = snapshot.rigid_fy;
  r.torque = snapshot.rigid_torque;
  for (std::size_t d = 0; d < model.node_drives.size(); ++d)
    model.node_drives[d].reaction =
        Vec2(snapshot.drive_reaction[2 * d], snapshot.drive_reaction[2 * d + 1]);
  solver.state() = snapshot.solver;
  SolverSnapshotAccess::set_pending(solver, snapshot.pending);
}

}  // namespace sg
