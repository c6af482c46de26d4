#pragma once
// `softgrain generate`: what the built sample is, measured on the Model that `run` would
// simulate (build_model, same seed), and its files (README.md "Using it": the sample only:
// grains, first bodies, nodes, quadrature):
//   <run folder>/sample/sample.vtu   the bodies at t = 0 (io/vtk_writer.h)
//   <run folder>/sample/sample.json  the measurements below (format version 1), atomic
//   <run folder>/sample/sample.png   a picture of the sample (render/sample_picture.h)
//
// Measured, not echoed: counts come from the Model; the solid fraction from the grains' contour
// areas and the container read off the built walls or first bodies; the size moments from the
// generator's draws (regenerated with the builder's mixture and seed, and checked against the
// built bodies' areas so a drift between the two is reported, not hidden), next to the moments
// the requested law has exactly, and their Kolmogorov-Smirnov distance to the law; the
// roughness RMS and the spectral slope (with the Hurst exponent it implies) from the built
// first-body contours; the smallest gap from the exact contours of every pair of bodies
// (periodic images included; geometry/contour_gap.h).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace sg {

// One grain component: requested vs drawn sizes.
struct ComponentSizes {
  std::string name;
  bool rigid = false;
  std::string quantity;  // "diameter" (disc), "long axis" (ellipse), "2 r_mean" (Fourier)
  int count = 0;
  double requested_mean = 0.0, requested_std = 0.0;  // of the requested law (exact)
  double drawn_mean = 0.0, drawn_std = 0.0;          // of the generator's draws
  // Mean of 2 sqrt(A / pi) over the built bodies of the component (A: contour area).
  double area_diameter_mean = 0.0;
  // Kolmogorov-Smirnov D of the draws against the requested law (geometry/size_distribution.h
  // ks_statistic) and the 5% critical value 1.36 / sqrt(count): D above it rejects the law at
  // the 5% level (which a correct generator does for 1 sample in 20).
  double ks_statistic = 0.0, ks_critical_5pct = 0.0;
};

struct SurfaceRoughness {
  std::string body;  // "bottom", "top"
  double requested_rms = 0.0, measured_rms = 0.0;
  // Spectral slope of the built surface: least-squares slope of ln P_k against ln q_k over the
  // modes [slope_min_mode, slope_max_mode] of its periodogram (geometry/rough_surface.h), the
  // Hurst exponent it implies, H = -(1 + slope) / 2, and the requested one. NaN (null) when the
  // surface is not sampled evenly (see slope_note).
  double spectral_slope = 0.0, expected_slope = 0.0;
  double measured_hurst = 0.0, requested_hurst = 0.0;
  int points = 0, slope_min_mode = 0, slope_max_mode = 0;
  std::string slope_note;
};

struct SampleReport {
  std::string name;     // the scenario's name
  std::string builder;  // "shear_cell", "compaction_box" or "explicit"
  std::size_t bodies = 0, rigid_bodies = 0, deformable_bodies = 0;
  std::size_t grains = 0, rigid_grains = 0, deformable_grains = 0;
  std::size_t other_bodies = 0;  // walls, first bodies
  std::size_t nodes = 0, gauss_points = 0, contour_points = 0, triangles = 0;
  double grain_area = 0.0;
  // The region the grains fill at t = 0 (compaction box: inside the walls; shear cell: L times
  // the distance between the mean surfaces); 0 when the scenario has none.
  double container_area = 0.0;
  double solid_fraction = 0.0;  // grain_area / container_area (0 without a container)
  std::vector<ComponentSizes> sizes;
  std::string sizes_note;  // why there are no sizes, or a mismatch
  std::vector<SurfaceRoughness> roughness;
  // Smallest distance between the contours of two different bodies (length); negative when
  // some pair overlaps (then minus the deepest penetration of a contour point).
  double smallest_gap = 0.0;
  std::string gap_body_a, gap_body_b;
  int overlapping_pairs = 0;
  // As `softgrain info` prints them: after mass scaling, with the contact penalty.
  double stable_step = 0.0;
  bool damping_limited = false;
  std::string limiting_body;
  long steps = 0;  // duration / stable_step
  std::string mass_scaling;
  double memory_mib = 0.0;  // node state and shape rows
};

// Measures the model built from `scenario` (applies mass scaling to it when the scenario asks,
// as run does).
SampleReport measure_sample(const ScenarioDef& scenario, Model& model);

// The smallest contour gap between bodies (see SampleReport::smallest_gap), fills the gap
// fields of `report`.
void measure_gaps(const Model& model, SampleReport& report);

std::string sample_json(const SampleReport& report);
// A readable table for the terminal.
std::string sample_table(const SampleReport& report);

// Writes <dir>/sample.vtu and <dir>/sample.json (atomically).
void write_sample(const Model& model, const SampleReport& report, const std::filesystem::path& dir);

}  // namespace sg
