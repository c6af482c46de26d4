#pragma once
// One simulation from a scenario to a complete run folder (docs/scenario.md "Outputs"):
//   <output>/<name>/run.log        every parameter as resolved, the discretization, the step,
//                                  and at the end the step control's record and the profile
//   <output>/<name>/series.csv     time series, one row per series period (flushed per row)
//   <output>/<name>/fields.pvd     ParaView index of fields/NNNNNN.vtu snapshots
//   <output>/<name>/checkpoint.bin the state at the last checkpoint ([output]
//                                  checkpoint_period), from which a stopped run resumes
//
// Resuming (RunOptions::resume) reads checkpoint.bin, cuts series.csv.partial back to the
// rows written when the checkpoint was taken, restores the .pvd indexes to the snapshots
// taken by then, and continues: the finished folder is byte-identical to that of a run that
// never stopped (tests/run/test_checkpoint_restart.cpp).
// The progress (simulated time, steps/s, ETA) goes to `progress` when it is set.
//
// run_scenario loops over a RunSession (run/run_session.h), which programs embedding a run
// (the Python module) drive step by step themselves.
#include <filesystem>
#include <ostream>
#include <vector>

#include "scenario/scenario.h"
#include "solver/step_profile.h"

namespace sg {

class RunObserver;  // run/run_observer.h

struct RunOptions {
  std::ostream* progress = nullptr;  // progress line and summary; nullptr: silent
  // `progress` is a terminal: the progress line is rewritten in place; otherwise plain lines
  // at a modest rate (run/progress_output.h).
  bool progress_on_terminal = false;
  std::filesystem::path
      output_root_override;  // non-empty: replaces the scenario's [output] directory
  bool resume = false;       // continue the run folder from its checkpoint.bin
  // With `resume`: restore this checkpoint file instead of <run folder>/checkpoint.bin.
  std::filesystem::path resume_checkpoint;
  // false: no run folder and none of the run's own outputs (no file is written); the
  // observers below still see the loop. A resume then needs `resume_checkpoint`.
  bool write_outputs = true;
  // Starting over: remove the run folder's old outputs first, even another scenario's
  // (io/run_directory.h); without it a folder of another scenario's run is refused.
  bool overwrite = false;
  bool profile = false;  // the progress line shows the share of each phase of the step
  // >= 0: stop after this many steps (of this call), leaving the folder as a killed run
  // leaves it (series.csv.partial, no final snapshot): to test resuming.
  long stop_after_steps = -1;
  // More observers of the loop (run/run_observer.h), called after the run's own outputs, in
  // this order: tests, and programs that embed a run.
  std::vector<RunObserver*> observers;
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
  StepProfile profile;          // wall time per phase of this call's steps and outputs
};

RunSummary run_scenario(const ScenarioDef& scenario, const RunOptions& options);

}  // namespace sg
