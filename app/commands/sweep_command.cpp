// softgrain sweep CAMPAIGN: a parametric study, locally (N runs at a time, resumable) or
// through Slurm (--slurm, --status), or prepared for a cluster (--dry-run, then --gather).
// docs/campaigns.md.
#include <filesystem>
#include <iostream>
#include <optional>

#include "analyze_options.h"
#include "campaign/campaign_def.h"
#include "campaign/slurm_campaign.h"
#include "campaign/sweep.h"
#include "command_registry.h"
#include "core/error.h"
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
  bool no_plan = false;
  bool slurm = false;
  bool status = false;
  // [slurm] overrides; CLI leaves a std::optional empty when its option is not given.
  std::optional<std::string> partition, account, qos, time, memory;
  std::optional<int> max_running;
  std::vector<std::string> sbatch;
};

const Registration registration(
    {"sweep",
     [](CLI::App& app, const GlobalOptions& options) {
       auto a = std::make_shared<SweepArguments>();
       CLI::App* cmd = app.add_subcommand(
           "sweep",
           "Run a campaign (a base scenario and the parameters to vary): N runs at a time, "
           "resumable, or through Slurm (--slurm); gathers every run's analysis into "
           "<campaign>/campaign.csv and draws mu_map.png");
       cmd->add_option("campaign", a->campaign, "campaign TOML file")->required();
       cmd->add_option("-o,--output", a->output,
                       "output root (overrides the campaign's `output`; the campaign folder is "
                       "<output>/<name>)");
       cmd->add_option("--parallel", a->parallel, "runs at a time (overrides `parallel`)")
           ->check(CLI::PositiveNumber);
       auto* dry = cmd->add_flag("--dry-run", a->dry_run,
                                 "write the run folders, runs.txt and slurm-array.sh; list the "
                                 "runs and plan them (nodes, Gauss points, step, measured wall "
                                 "time per time unit, projected wall time, core-hours); with "
                                 "--slurm also print the sbatch script and its time limit; run "
                                 "nothing");
       auto* gather = cmd->add_flag("--gather", a->gather,
                                    "run nothing: gather the finished runs into campaign.csv and "
                                    "draw the map (after cluster jobs)");
       gather->excludes(dry);
       auto* slurm = cmd->add_flag("--slurm", a->slurm,
                                   "submit the runs that are not done (nor queued or running) to "
                                   "Slurm as one job array, one task per run; record the job id "
                                   "in <campaign>/slurm-jobs.txt");
       slurm->excludes(gather);
       // (--slurm --dry-run: plan and print the script, submit nothing.)
       auto* status =
           cmd->add_flag("--status", a->status,
                         "run nothing: each run's state from Slurm and its files (pending, "
                         "running, done, failed, timed out, cancelled) and a summary");
       status->excludes(dry)->excludes(gather)->excludes(slurm);
       cmd->add_flag("--no-plot", a->no_plot, "do not draw mu_map.png");
       cmd->add_flag("--no-plan", a->no_plan,
                     "with --dry-run: do not measure the runs (about a second each plus its "
                     "model build)");
       const std::string group = "Slurm (override the campaign's [slurm] table)";
       cmd->add_option("--partition", a->partition, "sbatch --partition")->group(group);
       cmd->add_option("--account", a->account, "sbatch --account")->group(group);
       cmd->add_option("--qos", a->qos, "sbatch --qos")->group(group);
       cmd->add_option("--time", a->time, "time limit per task (sbatch --time, e.g. 12:00:00)")
           ->group(group);
       cmd->add_option("--mem", a->memory, "memory per task (sbatch --mem, e.g. 4G)")->group(group);
       cmd->add_option("--max-running", a->max_running, "tasks running at once (%K of --array)")
           ->group(group);
       cmd->add_option("--sbatch", a->sbatch,
                       "one more #SBATCH line (an sbatch option, e.g. --constraint=avx2); "
                       "repeatable")
           ->group(group);
       cmd->footer(
           "The global --threads sets the OpenMP threads of each run (default: the campaign's "
           "`threads`, else cores / parallel locally and 1 on Slurm, where it is also "
           "--cpus-per-task).\nA run is finished when its analysis/summary.json exists; run the "
           "same command again to continue an interrupted campaign (with --slurm: submit the "
           "unfinished runs again; each resumes from its checkpoint).");
       return std::function<int()>([a, &options] {
         CampaignDef campaign = load_campaign(a->campaign);
         // Before any run: a misspelt analysis option would fail each analysis after its
         // simulation.
         if (const std::string error = analyze_options_error(campaign.analyze_options);
             !error.empty())
           SG_THROW(campaign.file.string()
                    << ":" << campaign.analyze_options_line
                    << ": key 'analyze_options': `softgrain analyze` refuses them: " << error);
         SlurmOverrides overrides;
         overrides.partition = a->partition;
         overrides.account = a->account;
         overrides.qos = a->qos;
         overrides.time = a->time;
         overrides.memory = a->memory;
         overrides.max_running = a->max_running;
         overrides.extra = a->sbatch;
         campaign.slurm = apply_slurm_overrides(campaign.slurm, overrides);
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
         if (a->status) {
           const SlurmCampaignStatus s =
               slurm_campaign_status(campaign, campaign_folder(campaign, o));
           print_slurm_status(campaign, s, std::cout);
           return 0;
         }
         if (a->slurm && !a->dry_run) {
           submit_campaign_to_slurm(campaign, o);
           return 0;
         }
         const SweepResult r = sweep_campaign(campaign, o);
         if (a->dry_run && !a->no_plan) {
           // What the runs will cost (and, for Slurm, the script and its time limit).
           const int threads = a->slurm ? slurm_threads(campaign, o) : sweep_threads(campaign, o);
           const CampaignPlan plan = plan_campaign(campaign, r.folder, threads, &std::cout);
           if (a->slurm) print_slurm_plan(campaign, o, r.folder, plan, std::cout);
           return 0;
         }
         if (r.interrupted) return 130;
         if (r.failed > 0) return 1;
         return r.done_without_mu > 0 ? kExitUnmeasured : 0;
       });
     },
     50});

}  // namespace
}  // namespace sg::app
