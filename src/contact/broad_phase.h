#pragma once
// Broad phase of the node-to-segment contact: which (slave node, master segment) pairs are
// close enough to be worth a narrow-phase projection (node_segment.h). A uniform cell grid,
// periodic in x, with a Verlet skin so that it is rebuilt every few steps, not every step.
//
// Inputs are flat arrays (ids, not pointers): every contour node of every body with its
// owner body, and every contour segment as its two end points with its owner body. A node
// is never paired with a segment of its own body (no self-contact).
//
// Periodicity in x over [x_min, x_max), period L = x_max - x_min. Positions need not be
// wrapped into the cell (a body crossing the seam may keep contiguous coordinates). A
// candidate carries the shift, a multiple of L, that brings the node next to the segment:
// the narrow phase projects (node + (shift_x, 0)) on the segment. The period must exceed
// 2 (cutoff + skin) + the longest segment's x-extent, so that at most one image of a
// segment is ever within reach of a node (checked, with a clear error).
//
// Guarantee (no missed contact). build() lists every pair whose distance (point to
// segment, nearest periodic image) is < cutoff + skin. The distance from a point to a
// segment changes by at most the point's displacement plus the largest displacement of
// the segment's end points (every point of the segment is a convex combination of them),
// and not at all when everything moves by the same translation c: it changes by at most
// |d_node - c| + max |d_end - c| for any c. needs_rebuild() takes c at the centre of the box
// of all displacements d (nearest image) since the last build, so that |d - c| <= r, half the
// box's diagonal, for every node and segment end point. As long as r <= skin / 2 every pair
// whose current distance is < cutoff is in candidates():  d_build <= d_now + skin/2 + skin/2
// < cutoff + skin. (With c = 0, the plain Verlet rule, a layer sheared as a whole rebuilds
// twice as often: its top moves by V t and its bottom stays, a box of width V t, so r = V t / 2
// where the largest displacement is V t. On the 400-grain imex cell the grains' own motion
// fills the box: 511 builds in 1,529 steps against 539.) The test test_broad_phase.cpp checks
// this against brute force on random moving configurations that cross the periodic seam, and
// on ones that translate.
//
// Determinism: candidates are sorted by (node, segment); nothing depends on threads or on
// the order of insertion beyond the input indices.
//
// Why a class (docs/architecture.md §Conventions 3 keeps state in plain structs): the candidate
// list is only valid together with the positions it was built from (the skin criterion), and
// the cell grid is scratch rebuilt with it; the class keeps the two together. Its state is the
// plain struct BroadPhaseState (capture / restore).
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/vec2.h"

namespace sg {

struct BroadPhaseParams {
  double cutoff = 0.0;      // contact search distance: pairs closer than this are needed [L]
  double skin = 0.0;        // Verlet margin added at build time [L]
  bool periodic_x = false;  // periodic images in x over [x_min, x_max)
  double x_min = 0.0;
  double x_max = 0.0;
};

// Throws sg::Error if cutoff <= 0, skin < 0, or the periodic cell is empty.
void validate(const BroadPhaseParams& params);

struct BroadPhaseInput {
  std::span<const Vec2> nodes;          // slave points (contour nodes of all bodies)
  std::span<const int> node_body;       // owner body of each node
  std::span<const Vec2> segment_start;  // master segments: end points ...
  std::span<const Vec2> segment_end;
  std::span<const int> segment_body;  // ... and owner body
};

// The multiple of the period to add to a node's x to bring it next to segment [a, b]: the
// nearest image of the segment's centre (0 when not periodic). Recompute it at each
// narrow-phase evaluation if positions are wrapped into the cell between builds (a wrap
// changes a node's x by L without moving it).
double nearest_image_shift(const BroadPhaseParams& params, const Vec2& node, const Vec2& a,
                           const Vec2& b);

struct ContactCandidate {
  int node = 0;
  int segment = 0;
  double shift_x = 0.0;  // node + (shift_x, 0) is next to the segment (at build positions)
  friend bool operator==(const ContactCandidate&, const ContactCandidate&) = default;
};

// What a broad phase remembers between steps (checkpoints, retried steps): the positions at
// the last build, which decide when the next rebuild happens, and the list built from them.
// The list is a function of those positions, but it is copied rather than rebuilt: a restore
// is then a plain copy, as cheap as a capture, and does not depend on build() staying a pure
// function of its input. The cell grid and scratch arrays are not state.
struct BroadPhaseState {
  int build_count = 0;
  std::vector<Vec2> built_nodes, built_segment_start, built_segment_end;
  std::vector<ContactCandidate> candidates;
};

class BroadPhase {
 public:
  explicit BroadPhase(const BroadPhaseParams& params);

  // Lists all pairs closer than cutoff + skin; remembers the positions for needs_rebuild().
  void build(const BroadPhaseInput& input);

  // True before the first build, when the numbers of nodes or segments changed, or when the
  // displacements of the nodes and segment end points since the last build, less the centre
  // of their box, reach more than skin / 2 (above).
  bool needs_rebuild(const BroadPhaseInput& input) const;

  // Sorted by (node, segment).
  std::span<const ContactCandidate> candidates() const { return candidates_; }
  const BroadPhaseParams& params() const { return params_; }
  int build_count() const { return build_count_; }

  // Copies the state into `state` (reusing its buffers) / back from it. restore() checks that
  // the candidates refer to the remembered nodes and segments.
  void capture(BroadPhaseState& state) const;
  void restore(const BroadPhaseState& state);

 private:
  BroadPhaseParams params_;
  int build_count_ = 0;
  std::vector<ContactCandidate> candidates_;
  // Positions at the last build (for the skin criterion).
  std::vector<Vec2> built_nodes_, built_segment_start_, built_segment_end_;
  // Cell grid, rebuilt with the list: segments of cell c are cell_segments_[cell_start_[c]
  // .. cell_start_[c+1]), in no particular order (cell_fill_: scratch of the binning).
  std::vector<int> cell_start_, cell_segments_, cell_fill_;
  // The node queries of build(), in kQueryChunks ranges of nodes: each range's candidates,
  // each list on a cache line of its own: the threads append to neighbouring ranges' lists at
  // the same time, and lists whose sizes shared a line passed it from core to core at every
  // accepted pair.
  static constexpr std::size_t kQueryChunks = 64;
  struct alignas(64) ChunkCandidates {
    std::vector<ContactCandidate> list;
  };
  std::vector<ChunkCandidates> chunk_candidates_;
  // Per thread, per segment: the stamp of the last node query that met the segment. Stamps
  // only grow (never captured nor restored), so a stale entry never matches a new query.
  std::vector<std::vector<std::uint64_t>> thread_seen_;
  std::uint64_t next_stamp_ = 1;
};

}  // namespace sg
