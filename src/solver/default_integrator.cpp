#include "solver/default_integrator.h"

#include <iomanip>
#include <optional>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "solver/implicit_viscosity.h"
#include "solver/stable_time_step.h"

namespace sg {

double imex_step_cost(DampingModel model) {
  switch (model) {
    case DampingModel::objective:
      return 5.5;
    case DampingModel::corotational:
      return 1.6;
    case DampingModel::reference_stiffness:
      return 1.9;
  }
  SG_THROW("unknown damping model");
}

namespace {

// The costliest damping model among the bodies imex treats implicitly (the first in body
// order among equals); none: there are no such bodies.
std::optional<DampingModel> costliest_implicit_model(const Model& model) {
  std::optional<DampingModel> costliest;
  for (BodyId b = 0; b < static_cast<BodyId>(model.bodies.size()); ++b) {
    if (!has_implicit_viscosity(model, b)) continue;
    const DampingModel m = model.material_of(b).damping_model;
    if (!costliest || imex_step_cost(m) > imex_step_cost(*costliest)) costliest = m;
  }
  return costliest;
}

bool has_damped_fbar_body(const Model& model) {
  for (BodyId b = 0; b < static_cast<BodyId>(model.bodies.size()); ++b)
    if (model.body(b).kind == BodyKind::deformable && model.is_damped(b) &&
        model.material_of(b).volumetric == VolumetricFormulation::fbar)
      return true;
  return false;
}

IntegratorChoice chosen(const IntegratorParams& params, double step_tolerance,
                        const std::string& reason) {
  IntegratorChoice c;
  c.params = params;
  c.by_default = true;
  c.reason = reason;
  c.step_tolerance = step_tolerance >= 0.0       ? step_tolerance
                     : params.implicit_viscosity ? kDefaultImexStepTolerance
                                                 : 0.0;
  return c;
}

}  // namespace

IntegratorChoice choose_default_integrator(const Model& model, double safety,
                                           double contact_stiffness, const IntegratorParams& imex,
                                           double fixed_step, double step_tolerance) {
  const IntegratorParams explicit_integrator = IntegratorParams::explicit_integrator();
  const std::optional<DampingModel> costliest = costliest_implicit_model(model);
  if (!costliest) return chosen(explicit_integrator, step_tolerance, "no damped deformable body");
  if (fixed_step > 0.0)
    return chosen(explicit_integrator, step_tolerance,
                  "fixed_step is set, and imex would not make it larger");
  // The frequencies depend on the integrator only through F-bar bodies whose viscosity is
  // explicit (stable_time_step.h): estimated twice only when there are such bodies.
  const BodyFrequencies omega =
      estimate_body_frequencies(model, contact_stiffness, explicit_integrator);
  const BodyFrequencies omega_imex = has_damped_fbar_body(model)
                                         ? estimate_body_frequencies(model, contact_stiffness, imex)
                                         : omega;
  const StableStep damped = stable_time_step(model, omega, safety, explicit_integrator);
  const StableStep implicit = stable_time_step(model, omega_imex, safety, imex);
  const double gain = implicit.dt / damped.dt, cost = imex_step_cost(*costliest);
  const bool faster = gain > cost;
  std::ostringstream why;
  why << std::setprecision(2) << "damped deformable bodies; imex step " << implicit.dt
      << " against " << damped.dt << " explicit ("
      << (damped.damping_limited ? "damping-limited" : "wave-speed-limited") << "), " << std::fixed
      << std::setprecision(1) << gain << " times larger, " << (faster ? "more" : "no more")
      << " than an imex step costs with the " << to_string(*costliest) << " damping model (" << cost
      << " explicit steps)";
  return chosen(faster ? imex : explicit_integrator, step_tolerance, why.str());
}

std::string describe(const IntegratorChoice& choice) {
  std::ostringstream text;
  text << choice.params.name();
  if (choice.by_default) {
    text << " (default: " << choice.reason;
    if (choice.params.implicit_viscosity) text << "; step_tolerance " << choice.step_tolerance;
    text << ")";
  }
  return text.str();
}

}  // namespace sg
