// softgrain run SCENARIO: simulate, writing the run folder.
#include <unistd.h>

#include <iostream>

#include "command_registry.h"
#include "run/run.h"

namespace sg::app {
namespace {

struct RunArguments {
  std::string scenario;
  std::string output;
  bool resume = false;
  bool overwrite = false;
  bool profile = false;
  long max_steps = -1;
};

const Registration registration(
    {"run",
     [](CLI::App& app, const GlobalOptions& options) {
       auto args = std::make_shared<RunArguments>();
       CLI::App* run = app.add_subcommand(
           "run", "Simulate a scenario; writes series.csv, fields/, run.log, checkpoint.bin");
       run->add_option("scenario", args->scenario, "scenario TOML file")->required();
       run->add_option("-o,--output", args->output,
                       "output root folder (overrides [output] directory)");
       run->add_flag("--resume", args->resume,
                     "continue a stopped run from <run folder>/checkpoint.bin (same scenario)");
       run->add_flag("--overwrite", args->overwrite,
                     "start over in a run folder that holds another scenario's run, removing "
                     "its outputs (fields/, grains/, series.csv, ...) first")
           ->excludes("--resume");
       run->add_flag("--profile", args->profile,
                     "show the share of each phase of the step (contacts, internal forces, ...) "
                     "with the progress line; run.log always ends with the profile");
       // For tests (the scenario fuzzer): a tiny run of any scenario. Hidden from --help.
       run->add_option("--max-steps", args->max_steps,
                       "stop after N steps, leaving the folder as a killed run leaves it")
           ->group("");
       return std::function<int()>([args, &options] {
         apply_threads(options);
         const ScenarioDef scenario = load_scenario(args->scenario);
         RunOptions run_options;
         run_options.progress = &std::cerr;
         run_options.progress_on_terminal = ::isatty(STDERR_FILENO) == 1;
         run_options.output_root_override = args->output;
         run_options.resume = args->resume;
         run_options.overwrite = args->overwrite;
         run_options.profile = args->profile;
         run_options.stop_after_steps = args->max_steps;
         const RunSummary summary = run_scenario(scenario, run_options);
         std::cout << "run '" << scenario.name << "': " << summary.steps << " steps";
         if (summary.resumed_from_step >= 0)
           std::cout << " (resumed at step " << summary.resumed_from_step << ")";
         std::cout << " of " << summary.time_step << ", " << summary.nodes << " nodes, "
                   << summary.node_steps_per_second / 1e6 << " M node-steps/s -> "
                   << summary.directory.string() << "\n";
         return 0;
       });
     },
     10});

}  // namespace
}  // namespace sg::app
