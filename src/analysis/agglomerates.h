#pragma once
// Agglomerates ("structures") of paper 002 §2.2-3.4, from a sequence of grain snapshots:
//
//   per snapshot: grain velocities -> grid (velocity_grid.h) -> coherence C (coherence.h)
//   -> sign mask |C| > threshold (default 0.8) -> space-time labels (space_time_labels.h)
//   -> per structure: lifetime, diameter, angular velocity; share of grains; PDFs.
//
// Definitions (paper 002; choices the paper leaves open are marked "ours"):
//  - grains of a structure at frame t: those whose centre's nearest grid node (x periodic)
//    carries the structure's label at t (ours: the paper says "associated with a certain
//    number of grains belonging to it").
//  - lifetime = number of frames in which it appears x frame period (ours: a structure
//    seen in one frame lives one period, the height of its slab in the stacked picture).
//  - diameter D = 2 sqrt(A_bar / pi), A_bar its mean area over the frames where it
//    appears, area = node count x hx hy (paper 002 §3.4).
//  - angular velocity, eq. 6: omega = (1/n) sum_i V_circ,i / R_i over its grains, with R_i
//    the distance from grain i to the structure's barycentre and V_circ,i the
//    circumferential component of the grain's velocity relative to the structure's mean
//    velocity (ours: relative, so that a translating rigid cluster gives its rotation rate,
//    not its drift; barycentre and mean velocity area-weighted, consistently, so that a
//    rigid cluster gives omega exactly). Pooled over all (grain, frame) samples.
//  - omega~ = omega / (-V/D) (eq. 7): the mean shear of the cell (top at +V/2) turns
//    clockwise, the paper's "negative shear rate"; dividing by -V/D makes a structure that
//    rolls without slip between the walls omega~ = +1, as paper 002 §2.2 states. Its
//    rotation sign (sign of C) is reported apart: sign = -1 turns with the shear.
//  - share of grains in structures: (grain, frame) samples in any structure / all samples.
//  - PDFs "in terms of equivalent grains" (paper 002 §3.3): each structure weighs by its
//    number of (grain, frame) samples; densities integrate to 1 over structures' grains.
#include <span>
#include <vector>

#include "analysis/coherence.h"
#include "analysis/grain_snapshot.h"
#include "analysis/space_time_labels.h"
#include "analysis/velocity_grid.h"
#include "geometry/vec2.h"

namespace sg {

struct AgglomerateParams {
  double grid_spacing = 1.0;        // Delta x = Delta y, paper 002: 1 (one mean grain diameter)
  VelocityFitParams interpolation;  // support radius default 2 diameters
  CoherenceParams coherence;        // R default 2.5 diameters
  double threshold = 0.8;           // |C| > threshold, paper 002 §2.2
};

struct Structure {
  int sign = 0;  // +1 counter-clockwise (C > 0), -1 clockwise
  int first_frame = 0, last_frame = 0;
  int frame_count = 0;            // frames in which it appears
  double lifetime = 0.0;          // frame_count x frame period (time)
  double mean_area = 0.0;         // A_bar (length^2)
  double diameter = 0.0;          // 2 sqrt(A_bar / pi) (length)
  std::size_t grain_samples = 0;  // (grain, frame) pairs assigned to it
  double omega = 0.0;             // eq. 6 (1/time); NaN if no grain was assigned
  double omega_normalized = 0.0;  // eq. 7, omega / (-V/D); NaN if V or D unknown
};

struct AgglomerateResult {
  RegularGrid grid;
  double frame_period = 0.0;
  std::vector<CoherenceField> coherence;  // per snapshot, for pictures
  SpaceTimeLabels labels;
  std::vector<Structure> structures;  // index = label
  std::size_t grain_samples = 0;      // all (grain, frame) samples
  std::size_t grain_samples_in_structures = 0;
  double grain_share = 0.0;  // in [0, 1]
};

// Snapshots in time order, equally spaced (frame period = mean spacing of their times;
// 1 if there is one). `grid` from make_periodic_grid; `velocity` = V and `gap` = D
// (NaN if unknown: omega_normalized is then NaN).
AgglomerateResult detect_agglomerates(std::span<const GrainSnapshot> snapshots,
                                      const RegularGrid& grid, const AgglomerateParams& params,
                                      double velocity, double gap);

// Sign, frames, lifetime, mean area and diameter of each labelled structure (no grain
// data: grain_samples, omega, omega_normalized left at 0).
std::vector<Structure> measure_structure_extents(const SpaceTimeLabels& labels,
                                                 const std::vector<signed char>& sign,
                                                 const RegularGrid& grid, double frame_period);

// Paper 002 eq. 6 for one cluster at one instant, samples appended to `samples`
// (V_circ,i / R_i per grain; grains closer than 1e-12 x the cluster size to the
// barycentre are skipped, their direction being undefined). Returns the mean of the
// appended samples (NaN if none).
double cluster_angular_velocity(std::span<const Vec2> positions, std::span<const Vec2> velocities,
                                std::span<const double> areas, std::vector<double>* samples);

// A probability density from weighted samples, on bin_count equal bins over [lo, hi]
// (samples outside are dropped, their weight counted in `outside`). density[b] =
// w_b / (W bin_width), W the total weight inside.
struct WeightedPdf {
  double lo = 0.0, hi = 1.0;
  std::vector<double> centre, density;
  double outside = 0.0;
  double mode() const;  // centre of the highest bin (NaN if empty)
};
WeightedPdf weighted_pdf(std::span<const double> values, std::span<const double> weights,
                         int bin_count, double lo, double hi);

}  // namespace sg
