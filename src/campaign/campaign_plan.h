#pragma once
// `softgrain sweep CAMPAIGN --dry-run`: what each run will cost before anything runs.
// For every run the model is built from its scenario.toml and stepped from its initial state
// (with its step controller, on the run's thread count) for at least kMeasureSeconds of wall
// time and 10 steps, as `softgrain info` measures: wall seconds per time unit. A run's
// projected wall time is its model build plus duration x seconds per time unit (outputs and
// the analysis are not included; a layer that compacts and shears usually costs more per step
// than its initial state, README "Paper-scale runs"), its cost that times its threads.
//
// The Slurm time limit planned from it: time_margin x the longest projected run, plus
// kAnalysisAllowance for start-up and `softgrain analyze`, rounded up to the minute.
#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "campaign/campaign_def.h"

namespace sg {

inline constexpr double kMeasureSeconds = 1.0;
inline constexpr double kAnalysisAllowance = 300.0;  // seconds

struct RunPlan {
  std::size_t nodes = 0, gauss_points = 0;
  double step = 0.0;                   // the first time step
  double duration = 0.0;               // simulated time
  double build_seconds = 0.0;          // building the model (and its contact system)
  double seconds_per_time_unit = 0.0;  // measured wall time per simulated time unit
  long measured_steps = 0;
  double projected_seconds() const { return build_seconds + duration * seconds_per_time_unit; }
};

// Measures one run (its scenario file) on `threads` OpenMP threads.
RunPlan plan_run(const std::filesystem::path& scenario_file, int threads);

struct CampaignPlan {
  std::vector<RunPlan> runs;  // one per campaign run (finished runs too)
  int threads = 1;
  double core_hours() const;
  double longest_seconds() const;
  // time_margin x the longest run + kAnalysisAllowance, in Slurm's format.
  std::string time_limit(double time_margin) const;
};

// "2.91 s", "12.5 min", "7.3 h": three significant digits.
std::string format_wall_time(double seconds);

// Measures every run of the prepared campaign folder, printing one line per run to `out`
// (if not null) as it goes, then the totals.
CampaignPlan plan_campaign(const CampaignDef& campaign, const std::filesystem::path& folder,
                           int threads, std::ostream* out);

}  // namespace sg
