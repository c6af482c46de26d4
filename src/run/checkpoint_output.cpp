#include "run/checkpoint_output.h"

#include <filesystem>

namespace sg {

CheckpointOutput::CheckpointOutput(RunContext& context)
    : context_(context),
      period_(context.scenario.checkpoint_period < 0.0 ? context.scenario.duration / 10.0
                                                       : context.scenario.checkpoint_period) {}

void CheckpointOutput::begin(bool resumed) {
  if (resumed) return;
  context_.loop.next_checkpoint_time = period_;
  // (A checkpoint left by an earlier run in this folder was removed by prepare_run_directory.)
}

void CheckpointOutput::after_step(const StepTaken&) {
  const double t = context_.simulation.solver.state().time;
  RunLoopState& loop = context_.loop;
  if (period_ <= 0.0 || t >= context_.scenario.duration - context_.time_tolerance ||
      t < loop.next_checkpoint_time - context_.time_tolerance)
    return;
  loop.next_checkpoint_time += period_;  // before saving: the saved loop is current
  write_now();
}

void CheckpointOutput::write_now() {
  Simulation& sim = context_.simulation;
  RunLoopState& loop = context_.loop;
  sim.controller.seal();  // no rollback crosses a checkpoint (resumed = uninterrupted, bitwise)
  loop.controller = sim.controller.state();
  capture_state(sim.solver, sim.contacts.get(), checkpoint_.state);
  checkpoint_.fingerprint = sim.fingerprint;
  checkpoint_.loop = loop;
  write_checkpoint(context_.folder.checkpoint(), checkpoint_);
  // A run resumed from here starts without the IMEX preconditioners' reference states: the
  // uninterrupted run drops them too, so that both go on with the same factors.
  sim.solver.refresh_implicit_preconditioners();
  ++written_;
}

void resume_from_checkpoint(RunContext& context) {
  Simulation& sim = context.simulation;
  const Checkpoint checkpoint = read_checkpoint(context.folder.checkpoint(), sim.fingerprint);
  restore_state(checkpoint.state, sim.solver, sim.contacts.get());
  context.loop = checkpoint.loop;
  sim.controller.set_state(context.loop.controller);
}

}  // namespace sg
