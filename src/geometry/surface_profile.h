#pragma once
// The contact surface of a periodic strip (a first body), over one period L: the random
// self-affine generator (rough_surface.h), a sum of sines, or a list of measured or
// published points. A profile gives heights about the strip's reference line (the mean
// surface line for the generated ones; the points' own y for a list).
//
//   sines:       y(x) = sum_k A_k sin(2 pi (x - x_begin) / lambda_k + phi_k), each
//                wavelength lambda_k dividing L (so that y is periodic), sampled at
//                x_j = x_begin + j L / N, N = max(8, round(L / spacing));
//   points:      (x, y) over one period, x strictly increasing in [x_begin, x_begin + L]; a
//                last point at x_begin + L must repeat the first one's height (it is the
//                first point's periodic image, dropped); the last point joins the first
//                shifted by L with a straight segment. Segments longer than 1.5 spacing are
//                subdivided (points on the straight segment, the seam's too), so that a
//                deformable strip gets node columns at about the node spacing;
//   self_affine: make_rough_profile with N samples as above.
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/rough_surface.h"
#include "geometry/vec2.h"

namespace sg {

struct SineMode {
  double amplitude = 0.0;   // length
  double wavelength = 1.0;  // length; must divide the period
  double phase = 0.0;       // rad
};

enum class ProfileKind { self_affine, sines, points };

struct SurfaceProfileDef {
  ProfileKind kind = ProfileKind::self_affine;
  double rms = 0.3, hurst = 0.8;  // self_affine
  std::uint64_t seed = 1;         // self_affine
  std::vector<SineMode> modes;    // sines
  std::vector<Vec2> points;       // points: (x, y) over one period
  std::string source;             // where the points came from (for errors): "file.csv"
};

// y(x) of a sum of sines (x measured from the start of the period).
double sum_of_sines(const std::vector<SineMode>& modes, double x);

// One period of the profile: points (x, y), x strictly increasing within [x_begin,
// x_begin + L); the last point joins the first shifted by (L, 0). Throws sg::Error naming
// `what` (e.g. "strip 'top'") for a wavelength that does not divide L, points that are not
// increasing in x or leave the period, or a step at the seam.
std::vector<Vec2> sample_profile(const SurfaceProfileDef& def, double x_begin, double period,
                                 double spacing, const std::string& what);

}  // namespace sg
