#pragma once
// The Slurm job array of a campaign, <campaign>/slurm-array.sh: array task i runs the run on
// line i+1 of runs.txt (its index in the campaign), so task ids are run indices in every
// submission and a resubmission's --array lists only the unfinished runs. Each task does what
// a local sweep does for its run (campaign/sweep.h):
//   - a finished run (analysis/summary.json) is left untouched: the task exits at once;
//   - a run with series.csv is only analysed;
//   - a run with checkpoint.bin and series.csv.partial continues (`softgrain run --resume`),
//     as after a cancel, a time-out, a preemption or a node failure (--requeue re-queues it
//     on a node failure or preemption itself);
//   - any other run starts from scratch (its folder emptied except scenario.toml);
//   - a command that fails writes runs/<id>/sweep.failed (a resumed run that fails loses its
//     checkpoint, as locally); a task killed by the scheduler writes nothing: its state is
//     the scheduler's (cancelled, timed out), and the next submission resumes it.
// The script only uses paths relative to the campaign folder (it runs from there) and the
// softgrain executable ($SOFTGRAIN, default: the one that wrote it).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "campaign/campaign_def.h"
#include "campaign/slurm_settings.h"

namespace sg {

struct SlurmScriptSpec {
  std::filesystem::path executable;  // softgrain
  int threads = 1;                   // --cpus-per-task and --threads
  std::string array;                 // the #SBATCH --array line's value ("0-74%20")
  std::string time_limit;            // --time; empty: none (the partition's default)
};

std::string slurm_array_script(const CampaignDef& campaign, const SlurmSettings& settings,
                               const SlurmScriptSpec& spec);

// The --array value for these run indices (ascending): ranges where consecutive ("0-3,7,9-10"),
// then "%K" if max_running > 0.
std::string slurm_array_spec(const std::vector<std::size_t>& indices, int max_running);

// The folder (in the campaign folder) of the tasks' Slurm output files, slurm/<job>_<task>.out.
inline constexpr const char* kSlurmOutputFolder = "slurm";

}  // namespace sg
