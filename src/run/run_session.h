#pragma once
// One run driven step by step: what run_scenario (run/run.h) loops over, and what a program
// embedding a run drives itself (the Python module's Simulation, python/src/).
//
// The session owns everything a run holds between steps: the scenario, the Simulation, the
// loop state and the outputs, built and begun as `softgrain run` does (run folder checked,
// resumed from a checkpoint if asked, run.log written). step() is one iteration of the loop
// (run/run_observer.h: prepare, advance, commit, after_step), so a program calling step()
// until reached_end() and then close() writes the very files `softgrain run` writes, bitwise.
// close() ends the session: the outputs' finish() if the run reached its duration, else the
// folder stays as a killed run leaves it (series.csv.partial, resumable); run.log rewritten
// with the session's step control record and profile.
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/checkpoint.h"
#include "io/run_lock.h"
#include "run/run.h"
#include "run/run_observer.h"
#include "run/simulation.h"

namespace sg {

class SeriesOutput;
class SnapshotOutput;
class CheckpointOutput;

class RunSession {
 public:
  // Throws sg::Error (bad folder, checkpoint of another scenario, ...) before any step.
  RunSession(const ScenarioDef& scenario, const RunOptions& options);
  ~RunSession();
  RunSession(const RunSession&) = delete;  // observers hold references to the members
  RunSession& operator=(const RunSession&) = delete;

  // Simulated time has reached the duration (round-off aside): the loop's end condition.
  bool reached_end() const;
  // One accepted step, observed by the outputs. Must not be called after close().
  void step();
  // Ends the session (see above) and returns its summary; once.
  RunSummary close();
  bool closed() const { return closed_; }

  // Writes a checkpoint of the present state to `path`, as the run's own checkpoints are
  // written: the step controller is sealed first (no later rollback crosses it), so the run
  // resumed from it repeats this one bitwise.
  void write_checkpoint(const std::filesystem::path& path);

  // For a caller that caught `error` from step() or close(): run.log records where and why
  // the run stopped, then the error is rethrown (an sg::Error as it is, anything else as an
  // sg::Error naming the run and the step).
  [[noreturn]] void stop_with_error(const std::exception& error);

  Simulation& simulation() { return *simulation_; }
  const Simulation& simulation() const { return *simulation_; }
  const ScenarioDef& scenario() const { return scenario_; }
  // The run folder; empty without outputs (RunOptions::write_outputs = false).
  const std::filesystem::path& directory() const { return folder_.dir; }
  long first_step() const { return first_step_; }

 private:
  using clock = std::chrono::steady_clock;
  ScenarioDef scenario_;
  RunOptions options_;
  clock::time_point start_;
  RunFolderLock lock_;  // held from before the folder is prepared to the session's end
  RunFolder folder_;
  std::unique_ptr<Simulation> simulation_;
  RunLoopState loop_;  // what the outputs have written and when they write next (checkpointed)
  RunContext context_;
  std::vector<std::unique_ptr<RunObserver>> own_outputs_;
  SnapshotOutput* snapshots_ = nullptr;      // in own_outputs_; null without outputs
  SeriesOutput* series_ = nullptr;           // idem
  CheckpointOutput* checkpoints_ = nullptr;  // idem
  std::vector<RunObserver*> observers_;      // own outputs, then RunOptions::observers
  Checkpoint checkpoint_scratch_;            // write_checkpoint()'s buffers
  RunSummary summary_;
  std::string resume_note_;
  long first_step_ = 0;
  bool closed_ = false;
};

}  // namespace sg
