#pragma once
// Random grain shapes from Fourier descriptors (star-shaped contours in polar form).
//
// The radius about the grain's polar centre is a Fourier series with normalized
// amplitudes D_n (Mollon & Zhao 2012, "Fourier-Voronoi-based generation of realistic
// samples for discrete modelling of granular materials", Granular Matter 14:621-638,
// eq. 1-2; the descriptor method cited by paper 000 for its Fourier-Voronoi sample):
//
//   r(theta) = r_mean * (1 + sum_n D_n cos(n theta - phi_n)),   n = 2 .. max_mode
//
// D_0 = 1 is the size, D_1 only shifts the centre (left out), D_2 sets the elongation,
// D_3 the irregularity and D_8 the roughness; the other modes follow a power-law decay
// between these anchors (the log-log linear spectrum of Mollon & Zhao 2012 §2.2). Phases
// are random, so each grain is a different shape with the same spectrum.
//
// A polar contour with r(theta) > 0 everywhere is star-shaped about its centre, hence
// simple; the generator still checks simplicity and redraws phases when a draw fails.
#include <cstdint>
#include <vector>

#include "geometry/polygon.h"
#include "geometry/size_distribution.h"

namespace sg {

// The descriptor spectrum (dimensionless, relative to the mean radius).
struct FourierSpectrumDef {
  double elongation = 0.0;    // D_2
  double irregularity = 0.0;  // D_3
  double roughness = 0.0;     // D_8
  int max_mode = 16;          // highest mode n kept (>= 2)
  // Each amplitude is D_n (1 + s (2u - 1)), u uniform in [0, 1): a relative scatter s in
  // [0, 1) so that grains differ in their spectrum too, not only in phase. 0: exact D_n.
  double amplitude_scatter = 0.0;
};

struct FourierMode {
  int order = 2;           // n
  double amplitude = 0.0;  // D_n, relative to the mean radius
  double phase = 0.0;      // phi_n, radians
};

// D_n for n = 0 .. max_mode (index = n): D_0 = 1, D_1 = 0, D_2 = elongation, D_3 =
// irregularity, D_8 = roughness; for 3 < n < 8 log-log interpolation between (3, D_3) and
// (8, D_8); for n > 8 the same log-log slope continued. When D_3 or D_8 is zero the
// log-log line is undefined: the modes between them fall linearly in ln n, and beyond 8
// decay as D_8 (n/8)^-2.
std::vector<double> fourier_descriptor_spectrum(const FourierSpectrumDef& spectrum);

// Modes n = 2 .. max_mode with amplitudes from the spectrum (scattered) and phases
// uniform in [0, 2 pi).
std::vector<FourierMode> sample_fourier_modes(const FourierSpectrumDef& spectrum,
                                              RandomEngine& engine);

// r(theta)/r_mean of the series above.
double fourier_relative_radius(const std::vector<FourierMode>& modes, double theta);

// The CCW contour of r(theta) about `center`, vertices on the exact curve at an arc-length
// spacing close to `spacing`. Throws if r(theta) <= 0 somewhere (amplitudes too large).
// Exact area: pi r_mean^2 (1 + sum_n D_n^2 / 2) (Parseval on 1/2 integral r^2 dtheta).
Polygon make_fourier_shape(const Vec2& center, double mean_radius,
                           const std::vector<FourierMode>& modes, double spacing);

// Draws modes and builds the contour, redrawing (up to `max_attempts`) when the draw gives
// a non-positive radius or a self-intersecting polygon; throws with the spectrum if all fail.
Polygon sample_fourier_shape(const Vec2& center, double mean_radius,
                             const FourierSpectrumDef& spectrum, double spacing,
                             RandomEngine& engine, int max_attempts = 100);

}  // namespace sg
