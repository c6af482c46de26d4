#pragma once
// Snapshot NNNNNN (fields/, grains/, contacts/) describes one instant t_n, its label in
// fields.pvd and contacts.pvd. The fields and grains are the state at t_n, written before the
// step (prepare); the contact network is the step's force evaluation at t_n
// (ContactSystem::records()), so it is written after the step (commit), and so are the .pvd
// entries. After a rollback the run may be at the time of the last committed snapshot again
// (when field_period < dt): that instant is in the collection already and is not retaken.
// The final snapshot (finish) is of the final state, whose contact network is evaluated on a
// copy of the state that is put back after.
#include <string>

#include "io/vtk_writer.h"
#include "run/run_observer.h"
#include "solver/state_snapshot.h"

namespace sg {

class SnapshotOutput : public RunObserver {
 public:
  explicit SnapshotOutput(RunContext& context);

  void begin(bool resumed) override;
  void prepare(const RunInstant& now) override;
  void commit(const StepTaken& step) override;
  void finish() override;

 private:
  RunContext& context_;
  double strain_rate_unit_;  // V/D of a shear cell, else 1 (io/vtk_writer.h global_strain_rate)
  PvdCollection fields_pvd_, contacts_pvd_;
  bool snapshot_due_ = false;  // prepare() wrote the state files of a due snapshot
  StateSnapshot final_state_;  // finish(): the state put back after the contact evaluation

  std::string snapshot_name(const char* extension) const;
  void write_state_files();
  void add_to_collections(double time);
};

}  // namespace sg
