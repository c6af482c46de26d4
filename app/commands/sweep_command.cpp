// softgrain sweep CAMPAIGN: a parametric study, locally (N runs at a time, resumable) or
// prepared for a cluster (--dry-run, then --gather). docs/campaigns.md.
#include <filesystem>
#include <iostream>

#include "campaign/campaign_def.h"
#include "campaign/sweep.h"
#include "command_registry.h"
#include "core/exit_status.h"

namespace sg::app {
namespace {

struct SweepArguments {
  std::string campaign;
  std::string output;
  int parallel = 0;
  bool dry_run = false;
  bool gather = false;
  bool no_plot = false;
};

const Registration registration(
    {"sweep",
     [](CLI::App& app, const GlobalOptions& options) {
       auto a = std::make_shared<SweepArguments>();
       CLI::App* cmd = app.add_subcommand(
           "sweep",
           "Run a campaign (a base scenario and the parameters to vary): N runs at a time, "
           "resumable; gathers every run's analysis into <campaign>/campaign.csv and draws "
           "mu_map.png");
       cmd->add_option("campaign", a->campaign, "campaign TOML file")->required();
       cmd->add_option("-o,--output", a->output,
                       "output root (overrides the campaign's `output`; the campaign folder is "
                       "<output>/<name>)");
       cmd->add_option("--parallel", a->parallel, "runs at a time (overrides `parallel`)")
           ->check(CLI::PositiveNumber);
       auto* dry = cmd->add_flag("--dry-run", a->dry_run,
                                 "write the run folders, runs.txt and slurm-array.sh; list the "
                                 "runs; run nothing");
       cmd->add_flag("--gather", a->gather,
                     "run nothing: gather the finished runs into campaign.csv and draw the map "
                     "(after cluster jobs)")
           ->excludes(dry);
       cmd->add_flag("--no-plot", a->no_plot, "do not draw mu_map.png");
       cmd->footer(
           "The global --threads sets the OpenMP threads of each run (default: the campaign's "
           "`threads`, else cores / parallel).\nA run is finished when its "
           "analysis/summary.json exists; run the same command again to continue an "
           "interrupted campaign.");
       return std::function<int()>([a, &options] {
         const CampaignDef campaign = load_campaign(a->campaign);
         SweepOptions o;
         o.mode = a->dry_run  ? SweepOptions::Mode::dry_run
                  : a->gather ? SweepOptions::Mode::gather
                              : SweepOptions::Mode::run;
         // The runs are child processes of this very executable.
         o.executable = std::filesystem::read_symlink("/proc/self/exe");
         o.output_root = a->output;
         o.parallel = a->parallel;
         o.threads = options.threads;
         o.resume_from_checkpoints = true;  // `softgrain run --resume` (run_command.cpp)
         o.plot = !a->no_plot;
         o.out = &std::cout;
         const SweepResult r = sweep_campaign(campaign, o);
         if (r.interrupted) return 130;
         if (r.failed > 0) return 1;
         return r.done_without_mu > 0 ? kExitUnmeasured : 0;
       });
     },
     50});

}  // namespace
}  // namespace sg::app
