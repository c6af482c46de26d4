#pragma once
// Sample generation, the population: grain shape laws, mixtures by number fraction, each
// grain rigid or deformable, drawn from one seeded engine (geometry/size_distribution.h), so
// a seed gives the same grains everywhere. Placing them is geometry/packing.h.
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/fourier_shape.h"
#include "geometry/node_spacing.h"
#include "geometry/polygon.h"
#include "geometry/size_distribution.h"

namespace sg {

enum class GrainShapeKind { disc, ellipse, fourier };

// One shape law. Lengths are full lengths (diameters, axis lengths), not radii.
struct GrainShapeDef {
  GrainShapeKind kind = GrainShapeKind::disc;
  // disc: the diameter; fourier: twice the mean radius r_mean. Paper 001: [0.85, 1.15].
  SizeRangeDef diameter{0.85, 1.15, SizeLaw::uniform};
  // ellipse: long and short axis lengths, drawn independently (paper 003: 1-2 and 0.6-1.2
  // µm); when the ranges overlap and the short draw exceeds the long one, they are swapped.
  SizeRangeDef major_axis{1.0, 2.0, SizeLaw::uniform};
  SizeRangeDef minor_axis{0.6, 1.2, SizeLaw::uniform};
  // ellipse: angle of the long axis to +x (rad), uniform in [min, max).
  double orientation_min = 0.0;
  double orientation_max = std::numbers::pi;
  // fourier: the descriptor spectrum (fourier_shape.h).
  FourierSpectrumDef spectrum;
  // Contour vertex spacing (length): the boundary node spacing of a deformable grain.
  double contour_spacing = 0.1;
};

// One component of a mixture.
struct GrainComponentDef {
  std::string name = "grains";
  GrainShapeDef shape;
  double number_fraction = 1.0;  // relative weight; fractions are normalized over the mixture
  bool rigid = false;            // rigid (3 DOFs) or deformable (meshfree)
  std::string material = "default";
  // Its own node spacings (issue #32; 0: the builder's): the builder samples the contour at
  // spacing.contour and meshes the grain graded to spacing.interior.
  NodeSpacing spacing;
};

struct MixtureDef {
  std::vector<GrainComponentDef> components;
};

// A typical grain size of a mixture (length): the number-weighted mean of the components' mid
// sizes (disc or Fourier diameter, ellipse short axis). Sets packing clearances. Throws
// sg::Error naming `what` when the fractions sum to zero.
double mixture_grain_size(const std::vector<GrainComponentDef>& components,
                          const std::string& what);

// A generated grain, in its local frame (centroid at the origin).
struct GrainDef {
  Polygon contour;               // CCW, simple, centroid at (0, 0)
  double bounding_radius = 0.0;  // max |vertex|
  double size = 0.0;             // disc: diameter; ellipse: long axis; fourier: 2 r_mean
  int component = 0;             // index in MixtureDef::components
  bool rigid = false;
  std::string material;
};

// One contour from a shape law (CCW, centred on the origin of its polar/parametric frame);
// `size` receives the drawn size (see GrainDef::size).
Polygon sample_grain_contour(const GrainShapeDef& shape, RandomEngine& engine, double& size);

// `count` grains. Component counts follow the number fractions exactly up to rounding
// (largest-remainder rounding, so they sum to `count`); the components are then shuffled
// so that consecutive grains are not sorted by component.
std::vector<GrainDef> generate_grains(const MixtureDef& mixture, int count, std::uint64_t seed);

}  // namespace sg
