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
  write_run_checkpoint(context_, context_.folder.checkpoint(), checkpoint_);
  ++written_;
}

void write_run_checkpoint(RunContext& context, const std::filesystem::path& path,
                          Checkpoint& scratch) {
  Simulation& sim = context.simulation;
  RunLoopState& loop = context.loop;
  sim.controller.seal();  // no rollback crosses a checkpoint (resumed = uninterrupted, bitwise)
  loop.controller = sim.controller.state();
  capture_state(sim.solver, sim.contacts.get(), scratch.state);
  scratch.fingerprint = sim.fingerprint;
  encode_run_loop_state(loop, scratch.run_state);
  write_checkpoint(path, scratch);
  // A run resumed from here starts without the IMEX preconditioners' reference states and
  // carried viscous forces: the uninterrupted run drops them too, so that both go on alike.
  sim.solver.drop_implicit_history();
}

void resume_from_checkpoint(RunContext& context, const std::filesystem::path& path) {
  Simulation& sim = context.simulation;
  const Checkpoint checkpoint = read_checkpoint(path, sim.fingerprint);
  restore_state(checkpoint.state, sim.solver, sim.contacts.get());
  context.loop = decode_run_loop_state(checkpoint.run_state, "checkpoint '" + path.string() + "'");
  sim.controller.set_state(context.loop.controller);
}

}  // namespace sg
