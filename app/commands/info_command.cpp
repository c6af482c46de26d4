// softgrain info SCENARIO: build the model and print its size, stable step and memory.
#include <iostream>

#include "command_registry.h"
#include "scenario/scenario.h"
#include "solver/mass_scaling.h"
#include "solver/stable_time_step.h"

namespace sg::app {
namespace {

int info(const std::string& file) {
  const ScenarioDef scenario = load_scenario(file);
  Model model = build_model(scenario);
  // The same estimate as `run` makes: with the contact penalty and after mass scaling.
  double contact_stiffness = 0.0;
  if (!scenario.contact_laws.empty())
    contact_stiffness =
        ContactSystem(model, contact_law_table(scenario), contact_settings(scenario))
            .max_stiffness();
  std::string mass_scaling;
  if (scenario.mass_scaling_step > 0.0)
    mass_scaling = describe(apply_mass_scaling(model, scenario.mass_scaling_step,
                                               scenario.time_step_safety, contact_stiffness),
                            model);
  const StableStep stable =
      estimate_stable_time_step(model, scenario.time_step_safety, contact_stiffness);
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
              << model.bodies[static_cast<std::size_t>(stable.limiting_body)].name << "')\n"
              << "  steps:         " << static_cast<long>(scenario.duration / stable.dt) << " for "
              << scenario.duration << " time units\n";
  if (!mass_scaling.empty()) std::cout << "  " << mass_scaling << "\n";
  std::cout << "  memory:        " << bytes / 1048576.0 << " MiB (node state and shape rows)\n";
  return 0;
}

const Registration registration(
    {"info",
     [](CLI::App& app, const GlobalOptions& options) {
       auto file = std::make_shared<std::string>();
       CLI::App* sub =
           app.add_subcommand("info", "Build the model and print its size and stable step");
       sub->add_option("scenario", *file, "scenario TOML file")->required();
       return std::function<int()>([file, &options] {
         apply_threads(options);
         return info(*file);
       });
     },
     20});

}  // namespace
}  // namespace sg::app
