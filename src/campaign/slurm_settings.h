#pragma once
// How a campaign is submitted to Slurm (`softgrain sweep CAMPAIGN --slurm`): the campaign
// file's [slurm] table, each key overridable on the command line (docs/campaigns.md).
//
//   [slurm]
//   partition = "compute"             # sbatch --partition
//   account = "lab42"                 # --account
//   qos = "normal"                    # --qos
//   time = "12:00:00"                 # --time, per task (Slurm's formats); default: planned
//   memory = "4G"                     # --mem, per task (a number of MB, or with K, M, G, T)
//   max_running = 20                  # %K of --array: tasks running at once
//   requeue = true                    # --requeue: a preempted or failed node's task re-queued
//   time_margin = 1.5                 # planned time limit = margin x projected wall time
//   extra = ["--constraint=avx2"]     # more #SBATCH lines, as given
//
// Every malformed key is an error naming it: "mu.toml:14: key 'slurm.time': ...".
#include <optional>
#include <string>
#include <vector>

namespace sg {

struct SlurmSettings {
  std::string partition, account, qos;
  std::string time;  // as given (validated); empty: estimated by the planner, else none
  std::string memory;
  int max_running = 0;  // 0: no %K limit
  bool requeue = true;
  double time_margin = 1.5;        // > 1
  std::vector<std::string> extra;  // "--option=value", one #SBATCH line each
};

// (The [slurm] table is read by campaign/slurm_settings_reader.h.)

// Command-line overrides, each checked like its key; errors name the option ("--time").
struct SlurmOverrides {
  std::optional<std::string> partition, account, qos, time, memory;
  std::optional<int> max_running;
  std::vector<std::string> extra;  // appended to the table's
};
SlurmSettings apply_slurm_overrides(SlurmSettings settings, const SlurmOverrides& overrides);

// Seconds of a Slurm time limit ("90" minutes, "MM:SS", "HH:MM:SS", "D-HH", "D-HH:MM",
// "D-HH:MM:SS"); nullopt if it is none of them. "UNLIMITED" and "INFINITE" are -1.
std::optional<long> parse_slurm_time(const std::string& text);

// A duration in Slurm's "D-HH:MM:SS" (or "HH:MM:SS" under a day), rounded up to the minute.
std::string format_slurm_time(double seconds);

}  // namespace sg
