#pragma once
// The coherence analysis of paper 002 §2.2 set up for a run folder's grain snapshots:
// one parameter set and one grid for a whole sequence, shared by `softgrain analyze`
// (agglomerates) and `softgrain render --field coherence` (pictures, which show the C of
// grain_coherence below), so that a picture shows the field the statistics are computed from. (The
// grid's y span follows the snapshots given: analyze uses the window's, render the frames it
// draws, so values near the layer's edges may differ a little.)
//
// Parameters from the mean grain diameter d (paper 002 §2.2): grid spacing d, MLS support
// 2 d (velocity_grid.h), coherence radius R = 2.5 d ("two to three times the typical size
// of a particle"), threshold |C| > 0.8 (the caller may change it).
//
// Grid: x over the period [x0, x0 + L) when the run is periodic. When it is not, over the
// grains' x span padded on both sides by more than max(support, R) + d: the grid is then
// formally periodic (the analysis library needs a period), but no MLS support and no
// coherence disc reaches across the artificial seam to a node that has data, so nothing
// wraps. y: the given layer, else the span of the grain centres over all snapshots.
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "analysis/agglomerates.h"

namespace sg {

struct CoherenceSetup {
  AgglomerateParams params;
  RegularGrid grid;
  bool periodic = false;  // false: padded grid over a non-periodic run
  std::string note;       // how the grid was chosen, for summaries
};

// Throws sg::Error if the diameter is not positive or there is no grain at all.
CoherenceSetup choose_coherence_setup(std::span<const GrainSnapshot> snapshots,
                                      double mean_diameter,
                                      std::optional<std::pair<double, double>> periodic,
                                      std::optional<std::pair<double, double>> layer);

// C at point p by bilinear interpolation between the four surrounding grid nodes (x
// periodic), over the defined ones only, their weights renormalised; NaN if none of the
// four is defined or p is outside the grid's rows. Used to colour a grain by the C at
// its centre.
double coherence_at(const CoherenceField& field, const Vec2& p);

// Mean equivalent diameter 2 sqrt(A/pi) of a snapshot's grains (NaN if empty).
double mean_equivalent_diameter(const GrainSnapshot& snapshot);

// The coherence C at each grain's centre (coherence_at), per snapshot, indexed by body number
// (the grain rows' body column; NaN for numbers without a grain row and where C is
// undefined), on one setup for the whole sequence (choose_coherence_setup over every
// snapshot, no given layer): what `softgrain render --field coherence` colours the grains by.
struct GrainCoherence {
  std::vector<std::vector<double>> by_body;  // one per snapshot
  std::string note;                          // the setup's note
};
// Throws sg::Error if the diameter is not positive, there is no grain, or a grain row's body is
// not a body number.
GrainCoherence grain_coherence(std::span<const GrainSnapshot> snapshots, double mean_diameter,
                               std::optional<std::pair<double, double>> periodic);

}  // namespace sg
