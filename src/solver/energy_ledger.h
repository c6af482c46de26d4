#pragma once
// The energy ledger of the step (docs/method.md "Energy ledger"): the cumulative energies of a
// run, booked at each force evaluation t_n from what the step's phases measured there. Why the
// kinetic energy is K_n^+, why the step changes are booked apart, and why every force that is
// not a potential's is booked half with v_n-1/2 (closing [t_n-1, t_n]) and half with v_n+1/2
// (held, opening [t_n, t_n+1]) is derived in solver/stepper.h. The stepper calls
// book_step_energy in its ledger phase; nothing here reads the model.
#include "solver/step_sizes.h"

namespace sg {

// Cumulative energies since the start of the run (energy units: force x length).
struct EnergyLedger {
  double kinetic = 0.0;             // K_n^+ at the last force evaluation (stepper.h)
  double elastic = 0.0;             // strain energy at the last force evaluation
  double external_work = 0.0;       // work of external forces (gravity, loads) so far
  double damping_dissipated = 0.0;  // energy dissipated by bulk damping so far
  double contact_dissipated = 0.0;  // energy dissipated at contacts so far
  // Energy dissipated so far by the viscous force of servo-loaded rigid degrees of freedom
  // (DriveMode::load). Kept apart from the bulk damping: it is a device of the loading,
  // not a property of the third body, and must not count in the bulk share p_wb.
  double servo_dissipated = 0.0;
  double contact_elastic = 0.0;  // elastic energy held by contact springs now
  // Energy the changes of the time step have added to the scheme's kinetic energy so far:
  // the sum over force evaluations of K_n^+ - K_n^- = -1/8 (dt_+^2 - dt_-^2) F_n . F_n / m
  // (stepper.h). 0 while the step does not change. A numerical term, kept apart from the
  // residual (see there).
  double step_change = 0.0;
  // Energy balance residual:
  //   W_ext + S - (K - K0) - (E - E0) - D_bulk - D_contact - D_servo,
  // with S = step_change and K0, E0 the values at the first force evaluation (E includes the
  // contact springs). With S counted the residual is the sum of the intervals' integration
  // errors: for a linear undamped system it stays at round-off under any sequence of steps.
  double initial_kinetic = 0.0, initial_elastic = 0.0;
  double residual() const;
};

// Work and dissipation over the last step [t_n, t_n+1], booked at the next step so that the
// ledger always describes one instant (see above): part of the state although private to the
// stepper (checkpointed, restored with a rejected step: solver/state_snapshot.h).
struct SolverPendingIncrements {
  double external_work = 0.0;
  double damping_dissipation = 0.0;
  double load_work = 0.0;  // servo-loaded degrees of freedom, rigid or node carriers
  double servo_dissipation = 0.0;
  double drive_work = 0.0;  // reactions of driven field nodes (NodeDrive)
};

// Power of the servo loads (DriveMode::load) at the force evaluation: F_n . v and
// (c v_n+1/2) . v with v = v_n-1/2 (old) and v = v_n+1/2 (new), summed over rigid degrees
// of freedom and node-drive carriers.
struct ServoPower {
  double load_old = 0.0, load_new = 0.0, servo_old = 0.0, servo_new = 0.0;
};

// What one step measured at t_n, summed over field nodes then rigid bodies (in that order).
struct StepEnergyTerms {
  double kinetic = 0.0;         // time-centred, 1/2 m v_n-1/2 v_n+1/2
  double external_power = 0.0;  // of gravity, constant forces and velocity drives, along v_n+1/2
  double force_power = 0.0;     // F_n . v_n+1/2, F_n the total force of the update
  double force_square = 0.0;    // F_n . F_n / m
  double elastic_energy = 0.0;  // strain energy at u_n
  // -f_v,n . v_n-1/2, the bulk damping's dissipated power at the force evaluation (IMEX: with
  // the viscous force f_v* the solve applied, implicit_viscosity.h).
  double damping_power = 0.0;
  double viscous_power = 0.0;       // f_v,n . v_n+1/2
  double contact_dissipated = 0.0;  // by this contact evaluation (the increment ending at t_n)
  double contact_stored = 0.0;      // elastic energy of the contact springs at u_n
  double drive_work_old = 0.0;      // R_n . v_n-1/2 of velocity-driven node components
  double drive_work_new = 0.0;      // R_n . v_n+1/2
  ServoPower servo;                 // node carriers' first, then rigid degrees of freedom
};

// Books the force evaluation at t_n (`first`: the run's first, which sets K0 and E0) into
// `ledger`, and the halves that open [t_n, t_n+1] into `pending`.
void book_step_energy(const StepSizes& steps, const StepEnergyTerms& terms, bool first,
                      EnergyLedger& ledger, SolverPendingIncrements& pending);

}  // namespace sg
