#pragma once
// One simulation from a scenario to a complete run folder (DESIGN.md §1):
//   <output>/<name>/run.log        every parameter as resolved, the discretization, the step
//   <output>/<name>/series.csv     time series, one row per series period (flushed per row)
//   <output>/<name>/fields.pvd     ParaView index of fields/NNNNNN.vtu snapshots
//   <output>/<name>/checkpoint.bin the state at the last checkpoint ([output]
//                                  checkpoint_period), from which a stopped run resumes
//
// Resuming (RunOptions::resume) reads checkpoint.bin, cuts series.csv.partial back to the
// rows written when the checkpoint was taken, restores the .pvd indexes to the snapshots
// taken by then, and continues: the finished folder is byte-identical to that of a run that
// never stopped (tests/io/test_checkpoint_restart.cpp).
// A progress line (simulated time, steps/s, ETA) goes to `progress` when it is set.
#include <filesystem>
#include <ostream>

#include "scenario/scenario.h"

namespace sg {

struct RunOptions {
  std::ostream* progress = nullptr;  // progress line and summary; nullptr: silent
  std::filesystem::path
      output_root_override;  // non-empty: replaces the scenario's [output] directory
  bool resume = false;       // continue the run folder from its checkpoint.bin
  // >= 0: stop after this many steps (of this call), leaving the folder as a killed run
  // leaves it (series.csv.partial, no final snapshot): to test resuming.
  long stop_after_steps = -1;
};

struct RunSummary {
  std::filesystem::path directory;
  long steps = 0;
  double time_step = 0.0;
  double wall_seconds = 0.0;
  double node_steps_per_second = 0.0;
  std::size_t nodes = 0;
  bool completed = true;        // false: stopped by stop_after_steps
  long resumed_from_step = -1;  // the checkpoint's step when resumed
  int checkpoints_written = 0;  // by this call
};

RunSummary run_scenario(const ScenarioDef& scenario, const RunOptions& options);

}  // namespace sg
