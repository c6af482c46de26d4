// softgrain: the command line. Thin: parses options, calls the library, prints errors once.
#include <omp.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "core/error.h"
#include "io/run.h"
#include "scenario/scenario.h"
#include "solver/stable_time_step.h"

namespace {

void apply_threads(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

int run_command(const std::string& file, const std::string& output, int threads) {
  apply_threads(threads);
  const sg::ScenarioDef scenario = sg::load_scenario(file);
  sg::RunOptions options;
  options.progress = &std::cerr;
  options.output_root_override = output;
  const sg::RunSummary summary = sg::run_scenario(scenario, options);
  std::cout << "run '" << scenario.name << "': " << summary.steps << " steps of "
            << summary.time_step << ", " << summary.nodes << " nodes, "
            << summary.node_steps_per_second / 1e6 << " M node-steps/s -> "
            << summary.directory.string() << "\n";
  return 0;
}

int info_command(const std::string& file, int threads) {
  apply_threads(threads);
  const sg::ScenarioDef scenario = sg::load_scenario(file);
  const sg::Model model = sg::build_model(scenario);
  const sg::StableStep stable = sg::estimate_stable_time_step(model, scenario.time_step_safety);
  const double bytes = static_cast<double>(model.node_count()) * 10 * sizeof(double) +
                       static_cast<double>(model.gauss_rows.entries()) * (3 * sizeof(double) + 4) +
                       static_cast<double>(model.node_rows.entries()) * (3 * sizeof(double) + 4);
  std::cout << "scenario '" << scenario.name << "' (" << file << ")\n"
            << "  bodies:        " << model.bodies.size() << "\n"
            << "  materials:     " << model.materials.size() << "\n"
            << "  field nodes:   " << model.node_count() << "\n"
            << "  Gauss points:  " << model.gauss_point_count() << " ("
            << static_cast<double>(model.gauss_rows.entries()) /
                   static_cast<double>(model.gauss_point_count())
            << " neighbours per point on average)\n"
            << "  stable step:   " << stable.dt << " ("
            << (stable.damping_limited ? "damping-limited" : "wave-speed-limited") << ", body '"
            << model.bodies[static_cast<std::size_t>(stable.limiting_body)].name << "')\n"
            << "  steps:         " << static_cast<long>(scenario.duration / stable.dt) << " for "
            << scenario.duration << " time units\n"
            << "  memory:        " << bytes / 1048576.0 << " MiB (node state and shape rows)\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"softgrain: 2D simulation of rigid and highly deformable grains (multibody meshfree)"};
  app.footer(
      "Examples:\n"
      "  softgrain run examples/free-grains.toml            simulate; outputs in out/<name>/\n"
      "  softgrain run examples/free-grains.toml --threads 2\n"
      "  softgrain info examples/free-grains.toml           bodies, nodes, step, memory\n");
  app.require_subcommand(1);
  int threads = 0;
  app.add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);

  std::string run_file, output;
  CLI::App* run = app.add_subcommand("run", "Simulate a scenario; writes series.csv, fields/, run.log");
  run->add_option("scenario", run_file, "scenario TOML file")->required();
  run->add_option("-o,--output", output, "output root folder (overrides [output] directory)");

  std::string info_file;
  CLI::App* info = app.add_subcommand("info", "Build the model and print its size and stable step");
  info->add_option("scenario", info_file, "scenario TOML file")->required();

  CLI11_PARSE(app, argc, argv);
  try {
    if (*run) return run_command(run_file, output, threads);
    if (*info) return info_command(info_file, threads);
  } catch (const sg::Error& e) {
    std::cerr << "\nsoftgrain: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "\nsoftgrain: unexpected error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
