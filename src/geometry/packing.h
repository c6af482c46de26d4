#pragma once
// Sample generation, placement: grains (geometry/grain_population.h) placed without overlap
// in a rectangular box or a periodic strip, compacted along -y.
//
// Placement, in three steps (all randomness from one seeded engine, see
// size_distribution.h, so a seed gives the same sample everywhere):
//  1. random sequential addition (RSA): grains, largest first, at uniform random positions
//     of a loose region, rejected while they overlap an already placed grain;
//  2. compaction: Metropolis Monte Carlo of hard grains under gravity (moves in x, y and
//     rotation; a move that overlaps is rejected; one that rises by dy is accepted with
//     probability exp(-dy / T)), the temperature T annealed to zero and each grain's step
//     size adapted to its cage; the grains sediment from the loose RSA state, and the
//     finite temperature lets them leave the arches that a pure descent freezes in
//     (a straight "drop to first contact" pass was tried first: it builds a ballistic
//     deposit near 0.49 that the annealing then only slowly repairs);
//  3. verification: every pair of contours, periodic images included, is tested exactly
//     (edge intersections and containment, geometry/contour_gap.h), not only their bounding
//     circles.
// Bounding circles and inscribed circles about the centroid settle most pair tests
// without touching the contours; the exact test runs only in the thin shell between them.
//
// Rejected alternative: soft-disc relaxation of the bounding circles. It is faster for
// discs but packs elongated grains as if they were their bounding discs (an ellipse of
// aspect 2 fills half of its circle) and leaves overlaps to be removed afterwards.
#include <cstdint>
#include <vector>

#include "geometry/contour_gap.h"
#include "geometry/grain_population.h"
#include "geometry/polygon.h"
#include "geometry/size_distribution.h"

namespace sg {

enum class ContainerKind {
  box,             // [x_min, x_max] x [y_min, y_max], four walls
  periodic_strip,  // periodic in x with period x_max - x_min, floor y_min, free top
};

struct ContainerDef {
  ContainerKind kind = ContainerKind::box;
  double x_min = 0.0;  // length
  double x_max = 10.0;
  double y_min = 0.0;   // floor
  double y_max = 10.0;  // ceiling of the box; ignored by the strip
};

struct PackingDef {
  ContainerDef container;
  // Smallest clearance kept between two contours and between a contour and a wall
  // (length). 0: contours may come arbitrarily close but never cross.
  double min_gap = 0.0;
  bool compact = true;         // step 2 (otherwise the RSA placement is returned)
  bool allow_rotation = true;  // compaction may rotate grains (it perturbs the orientations)
  // Strip only: solid fraction of the region [y_min, y_min + H] in which RSA places the
  // grains before compaction (RSA of discs jams near 0.55, so 0.3 places quickly).
  double loose_fraction = 0.3;
  int max_attempts_per_grain = 20000;  // RSA draws before giving up (box) or growing H (strip)
  int max_sweeps = 2000;  // compaction sweeps (one trial move per grain each; ~0.15 ms per
                          // sweep for 200 discs)
};

struct PackingResult {
  // Per grain, in the input order: world = position + rotation(angle) * (local - centroid).
  std::vector<Vec2> positions;  // centroids; strip: x wrapped into [x_min, x_max)
  std::vector<double> rotations;
  std::vector<Polygon> contours;  // world coordinates (strip: may cross x_max; see images)
  double grain_area = 0.0;        // sum of the contour areas
  double top = 0.0;               // highest contour point
  // grain_area / ((x_max - x_min) (top - y_min)): counts the rough top layer as porosity.
  double solid_fraction = 0.0;
  // Solid fraction within [y_min + D, top - 2 D], D the largest bounding diameter (away
  // from the floor's layering and the free surface); equal to solid_fraction when that
  // band is empty.
  double bulk_solid_fraction = 0.0;
  int sweeps = 0;  // compaction sweeps performed
};

// Places grains given by local contours (any CCW simple polygons; they are re-centred on
// their centroids). Throws sg::Error when they cannot fit (box) or the input is invalid.
PackingResult pack_grains(const std::vector<Polygon>& local_contours, const PackingDef& def,
                          std::uint64_t seed);
PackingResult pack_grains(const std::vector<GrainDef>& grains, const PackingDef& def,
                          std::uint64_t seed);

// The packed grains' indices by increasing centroid x (ties: the input order). The sample
// builders add the grains to the model in this order. The grains are drawn and placed in random
// order: numbered in it, a grain's neighbours were anywhere among the bodies; along x, the
// contact partners of a body are bodies of nearby index, whose data are near in memory and,
// with the threads' contiguous ranges of bodies (core/cost_balanced_ranges.h), mostly on the
// same core.
std::vector<std::size_t> order_along_x(const PackingResult& packed);

}  // namespace sg
