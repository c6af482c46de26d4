#pragma once
// The whole evolving state of a run, in memory: what a checkpoint file holds
// (io/checkpoint.h) and what an adaptive step restores when it rejects a step.
//
// "Evolving" means everything a later step reads that an earlier step wrote:
//   field nodes   u, v, and ref_x (Stepper::wrap_periodic_bodies moves a deformable
//                 body across the periodic seam by shifting its reference positions)
//   rigid bodies  pose, velocities, and the forces received at the last evaluation
//   node drives   the reactions at the last evaluation (a servo-loaded drive's carrier has
//                 no state of its own: its velocity is its nodes' common one, saved above)
//   solver        time, step count, energy ledger, and the work and dissipation of the last
//                 step that the next step books (Stepper's pending increments)
//   contacts      per-contact histories, the previous contour positions (slip increments),
//                 the last evaluation's records (contact output), and the broad phase's
//                 positions at its last build and candidate list (which decide the next
//                 rebuild: a restored run must see exactly the candidates an uninterrupted
//                 one would)
// Everything else is either fixed at model build (reference geometry, masses, shape
// functions) or recomputed from the above at each step (forces, contour positions, cell
// grids, scratch), and is not saved: restoring the snapshot into a freshly built model of
// the same scenario continues the run bitwise identically.
//
// capture_state() and restore_state() copy arrays and nothing else: no file I/O, and no
// allocation once a snapshot reused for successive captures has grown to size.
#include <vector>

#include "contact/contact_system.h"
#include "solver/stepper.h"

namespace sg {

struct StateSnapshot {
  // Field nodes, one entry per node; rigid bodies, one entry per rigid body (kNodeStateArrays,
  // kRigidStateArrays below say which model array each copies).
  std::vector<double> ref_x, ux, uy, vx, vy;
  std::vector<double> rigid_x, rigid_y, rigid_theta;
  std::vector<double> rigid_vx, rigid_vy, rigid_omega;
  std::vector<double> rigid_fx, rigid_fy, rigid_torque;
  // Node drives: the reaction at the last evaluation (x, y per drive), like rigid_fx.
  std::vector<double> drive_reaction;
  SolverState solver;
  SolverPendingIncrements pending;
  bool has_contacts = false;
  ContactSystemState contacts;
};

// The schema of the snapshot's arrays: each beside the model array it copies, in the order a
// checkpoint saves them. capture_state() and restore_state() copy through these rows and the
// checkpoint (io/checkpoint.cpp) saves through them, so that an array added to the evolving
// state is a member above and a row here (and a checkpoint format version).
template <class ModelArrays>
struct StateArray {
  std::vector<double> StateSnapshot::*snapshot;
  std::vector<double> ModelArrays::*model;
};

inline constexpr StateArray<NodeState> kNodeStateArrays[] = {
    {&StateSnapshot::ref_x, &NodeState::ref_x},
    {&StateSnapshot::ux, &NodeState::ux},
    {&StateSnapshot::uy, &NodeState::uy},
    {&StateSnapshot::vx, &NodeState::vx},
    {&StateSnapshot::vy, &NodeState::vy}};

inline constexpr StateArray<RigidState> kRigidStateArrays[] = {
    {&StateSnapshot::rigid_x, &RigidState::x},
    {&StateSnapshot::rigid_y, &RigidState::y},
    {&StateSnapshot::rigid_theta, &RigidState::theta},
    {&StateSnapshot::rigid_vx, &RigidState::vx},
    {&StateSnapshot::rigid_vy, &RigidState::vy},
    {&StateSnapshot::rigid_omega, &RigidState::omega},
    {&StateSnapshot::rigid_fx, &RigidState::fx},
    {&StateSnapshot::rigid_fy, &RigidState::fy},
    {&StateSnapshot::rigid_torque, &RigidState::torque}};

// Copies the state of `solver` (its model) and of `contacts` (may be null) into `snapshot`,
// reusing the snapshot's buffers.
void capture_state(const Stepper& solver, const ContactSystem* contacts, StateSnapshot& snapshot);
StateSnapshot capture_state(const Stepper& solver, const ContactSystem* contacts);

// Puts `snapshot` back into `solver`, its model and `contacts`. Throws sg::Error if the
// snapshot does not fit (another number of nodes, rigid bodies or contour points, contacts
// expected and not given or the reverse, another number of node drives).
void restore_state(const StateSnapshot& snapshot, Stepper& solver, ContactSystem* contacts);

}  // namespace sg
