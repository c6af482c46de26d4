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
//   payload                   fingerprint, state snapshot (see checkpoint.cpp), then the run
//                             stage's bytes (Checkpoint::run_state) to its end
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

#include "solver/state_snapshot.h"

namespace sg {

// 6: node drives' servo loads (NodeDrive::load, load_damping) enter the model hash.
// 7: the solver's previous step (SolverState::previous_dt) and the ledger's step_change
//    (variable-step central difference, solver/stepper.h).
// 8: contact histories carry the damage laws' and contact damping's state (previous
//    tractions, stored energy, viscous tractions, damage, intact / unloading flags).
// 9: the run loop's last field snapshot (time and nodal strain norms), from which the next
//    snapshot's strain_rate increment is measured (io/vtk_writer.h).
// (A change of the run stage's part, run/run_loop_state.h, bumps this version too: a file
// holds one version for the whole payload.)
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

struct Checkpoint {
  CheckpointFingerprint fingerprint;
  StateSnapshot state;
  // The run stage's own state (its outputs' counters, next output times, the step
  // controller: run/run_loop_state.h), encoded by that stage (io/binary_archive.h) and stored
  // as it is at the end of the payload: what it holds is no concern of this stage.
  std::string run_state;
};

// Writes `checkpoint` to `path` atomically. Throws sg::Error naming the path on failure.
void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);

// Reads `path` and checks it against `expected` (the current scenario's fingerprint).
// Throws sg::Error "checkpoint '<path>': <what is wrong>" if it cannot be used.
Checkpoint read_checkpoint(const std::filesystem::path& path,
                           const CheckpointFingerprint& expected);

}  // namespace sg
