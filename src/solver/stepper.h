#pragma once
// The Stepper takes one time step of a Model: the phases of the step, timed into its profile,
// with either integrator (solver/integrator_params.h): explicit central difference, or IMEX
// with the bulk damping implicit (solver/implicit_viscosity.h). It holds the step only: the
// energy ledger is solver/energy_ledger.h, the step control solver/step_controller.h.
//
// Central-difference (leapfrog) time stepping of a Model with a step that may change
// from one step to the next (docs/method.md "Time integration"; Belytschko, Liu & Moran,
// "Nonlinear Finite Elements for Continua and Structures", §6.2, box 6.1). With dt_- = t_n -
// t_n-1 the step that ended at t_n and dt_+ = t_n+1 - t_n the step about to be taken:
//
//   forces:     F_n = f_ext + f_int(u_n, v_n-1/2)                  (+ drive reactions)
//   velocities: v_n+1/2 = v_n-1/2 + h_n M^-1 F_n,   h_n = (dt_- + dt_+) / 2
//   positions:  u_n+1   = u_n + dt_+ v_n+1/2
//
// Velocities live at the middles of the intervals, t_n+1/2 = t_n + dt_+ / 2, so h_n is the
// time between v_n-1/2 and v_n+1/2; for a constant step h_n = dt bitwise (0.5 * (dt + dt)).
// The full-step velocity v_n = v_n-1/2 + dt_-/2 M^-1 F_n = v_n+1/2 - dt_+/2 M^-1 F_n is then
// the same from both sides. (With h_n = dt_+, as before issue #4's fix, it is not, and every
// change of the step made a first-order energy error 1/2 (dt_+ - dt_-) v_n-1/2 . F_n that no
// smaller step removed: the step controller could not recover from a rejection.) The initial
// velocities are taken as v_-1/2 with dt_- = dt_+ at the first step: a start from rest is
// the exact motion shifted by dt_0/2 in time (tests/solver/test_variable_step.cpp).
//
// The energy ledger is written for the configuration u_n at which the forces were evaluated.
// Over an interval [t_n-1, t_n] of step dt_- the trapezoidal work of the forces along
// u_n - u_n-1 = dt_- v_n-1/2, 1/2 dt_- v_n-1/2 . (F_n-1 + F_n), equals K_n^- - K_n-1^+
// exactly, with the kinetic energies
//   K_n^- = 1/2 v_n-1/2 M v_n-1/2 + 1/2 dt_- v_n-1/2 . F_n   (closes the interval ending at n)
//   K_n^+ = 1/2 v_n+1/2 M v_n+1/2 - 1/2 dt_+ v_n+1/2 . F_n   (opens the one starting at n);
// for a constant step both are the time-centred 1/2 v_n-1/2 M v_n+1/2. For a linear undamped
// system the trapezoidal work is the elastic energy's change, so K + E is exactly conserved
// over each interval. At t_n the ledger switches from K_n^- to K_n^+, and
//   K_n^+ - K_n^- = -1/8 (dt_+^2 - dt_-^2) F_n M^-1 F_n,
// second order: each is the true kinetic energy 1/2 v_n M v_n less 1/8 dt_+-^2 F_n M^-1 F_n
// (the leapfrog's modified energy of its own step), and v_n is unique. The ledger's kinetic
// energy is K_n^+ and the switch is booked in EnergyLedger::step_change, so the residual is
// the intervals' integration error. Every force that is not a potential's (bulk damping,
// servo loads and their viscous force, drive reactions) is booked by the same split: the
// half 1/2 dt_- f_n . v_n-1/2 closes [t_n-1, t_n], the half 1/2 dt_+ f_n . v_n+1/2 is held
// (pending) and opens [t_n, t_n+1]; gravity and constant forces do dt_+ f . v_n+1/2 exactly.
//
// Driven field nodes (Model::node_drives, the back faces of deformable strips): a driven
// component gets v_n+1/2 = V(t_n + dt/2) exactly; the force that takes, beyond the forces the
// node receives, is the drive's reaction R_I = m_I (v_n+1/2 - v_n-1/2) / h_n - f_I. The nodes
// stay part of the system (their kinetic energy is counted) and the work of R is external
// work, booked like the servo loads: 1/2 dt_- R_n . v_n-1/2 + 1/2 dt_+ R_n . v_n+1/2, which
// is what the kinetic energies K^-, K^+ see, so the ledger stays closed.
//
// Servo-loaded node drives (DriveMode::load, the back face of a pressure-loaded strip): the
// driven nodes move as one carrier (model/model.h NodeDrive); its velocity v_n+1/2 is computed
// first, from the sum of the forces its nodes receive, then imposed on them as above. Its
// reaction is F - c v_n+1/2, so instead of R . v the ledger books the work of the load F as
// external work and that of -c v as servo dissipation, split over two steps as for a
// servo-loaded rigid degree of freedom; the two agree because the nodes share one velocity.
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_system.h"
#include "core/cost_balanced_ranges.h"
#include "core/parallel.h"
#include "model/internal_forces.h"
#include "model/model.h"
#include "solver/energy_ledger.h"
#include "solver/implicit_viscosity.h"
#include "solver/integrator_params.h"
#include "solver/step_profile.h"
#include "solver/step_sizes.h"

namespace sg {

struct SolverState {
  double time = 0.0;  // time of the current displacements (the ledger is one step behind)
  long step = 0;
  // The last step taken, t_n - t_n-1 (0: none yet). The next step's velocity update and the
  // ledger's closing halves depend on it (see the header), so it is state: checkpointed, and
  // restored with a rejected step.
  double previous_dt = 0.0;
  EnergyLedger energy;
};

class Stepper {
 public:
  // `contacts` may be null (free grains). With integrator.implicit_viscosity the damped
  // deformable bodies' viscous forces are implicit (IMEX, solver/implicit_viscosity.h).
  explicit Stepper(Model& model, ContactSystem* contacts = nullptr,
                   const IntegratorParams& integrator = {});
  ~Stepper();
  Stepper(const Stepper&) = delete;
  Stepper& operator=(const Stepper&) = delete;

  // Advances one step of size dt. Throws sg::Error with the body, node and step when the
  // state becomes invalid (inverted Gauss point, non-finite velocity).
  void step(double dt);

  const SolverState& state() const { return state_; }
  SolverState& state() { return state_; }
  Model& model() { return model_; }
  const IntegratorParams& integrator() const { return integrator_; }
  // Wall time per phase of the steps taken so far (timing only, see step_profile.h); the run
  // loop books its own phases (step control, outputs) into the same profile.
  const StepProfile& profile() const { return profile_; }
  StepProfile& profile() { return profile_; }
  // The IMEX solves so far (all zero for the explicit integrator).
  ViscousSolveStatistics viscous_statistics() const;
  // IMEX: what the solves carry from step to step is dropped (ImplicitViscosity::drop_history:
  // the objective model's preconditioners, the carried viscous forces). Called where a
  // checkpoint is written, so that a resumed run repeats the uninterrupted run bit for bit.
  void drop_implicit_history();

 private:
  Model& model_;
  ContactSystem* contacts_;
  IntegratorParams integrator_;
  SolverState state_;
  SolverPendingIncrements pending_;
  StepProfile profile_;
  std::unique_ptr<ImplicitViscosity> implicit_;  // IMEX: the per-body viscous systems
  // Checkpoints and retried steps save and restore pending_ with the rest of the state
  // (solver/state_snapshot.cpp): every member that is not scratch or timing.
  friend struct SolverSnapshotAccess;

  // What the velocity update of the field nodes measured, summed over bodies in body order.
  struct NodeUpdate {
    double kinetic = 0.0;         // time-centred, 1/2 m v_n-1/2 v_n+1/2
    double external_power = 0.0;  // of gravity, along v_n+1/2
    double viscous_power = 0.0;   // f_v,n . v_n+1/2
    double force_power = 0.0;     // F_n . v_n+1/2, F_n the total force of the update
    double force_square = 0.0;    // F_n . F_n / m
    ServoPower carriers;          // of the node drives' load-driven carriers
    double drive_work_old = 0.0;  // R_n . v_n-1/2 of velocity-driven node components
    double drive_work_new = 0.0;  // R_n . v_n+1/2
    // IMEX: -(F* - F_n) . v_n-1/2, the change of the damping power at the force evaluation
    // when the viscous force becomes f_v* (implicit_viscosity.h); 0 otherwise.
    double damping_correction = 0.0;
  };
  // What advance_rigid_bodies adds to the nodes' sums.
  struct RigidUpdate {
    double kinetic = 0.0;         // time-centred, 1/2 m v_n-1/2 v_n+1/2
    double external_power = 0.0;  // of gravity, constant forces and velocity drives
    double force_power = 0.0;     // F_n . v_n+1/2, F_n the total force of the update
    double force_square = 0.0;    // F_n . F_n / m
    // Of every servo-loaded degree of freedom: the node carriers' (summed first) and then the
    // rigid ones' in body order.
    ServoPower servo;
  };

  struct FieldNodeUpdate {
    InternalForceResult internal;
    NodeUpdate nodes;
  };

  // The phases of step(), in order (solver/stepper.cpp).
  // The rigid bodies' force accumulators (the nodes' forces start in advance_field_nodes).
  void clear_rigid_forces();
  ContactStepResult compute_contact_forces(const StepSizes& steps);
  // Body by body (solver/node_update.cpp): the node forces at u_n (gravity, the contact forces
  // evaluated before, the internal forces), v_n+1/2, then u_n+1 = u_n + dt_+ v_n+1/2. The
  // loop's time is booked by `timer` to the contacts (gravity and the contact forces' spread),
  // the internal forces and the velocities.
  FieldNodeUpdate advance_field_nodes(const StepSizes& steps, PhaseTimer& timer);
  // From the node carriers' servo power (summed on, so the sums keep their order).
  RigidUpdate advance_rigid_bodies(const StepSizes& steps,
                                   const ServoPower& carriers);  // solver/rigid_update.cpp
  // The ledger phase: what the phases measured, booked (solver/energy_ledger.h).
  void book_energy(const StepSizes& steps, const ContactStepResult& contact,
                   const InternalForceResult& internal, const NodeUpdate& nodes,
                   const RigidUpdate& rigid);
  void finish_step(double dt);

  // Helpers of the phases.
  // The velocities v_n+1/2 of the node drives' carriers (mode load), advanced over h, written
  // to the drive's imposed-velocity slots of `drive_data` (6 per drive, node_update.cpp);
  // their servo power.
  ServoPower advance_node_carriers(double h, double* drive_data) const;
  // The parts of advance_field_nodes. The drives' imposed velocities and the scratch; returns
  // where the drives' slots start in body_sums_ (6 per drive, node_update.cpp).
  double* prepare_field_node_update(const StepSizes& steps);
  // The loop over bodies; its time booked by `timer`. An error is left in body_error_.
  void advance_bodies(const StepSizes& steps, double* drive_data, PhaseTimer& timer);
  // The per-body and per-drive sums into `nodes`, in body and drive order; the drives'
  // reactions.
  void add_node_sums(const double* drive_data, NodeUpdate& nodes);
  // F = m g on the body's field nodes: the start of their forces.
  void apply_body_gravity(const Body& body);
  // Whether the body's nodes are driven by a load-driven carrier, whose velocity needs the
  // forces of all its nodes first.
  bool waits_for_carrier(const Body& body) const;
  // The velocity and position update of one body's nodes, its sums into body_sums_.
  void advance_body(BodyId b, const StepSizes& steps, double* drive_data);
  void wrap_periodic_bodies();
  void check_finite_velocities() const;

  // Scratch of advance_field_nodes: per-body internal force results, and the error thrown by
  // the lowest body in the loop over bodies.
  std::vector<BodyForceResult> body_forces_;
  LowestIndexError body_error_;
  // Which thread takes which bodies in the loop over bodies: their times at the previous step.
  // (Not state: it changes which thread runs a body, never a result.)
  CostBalancedRanges body_ranges_;
  // Scratch of advance_field_nodes: per-body partial sums, then per node drive its imposed
  // velocities and partial sums.
  std::vector<double> body_sums_;
  // Scratch of advance_field_nodes: IMEX velocity increments per node.
  std::vector<double> increment_x_, increment_y_;
  // Scratch of advance_field_nodes: per-body finite probes of the positions.
  std::vector<double> body_probes_;
};

}  // namespace sg
