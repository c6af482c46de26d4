#pragma once
// The point arrays of the pictures drawn from the grain snapshots (grains/NNNNNN.csv, same
// number as fields/NNNNNN.vtu) with the coherence C of paper 002 eq. 5 at each grain's centre
// (analysis/coherence_frames.h, one setup for the frames drawn):
//  - "coherence": each point carries its grain's C (NaN for bodies that are not grains and
//    where C is undefined);
//  - "agglomerates", the filtered view of paper 002 Fig. 8B: each point carries its grain's
//    class, +1 where C > threshold (counter-clockwise), -1 where C < -threshold (clockwise),
//    0 for every other grain (C undefined included), NaN for bodies that are not grains.
#include <filesystem>
#include <string>
#include <vector>

#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"

namespace sg {

// Whether a field is computed from the grain snapshots rather than read from the .vtu.
bool field_from_grain_snapshots(const std::string& field);

struct GrainCoherenceFrames {
  std::vector<std::vector<double>> by_body;  // per frame: C per body number (NaN: none)
  std::vector<std::vector<char>> grain;      // per frame: whether a body number is a grain
  std::string note;                          // the coherence grid, for the command's output
};

// From the grain snapshots with the numbers of `frames`, without the rows of
// options.non_grain_rows. Throws sg::Error naming a missing grain snapshot, or when no
// frame holds a grain.
GrainCoherenceFrames grain_coherence_frames(const std::filesystem::path& run_dir,
                                            const std::vector<PvdEntry>& frames,
                                            const RenderOptions& options);

// Adds the point array named options.field ("coherence" or "agglomerates") to a frame's mesh.
void add_grain_array(VtuMesh& mesh, const GrainCoherenceFrames& c, std::size_t frame,
                     const RenderOptions& options);

// The share of grain-frames the agglomerate view colours (|C| > threshold), as a note:
// "grains with |C| > 0.8: 31 of 400 over the 20 frames drawn (7.8%)".
std::string agglomerate_share_note(const GrainCoherenceFrames& c, double threshold);

}  // namespace sg
