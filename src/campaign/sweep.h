#pragma once
// `softgrain sweep`: a campaign from its file to a table and a map (docs/campaigns.md).
//
//   <output>/<name>/                  the campaign folder
//     campaign.toml                   copy of the campaign file
//     runs.txt                        the run ids, one per line (Slurm array index = line - 1)
//     runs/<id>/scenario.toml         the run's scenario (base scenario + the run's values)
//     runs/<id>/sweep.log             stdout and stderr of `softgrain run` and `analyze`
//     runs/<id>/...                   the run folder (series.csv, fields/, analysis/, ...)
//     runs/<id>/sweep.failed          present while the last attempt failed: what failed
//     campaign.csv                    one row per run (campaign_table.h)
//     mu_map.png                      mu over two parameters (scripts/plot_campaign.py)
//     slurm-array.sh                  the Slurm job array (--dry-run, --slurm; slurm_script.h)
//     slurm-jobs.txt                  the jobs submitted by --slurm (slurm_campaign.h)
//
// A run is finished iff runs/<id>/analysis/summary.json exists: `softgrain run` renames
// series.csv.partial to series.csv only at its end and summary.json is written atomically,
// so a killed sweep restarted later skips what was finished, analyses what was run but not
// analysed, and starts the rest from scratch.
#include <cstddef>
#include <filesystem>
#include <ostream>

#include "campaign/campaign_def.h"

namespace sg {

struct SweepOptions {
  enum class Mode {
    run,      // run what is not finished, gather, plot
    dry_run,  // write the run folders, runs.txt and slurm-array.sh; list the runs
    gather,   // only gather the finished runs into campaign.csv and plot
  };
  Mode mode = Mode::run;
  std::filesystem::path executable;   // softgrain itself: the runs are its child processes
  std::filesystem::path output_root;  // non-empty: replaces the campaign's `output`
  int parallel = 0;                   // > 0: replaces the campaign's `parallel`
  int threads = 0;                    // > 0: replaces the campaign's `threads`
  // `softgrain run --resume` exists: an unfinished run with a checkpoint/ continues from it.
  bool resume_from_checkpoints = false;
  bool plot = true;             // draw mu_map.png when matplotlib is available
  std::ostream* out = nullptr;  // progress; nullptr: silent
};

struct SweepResult {
  std::filesystem::path folder;  // the campaign folder
  std::filesystem::path table;   // campaign.csv
  std::size_t runs = 0, done = 0, failed = 0, pending = 0;
  // Of the done runs, those whose analysis could not measure what the run asks for (mu of a
  // shear cell): `analyze` exited with kExitUnmeasured, summary.json says why.
  std::size_t done_without_mu = 0;
  bool interrupted = false;
};

SweepResult sweep_campaign(const CampaignDef& campaign, const SweepOptions& options);

// Folder of a run inside the campaign folder.
std::filesystem::path campaign_run_folder(const std::filesystem::path& campaign_folder,
                                          const CampaignRun& run);

// True iff the run in `run_folder` is finished: its analysis/summary.json exists.
bool campaign_run_finished(const std::filesystem::path& run_folder);

// The OpenMP threads of each local run: options.threads, else the campaign's `threads`, else
// cores / parallel.
int sweep_threads(const CampaignDef& campaign, const SweepOptions& options);

// The campaign folder: <output>/<name>, absolute (options.output_root replaces `output`).
std::filesystem::path campaign_folder(const CampaignDef& campaign, const SweepOptions& options);

// What every mode does first: the campaign folder with campaign.toml, runs.txt and each run's
// scenario.toml, refusing a campaign that changed under runs already started. Returns it.
std::filesystem::path prepare_campaign_folder(const CampaignDef& campaign,
                                              const SweepOptions& options);

}  // namespace sg
