#include "run/simulation.h"

#include <algorithm>

#include "run/integration_checks.h"
#include "scenario/geometry_checks.h"
#include "solver/mass_scaling.h"

namespace sg {

namespace {

std::unique_ptr<ContactSystem> make_contacts(const ScenarioDef& s, Model& model) {
  if (s.contact_laws.empty()) return nullptr;
  return std::make_unique<ContactSystem>(model, contact_law_table(s), contact_settings(s));
}

// Mass scaling on the built model, before anything is estimated or restored: deterministic,
// so a resumed run rebuilds the same masses (and the checkpoint fingerprint checks them).
std::string scale_masses(const ScenarioDef& s, Model& model, const ContactSystem* contacts,
                         const IntegratorParams& integrator) {
  if (s.mass_scaling_step <= 0.0) return "";
  const MassScalingReport report =
      apply_mass_scaling(model, s.mass_scaling_step, s.time_step_safety,
                         contacts ? contacts->max_stiffness() : 0.0, integrator);
  return "# " + describe(report, model) + "\n";
}

// The warning of a fixed step beyond the estimated limit, to `progress` and for run.log.
std::string warn_about_fixed_step(const ScenarioDef& s, const Model& model,
                                  const ContactSystem* contacts, const IntegratorParams& integrator,
                                  std::ostream* progress) {
  const std::string warning = check_fixed_step(
      s.fixed_time_step, model, contacts ? contacts->max_stiffness() : 0.0, integrator);
  if (warning.empty()) return "";
  if (progress) *progress << "softgrain: warning: " << warning << "\n";
  return "# warning: " + warning + "\n";
}

StepControlParams step_control_params(const ScenarioDef& s, const IntegratorChoice& integrator,
                                      const Model& model, std::ostream* progress) {
  StepControlParams p;
  p.on_step_collapse = [&model, progress](const StableStep& now, double first_dt) {
    if (progress)
      *progress << "\nsoftgrain: warning: " << describe_step_collapse(model, now, first_dt) << "\n";
  };
  p.safety = s.time_step_safety;
  p.fixed_step = s.fixed_time_step;
  p.reestimate_interval = s.reestimate_interval;
  p.tolerance = integrator.step_tolerance;
  return p;
}

}  // namespace

Simulation::Simulation(const ScenarioDef& scenario, std::ostream* progress)
    : model(build_model(scenario)),
      contacts(make_contacts(scenario, model)),
      integrator(resolve_integrator(scenario, model, contacts ? contacts->max_stiffness() : 0.0)),
      mass_scaling_note(scale_masses(scenario, model, contacts.get(), integrator.params)),
      initial_state_note(check_initial_state(scenario, model, contacts != nullptr, progress)),
      solver(model, contacts.get(), integrator.params),
      controller(solver, contacts.get(),
                 step_control_params(scenario, integrator, model, progress)),
      first_estimate(controller.last_estimate()),
      first_dt(controller.next_step()),
      fixed_step_note(
          warn_about_fixed_step(scenario, model, contacts.get(), integrator.params, progress)),
      // Computed before any restore: the model's fixed data only.
      fingerprint(fingerprint_of(model, run_settings(scenario, integrator, first_dt))) {}

std::vector<double> run_settings(const ScenarioDef& s, const IntegratorChoice& integrator,
                                 double first_dt) {
  std::vector<double> v = {first_dt,
                           s.series_period,
                           s.field_period,
                           integrator.step_tolerance,
                           static_cast<double>(s.reestimate_interval),
                           s.mass_scaling_step};
  // (Appended only when set, so that explicit runs keep their checkpoints bitwise.)
  if (integrator.params.implicit_viscosity) {
    v.insert(v.end(), {1.0, s.imex_tolerance, s.imex_refactor_threshold});
    if (!s.imex_dense_factors) v.push_back(-1.0);  // (only when off: earlier checkpoints stay)
    // (Only when it matters, a material damped by that model: a checkpoint of the exact solve,
    // the only one before the split, does not resume under the split one; nor one of sparse or
    // full-matrix or packed factors or envelopes by rows under the single-precision tiled
    // envelope ones of the solves done once per step, reference_stiffness, corotational and the
    // split. -3, -4 and -5, which marked the full-matrix, the packed and the by-rows ones, are
    // retired.)
    const auto damped = [&](bool objective) {
      return std::any_of(s.materials.begin(), s.materials.end(), [&](const MaterialDef& m) {
        return m.damping > 0.0 && (m.damping_model == DampingModel::objective) == objective;
      });
    };
    if (s.imex_objective_split && damped(true)) v.push_back(-2.0);
    if (s.imex_dense_factors && (damped(false) || (s.imex_objective_split && damped(true))))
      v.push_back(-6.0);
  }
  if (!s.contact_laws.empty()) {
    const ContactSettings c = contact_settings(s);
    v.insert(v.end(), {c.cutoff, c.skin});
    for (const ContactLawDef& law : s.contact_laws) {
      const std::vector<double> coefficients = contact_law_coefficients(law.params);
      v.insert(v.end(), coefficients.begin(), coefficients.end());
    }
  }
  return v;
}

}  // namespace sg
