#pragma once
// Checkpoint files: everything needed to continue a run exactly where it stopped
// (docs/architecture.md §The run loop and its outputs), in one binary file written atomically
// (write to "<path>.tmp", rename).
//
// Layout (little-endian, as written by the machine; a byte-swapped file is refused):
//   magic            8 bytes  "SGCKPT\0\x1a"
//   format version   u32      kCheckpointFormatVersion
//   byte-order mark  u32      0x01020304
//   payload size     u64      bytes
//   payload                   fingerprint, state snapshot, run-loop state (see checkpoint.cpp)
//   checksum         u64      FNV-1a 64 of the payload
//
// A reader refuses, with one line naming the file and the reason: a file that is not a
// checkpoint, another format version or byte order, a truncated file or trailing bytes, a
// checksum mismatch (corruption), and a checkpoint of another model or other run settings
// (the fingerprint), so that a checkpoint is never applied to a scenario it was not
// written for.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "solver/state_snapshot.h"
#include "solver/step_controller.h"

namespace sg {

// 6: node drives' servo loads (NodeDrive::load, load_damping) enter the model hash.
// 7: the solver's previous step (SolverState::previous_dt) and the ledger's step_change
//    (variable-step central difference, solver/explicit_solver.h).
// 8: contact histories carry the damage laws' and contact damping's state (previous
//    tractions, stored energy, viscous tractions, damage, intact / unloading flags).
// 9: the run loop's last field snapshot (time and nodal strain norms), from which the next
//    snapshot's strain_rate increment is measured (io/vtk_writer.h).
inline constexpr std::uint32_t kCheckpointFormatVersion = 9;

// What identifies the scenario a checkpoint belongs to. The counts make the common mistake
// explicit in the message; the hashes catch the rest.
struct CheckpointFingerprint {
  std::uint64_t nodes = 0, bodies = 0, rigid_bodies = 0, contour_points = 0, gauss_points = 0;
  // FNV-1a 64 of the data fixed at model build: body names, kinds and ranges, materials,
  // reference y and masses of the nodes, Gauss weights, node shape-function values, rigid
  // masses, inertias and contour offsets, drives (imposed velocities, forces, servo loads;
  // node drives: nodes, imposed velocities and servo loads),
  // gravity and the periodic cell. (Not the reference x of the nodes: a body crossing the
  // periodic seam changes it by a period.)
  std::uint64_t model_hash = 0;
  // FNV-1a 64 of the run settings the caller passes (time step, output periods, contact
  // laws): another value would make the continued run something the first part was not.
  std::uint64_t settings_hash = 0;
  friend bool operator==(const CheckpointFingerprint&, const CheckpointFingerprint&) = default;
};

CheckpointFingerprint fingerprint_of(const Model& model, std::span<const double> run_settings);

// One .pvd collection's entries: (time, file relative to the .pvd).
using PvdEntries = std::vector<std::pair<double, std::string>>;

// The run loop's own state (run/run.cpp), beside the solver's: what it has written and when
// it writes next. A member added here must be added to describe() below, which reads and
// writes it (and kCheckpointFormatVersion bumped).
struct RunLoopState {
  int next_snapshot = 0;          // index of the next fields/NNNNNN.vtu
  double next_series_time = 0.0;  // time of the next series.csv row
  double next_field_time = 0.0;   // time of the next field snapshot
  double next_checkpoint_time = 0.0;
  long series_rows = 0;            // data rows written to series.csv(.partial)
  std::uint64_t series_bytes = 0;  // size of the series file after them (header included)
  // Shear cells: sums over the second half of the run for the friction summary line.
  double top_force_sum_x = 0.0, top_force_sum_y = 0.0;
  long top_force_rows = 0;
  PvdEntries field_entries, contact_entries;  // fields.pvd and contacts.pvd so far
  StepControllerState controller;             // the adaptive step (sealed at checkpoints)
  // The last committed field snapshot: its time and nodal |E| (io/vtk_writer.h
  // nodal_strain_norms), the start of the next snapshot's strain_rate interval. Empty norms:
  // no snapshot yet.
  double strain_snapshot_time = 0.0;
  std::vector<double> strain_snapshot_norm;
};

template <class Archive, class State>  // State: RunLoopState or const RunLoopState
void describe(Archive& archive,
              State& s) requires std::is_same_v<std::remove_const_t<State>, RunLoopState> {
  archive(s.next_snapshot);
  archive(s.next_series_time);
  archive(s.next_field_time);
  archive(s.next_checkpoint_time);
  archive(s.series_rows);
  archive(s.series_bytes);
  archive(s.top_force_sum_x);
  archive(s.top_force_sum_y);
  archive(s.top_force_rows);
  archive(s.field_entries);
  archive(s.contact_entries);
  archive(s.controller);
  archive(s.strain_snapshot_time);
  archive(s.strain_snapshot_norm);
}

struct Checkpoint {
  CheckpointFingerprint fingerprint;
  StateSnapshot state;
  RunLoopState loop;
};

// Writes `checkpoint` to `path` atomically. Throws sg::Error naming the path on failure.
void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);

// Reads `path` and checks it against `expected` (the current scenario's fingerprint).
// Throws sg::Error "checkpoint '<path>': <what is wrong>" if it cannot be used.
Checkpoint read_checkpoint(const std::filesystem::path& path,
                           const CheckpointFingerprint& expected);

}  // namespace sg
