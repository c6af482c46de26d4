#include "solver/stepper.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace sg {

Stepper::Stepper(Model& model, ContactSystem* contacts, const IntegratorParams& integrator)
    : model_(model), contacts_(contacts), integrator_(integrator) {
  if (integrator.implicit_viscosity)
    implicit_ = std::make_unique<ImplicitViscosity>(
        model, integrator.imex_tolerance, integrator.imex_refactor_threshold,
        integrator.imex_dense_factor_limit, integrator.imex_objective_split);
}

Stepper::~Stepper() = default;

ViscousSolveStatistics Stepper::viscous_statistics() const {
  return implicit_ ? implicit_->statistics() : ViscousSolveStatistics{};
}

void Stepper::drop_implicit_history() {
  if (implicit_) implicit_->drop_history();
}

// One step, as the algorithm of the header reads: forces at u_n, then velocities, then
// positions, then the ledger of the instant t_n. Each phase is timed into profile(). The
// contacts are all evaluated first; then each body's node forces (gravity, its contact forces,
// its internal forces), velocities and positions are done together, body by body
// (node_update.cpp): they read and write that body's nodes only. The positions phase holds
// the periodic wrap.
void Stepper::step(double dt) {
  PhaseTimer timer(profile_);
  const StepSizes steps = step_sizes(state_.previous_dt, dt);
  clear_rigid_forces();
  timer.stamp(StepPhase::external_forces);
  const ContactStepResult contact = compute_contact_forces(steps);
  timer.stamp(StepPhase::contacts);
  // (Its loop stamps the contacts, the internal forces and the velocities, the carriers the
  // velocities.)
  const FieldNodeUpdate field = advance_field_nodes(steps, timer);
  const InternalForceResult& internal = field.internal;
  const NodeUpdate& nodes = field.nodes;
  timer.stamp(StepPhase::velocities);
  const RigidUpdate rigid = advance_rigid_bodies(steps, nodes.carriers);
  timer.stamp(StepPhase::rigid_bodies);
  if (model_.periodic_x) wrap_periodic_bodies();
  timer.stamp(StepPhase::positions);
  book_energy(steps, contact, internal, nodes, rigid);
  finish_step(dt);
  timer.stamp(StepPhase::ledger);
  ++profile_.steps;
}

void Stepper::clear_rigid_forces() {
  RigidState& rigid = model_.rigid;
  std::fill(rigid.fx.begin(), rigid.fx.end(), 0.0);
  std::fill(rigid.fy.begin(), rigid.fy.end(), 0.0);
  std::fill(rigid.torque.begin(), rigid.torque.end(), 0.0);
}

ContactStepResult Stepper::compute_contact_forces(const StepSizes& steps) {
  if (!contacts_) return {};
  // The step that led to u_n (contact damping turns the slip and gap increments into rates),
  // and whether this is the run's first evaluation (where bonded laws form their bonds).
  const ContactEvaluation evaluation{steps.previous, state_.step == 0};
  try {
    // The forces on deformable bodies are added to their nodes body by body
    // (advance_field_nodes).
    return contacts_->evaluate_contacts(model_, evaluation);
  } catch (const Error& e) {
    SG_THROW(e.what() << " at step " << state_.step << ", time " << state_.time);
  }
}

void Stepper::book_energy(const StepSizes& steps, const ContactStepResult& contact,
                          const InternalForceResult& internal, const NodeUpdate& nodes,
                          const RigidUpdate& rigid) {
  StepEnergyTerms terms;
  terms.kinetic = nodes.kinetic + rigid.kinetic;
  terms.external_power = nodes.external_power + rigid.external_power;
  terms.force_power = nodes.force_power + rigid.force_power;
  terms.force_square = nodes.force_square + rigid.force_square;
  terms.elastic_energy = internal.elastic_energy;
  // IMEX: the damping power of the viscous force the solve applied (implicit_viscosity.h).
  terms.damping_power =
      implicit_ ? internal.damping_power + nodes.damping_correction : internal.damping_power;
  terms.viscous_power = nodes.viscous_power;
  terms.contact_dissipated = contact.dissipated;
  terms.contact_stored = contact.stored_energy;
  terms.drive_work_old = nodes.drive_work_old;
  terms.drive_work_new = nodes.drive_work_new;
  terms.servo = rigid.servo;
  book_step_energy(steps, terms, state_.step == 0, state_.energy, pending_);
}

}  // namespace sg
