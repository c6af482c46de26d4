#include "solver/energy_ledger.h"

namespace sg {

double EnergyLedger::residual() const {
  return external_work + step_change - (kinetic - initial_kinetic) -
         (elastic + contact_elastic - initial_elastic) - damping_dissipated - contact_dissipated -
         servo_dissipated;
}

namespace {

void book_servo_loads(const StepSizes& steps, const ServoPower& power, bool first, EnergyLedger& e,
                      SolverPendingIncrements& pending) {
  // A force f_n that depends on time or on v_n+1/2 is booked as
  // 1/2 dt_prev f_n . v_n-1/2 + 1/2 dt f_n . v_n+1/2, the same split as the bulk damping in
  // book_step_energy(): the kinetic energy changes over [t_n-1, t_n] by the trapezoidal work
  // 1/2 dt_prev v_n-1/2 . (F_n-1 + F_n) (K_n^- - K_n-1^+, stepper.h), so the half with
  // v_n-1/2 closes the interval that ends now, with its step, and the half with v_n+1/2 opens
  // the next.
  e.external_work += pending.load_work;
  e.servo_dissipated += pending.servo_dissipation;
  if (!first) {
    e.external_work += 0.5 * steps.previous * power.load_old;
    e.servo_dissipated += 0.5 * steps.previous * power.servo_old;
  }
  pending.load_work = 0.5 * steps.next * power.load_new;
  pending.servo_dissipation = 0.5 * steps.next * power.servo_new;
}

}  // namespace

void book_step_energy(const StepSizes& steps, const StepEnergyTerms& terms, bool first,
                      EnergyLedger& e, SolverPendingIncrements& pending) {
  const double dt_prev = steps.previous, dt = steps.next;
  book_servo_loads(steps, terms.servo, first, e, pending);

  // Bulk damping, booked so that the ledger closes exactly for a linear system under this
  // scheme: over [t_n, t_n+1] the energy K^+_n + E(u_n) becomes K^-_n+1 + E(u_n+1), changed
  // by the trapezoidal work 1/2 dt v_n+1/2 . (f_v,n + f_v,n+1) (stepper.h). The half pairing
  // f_v,n with v_n-1/2 (the power at the force evaluation) completes the interval that ends
  // here, with its step dt_prev; the half pairing it with v_n+1/2 opens the next one (dt).
  e.external_work += pending.external_work;
  e.damping_dissipated += pending.damping_dissipation;
  if (!first) e.damping_dissipated += 0.5 * dt_prev * terms.damping_power;
  // Contact dissipation of this evaluation belongs to the increment that led to u_n.
  e.contact_dissipated += terms.contact_dissipated;
  e.contact_elastic = terms.contact_stored;
  // The kinetic energy that opens [t_n, t_n+1], K_n^+ = tc + 1/4 (dt_prev - dt) F . v_n+1/2
  // with tc the time-centred sum, and the step change K_n^+ - K_n^- =
  // -1/8 (dt^2 - dt_prev^2) F . F / m (stepper.h): both exactly 0 for a constant step.
  e.kinetic = terms.kinetic;
  if (dt != dt_prev) {  // (not 0 * F . F: the ledger of a constant step is the same bits)
    e.kinetic += 0.25 * (dt_prev - dt) * terms.force_power;
    e.step_change += -0.125 * ((dt - dt_prev) * (dt + dt_prev)) * terms.force_square;
  }
  e.elastic = terms.elastic_energy;
  if (first) {
    e.initial_kinetic = terms.kinetic;
    e.initial_elastic = terms.elastic_energy + terms.contact_stored;
  }
  // Increments over [t_n, t_n+1]: the work of f_ext along u_n+1 - u_n = dt v_n+1/2 is exact.
  pending.external_work = dt * terms.external_power;
  pending.damping_dissipation = -0.5 * dt * terms.viscous_power;
  // Work of the node drives' reactions, split as the servo loads' (stepper.h).
  e.external_work += pending.drive_work;
  if (!first) e.external_work += 0.5 * dt_prev * terms.drive_work_old;
  pending.drive_work = 0.5 * dt * terms.drive_work_new;
}

}  // namespace sg
