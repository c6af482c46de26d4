#pragma once
// checkpoint.bin: the whole state and the loop state every checkpoint_period of simulated
// time (by default a tenth of the duration), written atomically after the step that reaches
// the checkpoint's time (none at the end: a complete run needs none). The step controller is
// sealed first, so that no rollback crosses a checkpoint and a resumed run repeats the
// uninterrupted one bitwise.
#include "io/checkpoint.h"
#include "run/run_observer.h"

namespace sg {

class CheckpointOutput : public RunObserver {
 public:
  explicit CheckpointOutput(RunContext& context);

  void begin(bool resumed) override;
  void after_step(const StepTaken& step) override;

  int written() const { return written_; }

 private:
  RunContext& context_;
  double period_;
  Checkpoint checkpoint_;  // reused: capture_state() fills its buffers in place
  int written_ = 0;

  void write_now();
};

// Seals the step controller and writes the state and the loop state to `path` (atomically);
// what every checkpoint of a run does. `scratch` is reused between calls.
void write_run_checkpoint(RunContext& context, const std::filesystem::path& path,
                          Checkpoint& scratch);

// Reads the checkpoint file `path` (a run folder's checkpoint.bin) into the simulation and the
// loop state (checked against the simulation's fingerprint).
void resume_from_checkpoint(RunContext& context, const std::filesystem::path& path);

}  // namespace sg
