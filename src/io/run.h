#pragma once
// One simulation from a scenario to a complete run folder (DESIGN.md §1):
//   <output>/<name>/run.log        every parameter as resolved, the discretization, the step
//   <output>/<name>/series.csv     time series, one row per series period (flushed per row)
//   <output>/<name>/fields.pvd     ParaView index of fields/NNNNNN.vtu snapshots
// A progress line (simulated time, steps/s, ETA) goes to `progress` when it is set.
#include <filesystem>
#include <ostream>

#include "scenario/scenario.h"

namespace sg {

struct RunOptions {
  std::ostream* progress = nullptr;  // progress line and summary; nullptr: silent
  std::filesystem::path
      output_root_override;  // non-empty: replaces the scenario's [output] directory
};

struct RunSummary {
  std::filesystem::path directory;
  long steps = 0;
  double time_step = 0.0;
  double wall_seconds = 0.0;
  double node_steps_per_second = 0.0;
  std::size_t nodes = 0;
};

RunSummary run_scenario(const ScenarioDef& scenario, const RunOptions& options);

}  // namespace sg
