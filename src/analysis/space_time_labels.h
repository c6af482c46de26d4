#pragma once
// Connected components of the filtered coherence field in space-time (paper 002 §2.2:
// "stack these detected areas ... labeled based on connectivity relationships in the
// space-time domain", Fig. 8C).
//
// Input: per frame t and grid node (i, j) a sign s in {-1, 0, +1}: +1 where C > threshold,
// -1 where C < -threshold, 0 elsewhere. Two marked cells belong to the same structure if
// a chain of face neighbours with the same sign joins them: (i +- 1, j, t) with i periodic,
// (i, j +- 1, t), (i, j, t +- 1). Face connectivity (6 neighbours), not 26: two regions
// touching only at a corner, or overlapping in time only diagonally, are not merged.
// Same sign only: a clockwise and a counter-clockwise structure are different objects
// (paper 002 colours them apart), even if a coarse grid makes them touch.
// Labels are numbered 0, 1, ... in order of first appearance (t, then j, then i): the
// result does not depend on the union-find's internal order.
#include <vector>

#include "analysis/regular_grid.h"

namespace sg {

struct SpaceTimeLabels {
  int nx = 0, ny = 0, nt = 0;
  std::vector<int> label;  // per cell, index (t ny + j) nx + i; -1 where unmarked
  int count = 0;           // number of structures
};

// `sign` has nx ny nt entries, index (t ny + j) nx + i.
SpaceTimeLabels label_space_time(const std::vector<signed char>& sign, int nx, int ny, int nt);

}  // namespace sg
