#pragma once
// The run loop's own state (run_session.cpp and its observers, run_observer.h), beside the
// solver's: what the outputs have written and when they write next, and the step
// controller's. The run stage owns it and its encoding; a checkpoint (io/checkpoint.h) stores
// the encoded bytes as they are (Checkpoint::run_state).
//
// An observer whose state a resumed run needs keeps it here: a member below, its line in
// describe() (the order is the file's), and kCheckpointFormatVersion (io/checkpoint.h)
// bumped.
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "solver/step_controller.h"

namespace sg {

// One .pvd collection's entries: (time, file relative to the .pvd).
using PvdEntries = std::vector<std::pair<double, std::string>>;

struct RunLoopState {
  int next_snapshot = 0;              // snapshot_output: index of the next fields/NNNNNN.vtu
  double next_series_time = 0.0;      // series_output: time of the next series.csv row
  double next_field_time = 0.0;       // snapshot_output: time of the next field snapshot
  double next_checkpoint_time = 0.0;  // checkpoint_output
  long series_rows = 0;               // series_output: data rows written to series.csv(.partial)
  std::uint64_t series_bytes = 0;     // series_output: size of the file after them (with header)
  // series_output, shear cells: sums over the second half of the run for the friction line.
  double top_force_sum_x = 0.0, top_force_sum_y = 0.0;
  long top_force_rows = 0;
  PvdEntries field_entries, contact_entries;  // snapshot_output: fields.pvd, contacts.pvd
  StepControllerState controller;             // the adaptive step (sealed at checkpoints)
  // snapshot_output: the last committed field snapshot, its time and nodal |E|
  // (io/vtk_writer.h nodal_strain_norms), the start of the next snapshot's strain_rate
  // interval. Empty norms: no snapshot yet.
  double strain_snapshot_time = 0.0;
  std::vector<double> strain_snapshot_norm;
};

// The adaptive step controller's state (solver/step_controller.h), saved as a member of
// RunLoopState (StepController::seal() before each checkpoint, set_state() after a restore).
template <class A, class S>
void describe(A& a, S& t) requires std::is_same_v<std::remove_const_t<S>, StepStatistics> {
  a(t.accepted);
  a(t.rejected);
  a(t.estimates);
  a(t.dt_min);
  a(t.dt_max);
  a(t.last_rejection);
}

template <class A, class S>
void describe(A& a, S& c) requires std::is_same_v<std::remove_const_t<S>, StepControllerState> {
  a(c.dt);
  a(c.stable_dt);
  a(c.energy_scale);
  a(c.since_estimate);
  a(c.since_reduction);
  a(c.statistics);
}

// The encoding (io/binary_archive.h), each member once: it serves both directions.
template <class A, class S>
void describe(A& a, S& s) requires std::is_same_v<std::remove_const_t<S>, RunLoopState> {
  a(s.next_snapshot);
  a(s.next_series_time);
  a(s.next_field_time);
  a(s.next_checkpoint_time);
  a(s.series_rows);
  a(s.series_bytes);
  a(s.top_force_sum_x);
  a(s.top_force_sum_y);
  a(s.top_force_rows);
  a(s.field_entries);
  a(s.contact_entries);
  a(s.controller);
  a(s.strain_snapshot_time);
  a(s.strain_snapshot_norm);
}

// The bytes a checkpoint stores for `state` (Checkpoint::run_state); `bytes` is reused.
void encode_run_loop_state(const RunLoopState& state, std::string& bytes);

// The state encoded in `bytes`. Throws sg::Error "<source>: malformed payload (...)" if they
// end early, hold an impossible value or have bytes left over; `source` names the file
// ("checkpoint '<path>'").
RunLoopState decode_run_loop_state(std::string_view bytes, const std::string& source);

}  // namespace sg
