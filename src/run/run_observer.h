#pragma once
// The outputs of a run observe the run loop (run.cpp) at fixed points; the loop itself never
// knows what a file looks like. One step of the loop reads
//
//   prepare(now)        every observer: the state is that of t_n, before the step; an output
//                       describing t_n takes what it needs now (positions, fields)
//   advance             the step controller takes one accepted step, which may have rolled
//                       back and retried (step_controller.h)
//   commit(step)        every observer, ONLY IF the accepted step started at t_n: the step's
//                       force evaluation is that of t_n, and what prepare() took is written
//   after_step(step)    every observer: the state is that of t_n+1 (checkpoints, progress)
//
// The rollback rule, the same for every output: a rejection may roll the run back to a state
// older than t_n (step_controller.h); the step accepted then did not start at t_n, so nothing
// describing t_n is committed, and it is taken again (same row, same snapshot index, files
// overwritten) when the run is back at t_n. With the energy check a later rejection rolls back
// to t_n at the earliest, so what is committed stays the run's history; a failed step without
// it rolls back to the last held state, which may be older, and rows and snapshots committed
// since then show the abandoned trajectory (step_controller.h). No rollback crosses a
// checkpoint (the controller is sealed there).
//
// Observers share the run's RunLoopState (run_loop_state.h, the run stage's part of a
// checkpoint): each owns its fields of it (next output times, counters, .pvd entries) and
// keeps them current, so that a checkpoint writes the loop state as it is and a resumed run
// restores every observer from it (begin(true)).
#include <filesystem>

#include "run/run_loop_state.h"
#include "run/simulation.h"
#include "scenario/scenario.h"

namespace sg {

// The run folder and what lives in it.
struct RunFolder {
  std::filesystem::path dir;
  std::filesystem::path checkpoint() const { return dir / "checkpoint.bin"; }
  std::filesystem::path series() const { return dir / "series.csv"; }
  // series.csv is written under this name and renamed when the run completes: a file named
  // series.csv always means a complete run.
  std::filesystem::path partial_series() const { return dir / "series.csv.partial"; }
  std::filesystem::path run_log() const { return dir / "run.log"; }
};

// What every observer sees.
struct RunContext {
  const ScenarioDef& scenario;
  const RunFolder& folder;
  Simulation& simulation;
  RunLoopState& loop;
  // "Time reached" despite round-off: t >= target - time_tolerance.
  double time_tolerance;
};

// An instant of the run: the state before a step.
struct RunInstant {
  double time;
  long step;
};

// A step the controller accepted.
struct StepTaken {
  RunInstant start;  // the instant before the call (t_n, n)
  double dt;         // the accepted step
  bool from_start;   // the accepted step started at `start` (no rollback beyond it)
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // Before the first step: a fresh run (resumed = false), or a run resumed from a checkpoint
  // whose loop state is already in the context's RunLoopState.
  virtual void begin(bool resumed) { (void)resumed; }
  virtual void prepare(const RunInstant& now) { (void)now; }
  virtual void commit(const StepTaken& step) { (void)step; }
  virtual void after_step(const StepTaken& step) { (void)step; }
  // The run reached its duration (not called when it stops early).
  virtual void finish() {}
};

}  // namespace sg
