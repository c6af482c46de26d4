#pragma once
// Explicit symplectic Euler time stepping of a Model (DESIGN.md §2 "Time integration"):
//
//   forces:     f_n = f_ext + f_int(u_n, v_{n-1/2})
//   velocities: v_{n+1/2} = v_{n-1/2} + dt M^-1 f_n
//   positions:  u_{n+1}   = u_n + dt v_{n+1/2}
//
// Velocities live at half steps. The energy ledger is written for the configuration u_n at
// which the forces were evaluated, with the kinetic energy taken as
// 1/2 sum m v_{n-1/2} . v_{n+1/2}: for a linear undamped system this "time-centred" kinetic
// energy plus the elastic energy is exactly conserved by the scheme, so the ledger measures
// the physics and not the O(dt) staggering of the update.
//
// Driven field nodes (Model::node_drives, the back faces of deformable strips): a driven
// component gets v_n+1/2 = V(t_n + dt/2) exactly; the force that takes, beyond the forces the
// node receives, is the drive's reaction R_I = m_I (v_n+1/2 - v_n-1/2) / dt - f_I. The nodes
// stay part of the system (their kinetic energy is counted) and the work of R is external
// work, booked like the servo loads: 1/2 dt R_n . (v_n-1/2 + v_n+1/2), which is what the
// time-centred kinetic energy sees, so the ledger stays closed.
//
// Servo-loaded node drives (DriveMode::load, the back face of a pressure-loaded strip): the
// driven nodes move as one carrier (model/model.h NodeDrive); its velocity v_n+1/2 is computed
// first, from the sum of the forces its nodes receive, then imposed on them as above. Its
// reaction is F - c v_n+1/2, so instead of R . v the ledger books the work of the load F as
// external work and that of -c v as servo dissipation, split over two steps as for a
// servo-loaded rigid degree of freedom; the two agree because the nodes share one velocity.
#include <string>
#include <vector>

#include "contact/contact_system.h"
#include "model/model.h"

namespace sg {

// Cumulative energies since the start of the run (energy units: force x length).
struct EnergyLedger {
  double kinetic = 0.0;             // at the last force evaluation (time-centred, see above)
  double elastic = 0.0;             // strain energy at the last force evaluation
  double external_work = 0.0;       // work of external forces (gravity, loads) so far
  double damping_dissipated = 0.0;  // energy dissipated by bulk damping so far
  double contact_dissipated = 0.0;  // energy dissipated at contacts so far
  // Energy dissipated so far by the viscous force of servo-loaded rigid degrees of freedom
  // (DriveMode::load). Kept apart from the bulk damping: it is a device of the loading,
  // not a property of the third body, and must not count in the bulk share p_wb.
  double servo_dissipated = 0.0;
  double contact_elastic = 0.0;  // elastic energy held by contact springs now
  // Energy balance residual: W_ext - (K - K0) - (E - E0) - D_bulk - D_contact - D_servo,
  // with K0, E0
  // the values at the first force evaluation (E includes the contact springs).
  double initial_kinetic = 0.0, initial_elastic = 0.0;
  double residual() const;
};

struct SolverState {
  double time = 0.0;  // time of the current displacements (the ledger is one step behind)
  long step = 0;
  EnergyLedger energy;
};

class ExplicitSolver {
 public:
  // `contacts` may be null (free grains).
  explicit ExplicitSolver(Model& model, ContactSystem* contacts = nullptr)
      : model_(model), contacts_(contacts) {}

  // Advances one step of size dt. Throws sg::Error with the body, node and step when the
  // state becomes invalid (inverted Gauss point, non-finite velocity).
  void step(double dt);

  const SolverState& state() const { return state_; }
  SolverState& state() { return state_; }
  Model& model() { return model_; }

 private:
  Model& model_;
  ContactSystem* contacts_;
  SolverState state_;
  // Checkpoints and retried steps save and restore the pending increments below with the
  // rest of the state (solver/state_snapshot.cpp): every member that is not scratch.
  friend struct SolverSnapshotAccess;
  // Work and dissipation over the last step [t_n, t_n+1], booked at the next step so the
  // ledger always describes one instant.
  double pending_external_work_ = 0.0;
  double pending_damping_dissipation_ = 0.0;
  // The same for servo-loaded degrees of freedom, rigid or node carriers (their imposed force
  // and viscous force).
  double pending_load_work_ = 0.0;
  double pending_servo_dissipation_ = 0.0;
  // The same for the reactions of driven field nodes (NodeDrive: the back faces of deformable
  // strips).
  double pending_drive_work_ = 0.0;
  // Scratch: per-body partial sums of the update, then per node drive its imposed velocities
  // and partial sums (see step()).
  std::vector<double> body_sums_;
  void check_finite_velocities() const;
  // Power of the servo loads (DriveMode::load) at the force evaluation: F_n . v and
  // (c v_n+1/2) . v with v = v_n-1/2 (old) and v = v_n+1/2 (new), summed over rigid degrees
  // of freedom and node-drive carriers.
  struct ServoPower {
    double load_old = 0.0, load_new = 0.0, servo_old = 0.0, servo_new = 0.0;
  };
  // The velocities v_n+1/2 of the node drives' carriers (mode load), written to the drive's
  // imposed-velocity slots of `drive_data` (6 per drive, see step()); their servo power.
  ServoPower advance_node_carriers(double dt, double* drive_data) const;
  // Advances rigid bodies; returns (kinetic energy time-centred, external power of gravity
  // and constant forces). Books the load work and servo dissipation of DriveMode::load
  // degrees of freedom in the ledger itself (they are split over two steps), those of the
  // rigid bodies added to `servo` (the node carriers' part).
  std::pair<double, double> advance_rigid_bodies(double dt, ServoPower servo);
  void wrap_periodic_bodies();
};

}  // namespace sg
