// softgrain info SCENARIO: build the model and print its size, stable step and memory, and for
// a damped model the step and the measured wall time per time unit of both integrators.
#include <iomanip>
#include <iostream>
#include <memory>

#include "command_registry.h"
#include "model/force_kernel.h"
#include "scenario/scenario.h"
#include "solver/integrator_comparison.h"
#include "solver/mass_scaling.h"
#include "solver/stable_time_step.h"

namespace sg::app {
namespace {

bool has_damped_body(const Model& model) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.is_damped(static_cast<BodyId>(b))) return true;
  return false;
}

// The integrators compared on the model's initial state; the model is left as it was.
// `imex`: the scenario's imex settings, measured whichever integrator is `configured`.
void print_integrators(Model& model, ContactSystem* contacts, const ScenarioDef& scenario,
                       double contact_stiffness, const IntegratorParams& configured,
                       const IntegratorParams& imex) {
  std::cout << "  integrators (measured over 10 steps from the initial state):\n";
  for (const IntegratorCost& c : compare_integrators(model, contacts, scenario.time_step_safety,
                                                     contact_stiffness, imex, 10)) {
    const bool is_configured = c.integrator.implicit_viscosity == configured.implicit_viscosity;
    const double steps_per_unit = 1.0 / c.stable.dt;
    std::cout << "    " << std::left << std::setw(9) << c.integrator.name() << std::right << " dt "
              << std::setprecision(3) << c.stable.dt << " ("
              << (c.stable.damping_limited ? "damping-limited" : "wave-speed-limited") << "), "
              << 1e3 * c.seconds_per_step << " ms/step, " << c.seconds_per_step * steps_per_unit
              << " s per time unit, "
              << c.seconds_per_step * steps_per_unit * scenario.duration / 3600.0 << " h for "
              << scenario.duration << " time units";
    if (c.matrix_bytes > 0.0) std::cout << ", " << c.matrix_bytes / 1048576.0 << " MiB of factors";
    std::cout << (is_configured ? "  <- run" : "") << "\n";
  }
}

int info(const std::string& file) {
  const ScenarioDef scenario = load_scenario(file);
  Model model = build_model(scenario);
  // The same estimate as `run` makes: with the contact penalty and after mass scaling.
  std::unique_ptr<ContactSystem> contacts;
  double contact_stiffness = 0.0;
  if (!scenario.contact_laws.empty()) {
    contacts = std::make_unique<ContactSystem>(model, contact_law_table(scenario),
                                               contact_settings(scenario));
    contact_stiffness = contacts->max_stiffness();
  }
  // As `run` resolves it: on the built model, before mass scaling.
  const IntegratorChoice integrator = resolve_integrator(scenario, model, contact_stiffness);
  std::string mass_scaling;
  if (scenario.mass_scaling_step > 0.0)
    mass_scaling =
        describe(apply_mass_scaling(model, scenario.mass_scaling_step, scenario.time_step_safety,
                                    contact_stiffness, integrator.params),
                 model);
  const StableStep stable = estimate_stable_time_step(model, scenario.time_step_safety,
                                                      contact_stiffness, integrator.params);
  const double bytes = static_cast<double>(model.node_count()) * 12 * sizeof(double) +
                       static_cast<double>(model.gauss_rows.entries()) * (4 * sizeof(double) + 4) +
                       static_cast<double>(model.node_rows.entries()) * (4 * sizeof(double) + 4);
  std::cout << "scenario '" << scenario.name << "' (" << file << ")\n"
            << "  bodies:        " << model.bodies.size() << "\n"
            << "  materials:     " << model.materials.size() << "\n"
            << "  field nodes:   " << model.node_count() << "\n"
            << "  Gauss points:  " << model.gauss_point_count() << " ("
            << static_cast<double>(model.gauss_rows.entries()) /
                   static_cast<double>(std::max<std::size_t>(1, model.gauss_point_count()))
            << " neighbours per point on average)\n";
  if (stable.limiting_body >= 0)
    std::cout << "  stable step:   " << stable.dt << " ("
              << (stable.damping_limited ? "damping-limited" : "wave-speed-limited") << ", body '"
              << model.body(stable.limiting_body).name << "'; " << integrator.params.name()
              << " integrator; " << contact_share_note(stable) << ")\n"
              << "  steps:         " << static_cast<long>(scenario.duration / stable.dt) << " for "
              << scenario.duration << " time units\n";
  std::cout << "  integrator:    " << describe(integrator) << "\n";
  if (!mass_scaling.empty()) std::cout << "  " << mass_scaling << "\n";
  std::cout << "  memory:        " << bytes / 1048576.0
            << " MiB (node state and shape rows; the imex integrator's factors below)\n";
  std::cout << "  force kernel:  " << force_kernel().isa
            << " (SOFTGRAIN_SIMD=default selects the baseline one)\n";
  if (stable.limiting_body >= 0 && has_damped_body(model))
    print_integrators(model, contacts.get(), scenario, contact_stiffness, integrator.params,
                      imex_integrator(scenario));
  return 0;
}

const Registration registration(
    {"info",
     [](CLI::App& app, const GlobalOptions& options) {
       auto file = std::make_shared<std::string>();
       CLI::App* sub = app.add_subcommand(
           "info", "Build the model and print its size, stable step and cost per time unit");
       sub->add_option("scenario", *file, "scenario TOML file")->required();
       return std::function<int()>([file, &options] {
         apply_threads(options);
         return info(*file);
       });
     },
     20});

}  // namespace
}  // namespace sg::app
