#include "solver/explicit_solver.h"

#include <cmath>

#include "core/error.h"

namespace sg {

double EnergyLedger::residual() const {
  return external_work + step_change - (kinetic - initial_kinetic) -
         (elastic + contact_elastic - initial_elastic) - damping_dissipated - contact_dissipated -
         servo_dissipated;
}

ExplicitSolver::ExplicitSolver(Model& model, ContactSystem* contacts,
                               const IntegratorParams& integrator)
    : model_(model), contacts_(contacts), integrator_(integrator) {
  if (integrator.implicit_viscosity)
    implicit_ = std::make_unique<ImplicitViscosity>(model, integrator.imex_tolerance,
                                                    integrator.imex_refactor_threshold);
}

ExplicitSolver::~ExplicitSolver() = default;

ViscousSolveStatistics ExplicitSolver::viscous_statistics() const {
  return implicit_ ? implicit_->statistics() : ViscousSolveStatistics{};
}

void ExplicitSolver::refresh_implicit_preconditioners() {
  if (implicit_) implicit_->refresh_preconditioners();
}

// One step, as the algorithm of the header reads: forces at u_n, then velocities, then
// positions, then the ledger of the instant t_n. Each phase is timed into profile().
void ExplicitSolver::step(double dt) {
  PhaseTimer timer(profile_);
  const StepSizes steps = step_sizes(dt);
  apply_external_forces();
  timer.stamp(StepPhase::external_forces);
  const ContactStepResult contact = compute_contact_forces(steps.previous);
  timer.stamp(StepPhase::contacts);
  const InternalForceResult internal = compute_internal_forces();
  timer.stamp(StepPhase::internal_forces);
  const NodeUpdate nodes = update_node_velocities(steps);
  timer.stamp(StepPhase::velocities);
  const RigidUpdate rigid = advance_rigid_bodies(steps, nodes.carriers);
  timer.stamp(StepPhase::rigid_bodies);
  update_node_positions(dt);
  timer.stamp(StepPhase::positions);
  book_energy(steps, contact, internal, nodes, rigid);
  finish_step(dt);
  timer.stamp(StepPhase::ledger);
  ++profile_.steps;
}

ExplicitSolver::StepSizes ExplicitSolver::step_sizes(double dt) const {
  // The interval [t_n-1, t_n] that ends here was dt_prev long (at the first step there is none:
  // the initial velocities are v_-1/2, as for a constant step dt); velocities advance over
  // h = t_n+1/2 - t_n-1/2 = (dt_prev + dt) / 2, which is dt bitwise when the step does not
  // change (0.5 * (dt + dt) is exact).
  const double dt_prev = state_.previous_dt > 0.0 ? state_.previous_dt : dt;
  return StepSizes{dt_prev, dt, 0.5 * (dt_prev + dt)};
}

void ExplicitSolver::apply_external_forces() {
  // With lumped (row-sum) masses, the consistent gravity load on the parameter I is
  // integral(N_I rho g) = m_I g. Loops over nodes run per body in parallel: each body writes
  // its own node range, so the result does not depend on the number of threads.
  NodeState& n = model_.nodes;
  const double gx = model_.gravity.x(), gy = model_.gravity.y();
  const int body_count = static_cast<int>(model_.bodies.size());
#pragma omp parallel for schedule(static)
  for (int b = 0; b < body_count; ++b) {
    const Body& body = model_.body(b);
    // Gravity acts on the physical mass (mass scaling changes the inertia only).
    const double bgx = gx / body.mass_scale, bgy = gy / body.mass_scale;
    for (int k = body.node_begin; k < body.node_end; ++k) {
      const auto i = static_cast<std::size_t>(k);
      n.fx[i] = n.mass[i] * bgx;
      n.fy[i] = n.mass[i] * bgy;
    }
  }
  RigidState& rigid = model_.rigid;
  std::fill(rigid.fx.begin(), rigid.fx.end(), 0.0);
  std::fill(rigid.fy.begin(), rigid.fy.end(), 0.0);
  std::fill(rigid.torque.begin(), rigid.torque.end(), 0.0);
}

ContactStepResult ExplicitSolver::compute_contact_forces(double dt_prev) {
  // The step that led to u_n: contact damping turns the slip and gap increments into rates.
  if (!contacts_) return {};
  try {
    return contacts_->add_contact_forces(model_, dt_prev);
  } catch (const Error& e) {
    SG_THROW(e.what() << " at step " << state_.step << ", time " << state_.time);
  }
}

InternalForceResult ExplicitSolver::compute_internal_forces() {
  try {
    return add_internal_forces(model_);
  } catch (const Error& e) {
    SG_THROW(e.what() << " at step " << state_.step << ", time " << state_.time);
  }
}

void ExplicitSolver::book_energy(const StepSizes& steps, const ContactStepResult& contact,
                                 const InternalForceResult& internal, const NodeUpdate& nodes,
                                 const RigidUpdate& rigid) {
  const double dt_prev = steps.previous, dt = steps.next;
  book_servo_loads(steps, rigid.servo);
  const double kinetic = nodes.kinetic + rigid.kinetic;
  const double external_power = nodes.external_power + rigid.external_power;
  const double force_power = nodes.force_power + rigid.force_power;
  const double force_square = nodes.force_square + rigid.force_square;

  // Bulk damping, booked so that the ledger closes exactly for a linear system under this
  // scheme: over [t_n, t_n+1] the energy K^+_n + E(u_n) becomes K^-_n+1 + E(u_n+1), changed
  // by the trapezoidal work 1/2 dt v_n+1/2 . (f_v,n + f_v,n+1) (header). The half pairing
  // f_v,n with v_n-1/2 (the power at the force evaluation) completes the interval that ends
  // here, with its step dt_prev; the half pairing it with v_n+1/2 opens the next one (dt).
  EnergyLedger& e = state_.energy;
  e.external_work += pending_.external_work;
  e.damping_dissipated += pending_.damping_dissipation;
  if (state_.step > 0) {
    if (implicit_)
      e.damping_dissipated += 0.5 * dt_prev * (internal.damping_power + nodes.damping_correction);
    else
      e.damping_dissipated += 0.5 * dt_prev * internal.damping_power;
  }
  // Contact dissipation of this evaluation belongs to the increment that led to u_n.
  e.contact_dissipated += contact.dissipated;
  e.contact_elastic = contact.stored_energy;
  // The kinetic energy that opens [t_n, t_n+1], K_n^+ = tc + 1/4 (dt_prev - dt) F . v_n+1/2
  // with tc the time-centred sum, and the step change K_n^+ - K_n^- =
  // -1/8 (dt^2 - dt_prev^2) F . F / m (header): both exactly 0 for a constant step.
  e.kinetic = kinetic;
  if (dt != dt_prev) {  // (not 0 * F . F: the ledger of a constant step is the same bits)
    e.kinetic += 0.25 * (dt_prev - dt) * force_power;
    e.step_change += -0.125 * ((dt - dt_prev) * (dt + dt_prev)) * force_square;
  }
  e.elastic = internal.elastic_energy;
  if (state_.step == 0) {
    e.initial_kinetic = kinetic;
    e.initial_elastic = internal.elastic_energy + contact.stored_energy;
  }
  // Increments over [t_n, t_n+1]: the work of f_ext along u_n+1 - u_n = dt v_n+1/2 is exact.
  pending_.external_work = dt * external_power;
  pending_.damping_dissipation = -0.5 * dt * nodes.viscous_power;
  // Work of the node drives' reactions, split as the servo loads' (see the header).
  e.external_work += pending_.drive_work;
  if (state_.step > 0) e.external_work += 0.5 * dt_prev * nodes.drive_work_old;
  pending_.drive_work = 0.5 * dt * nodes.drive_work_new;
}

void ExplicitSolver::book_servo_loads(const StepSizes& steps, const ServoPower& power) {
  // A force f_n that depends on time or on v_n+1/2 is booked as
  // 1/2 dt_prev f_n . v_n-1/2 + 1/2 dt f_n . v_n+1/2, the same split as the bulk damping in
  // book_energy(): the kinetic energy changes over [t_n-1, t_n] by the trapezoidal work
  // 1/2 dt_prev v_n-1/2 . (F_n-1 + F_n) (K_n^- - K_n-1^+, header), so the half with v_n-1/2
  // closes the interval that ends now, with its step, and the half with v_n+1/2 opens the next.
  EnergyLedger& e = state_.energy;
  e.external_work += pending_.load_work;
  e.servo_dissipated += pending_.servo_dissipation;
  if (state_.step > 0) {
    e.external_work += 0.5 * steps.previous * power.load_old;
    e.servo_dissipated += 0.5 * steps.previous * power.servo_old;
  }
  pending_.load_work = 0.5 * steps.next * power.load_new;
  pending_.servo_dissipation = 0.5 * steps.next * power.servo_new;
}

}  // namespace sg
