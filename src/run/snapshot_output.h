#pragma once
// Snapshot NNNNNN (fields/, grains/, contacts/) describes one instant t_n, its label in
// fields.pvd and contacts.pvd. The fields and grains are the state at t_n, written before the
// step (prepare); the contact network is the step's force evaluation at t_n
// (ContactSystem::records()), so it is written after the step (commit), and so are the .pvd
// entries. After a rollback the run may be at the time of the last committed snapshot again
// (when field_period < dt): that instant is in the collection already and is not retaken.
// The final snapshot (finish) is of the final state, whose contact network is evaluated on a
// copy of the state that is put back after.
//
// The interval strain rate (io/vtk_writer.h strain_rate) of snapshot k is measured from the
// nodal |E| of snapshot k-1: prepare() measures from the last COMMITTED snapshot (the run
// loop state's strain_snapshot_*, saved in checkpoints) and holds its own norms aside; only
// commit() makes them the new start. A rolled-back snapshot is measured again from the same
// start, and a resumed run from the checkpoint's, so that it writes the same bytes as an
// uninterrupted run. The contact rate of contacts/NNNNNN.vtu (io/contact_vtk.h) takes the
// contour velocities of t_n, captured in prepare() too (commit() sees the state of t_n+1).
#include <string>
#include <vector>

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

  // After begin(true): "# ..." lines naming the snapshots the checkpoint's .pvd entries list
  // but the folder no longer holds (deleted since the run stopped); they are dropped from the
  // indexes, which list only files present (issue #26). "" when every one is there.
  const std::string& resume_note() const { return resume_note_; }

 private:
  std::string resume_note_;
  RunContext& context_;
  double strain_rate_unit_;  // V/D of a shear cell, else 1 (io/vtk_writer.h global_strain_rate)
  PvdCollection fields_pvd_, contacts_pvd_;
  bool snapshot_due_ = false;  // prepare() wrote the state files of a due snapshot
  StateSnapshot final_state_;  // finish(): the state put back after the contact evaluation
  // The snapshot prepare() wrote: its time and nodal |E|, the next interval's start once
  // committed; and the contour velocities of its instant, for the contact rates.
  double pending_time_ = 0.0;
  std::vector<double> pending_norm_;
  std::vector<Vec2> contour_velocity_;

  std::string snapshot_name(const char* extension) const;
  void write_state_files(double time);
  void add_to_collections(double time);
};

}  // namespace sg
