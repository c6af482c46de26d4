#pragma once
// Self-affine rough profiles for first bodies, and the strip polygon built on one.
//
// Spectral synthesis (e.g. Persson et al. 2005, J. Phys.: Condens. Matter 17 R1, §2;
// Jacobs, Junge & Pastewka 2017, Surf. Topogr. 5 013001, §2): a 1D self-affine profile of
// Hurst exponent H has a power spectral density C(q) ∝ q^-(1 + 2H). The profile is a sum
// of cosines over the wavenumbers q_k = 2 pi k / L of the periodic cell,
//
//   y(x) = sum_{k = k_min}^{k_max} A_k cos(q_k x + phi_k),   A_k ∝ k^-(1 + 2H)/2,
//
// so it is exactly periodic on [0, L); it is then shifted to zero mean and scaled to the
// requested RMS (paper 001 §2: RMS 1 over L = 100). Evaluated directly, without an FFT
// (none is among the project's dependencies): with a table of cos/sin(2 pi m / N) the
// N x modes sum costs one multiply-add per term and is exact at the sample points.
#include <cstdint>
#include <vector>

#include "geometry/polygon.h"

namespace sg {

enum class RoughSpectrumSampling {
  // |A_k| exactly on the power law, phases random: the periodogram is the power law itself
  // (the "random phase" surfaces of Persson 2005).
  random_phase,
  // A_k cos + B_k sin with A_k, B_k Gaussian of the power-law variance: the periodogram
  // scatters around the power law (exponential distribution per mode), as a measured
  // surface would.
  gaussian,
};

struct RoughSurfaceDef {
  double length = 100.0;  // L, period (length units); paper 001: 100
  int points = 1024;      // N samples at x_j = j L / N, j = 0 .. N-1 (N >= 8)
  double hurst = 0.8;     // H in (0, 1); not given by paper 001 (0.8 is a common value)
  double rms = 1.0;       // root mean square height (length); paper 001: 1
  int min_mode = 1;       // k_min: longest wavelength L / k_min
  int max_mode = 0;       // k_max: shortest wavelength L / k_max; 0 means N/2 - 1
  RoughSpectrumSampling sampling = RoughSpectrumSampling::random_phase;
};

// Heights at x_j = j * length / heights.size(); y(length) = y(0) by periodicity.
struct RoughProfile {
  double length = 0.0;
  std::vector<double> heights;
  double spacing() const { return length / static_cast<double>(heights.size()); }
};

RoughProfile make_rough_profile(const RoughSurfaceDef& def, std::uint64_t seed);

// --- Measuring a profile (tests and `softgrain generate`'s report).

// Periodogram P_k = |Y_k|^2, Y_k = sum_j y_j exp(-2 pi i k j / N), k = 0 .. N/2, of N evenly
// spaced samples of one period. A direct DFT (O(N^2), a cos/sin table), deliberately not the
// synthesis code path of make_rough_profile, so that it can check it. P_k is proportional to
// the PSD C(q_k) at q_k = 2 pi k / L.
std::vector<double> periodogram(const std::vector<double>& heights);

// Least-squares fit of ln P_k against ln k over the modes [min_mode, max_mode] (ln q_k differs
// from ln k by a constant: same slope). A self-affine profile has C(q) ∝ q^-(1 + 2H).
struct SpectralSlopeFit {
  double slope = 0.0;
  // The slope's standard error if ln P_k scattered like the log of an exponential variable
  // (variance pi^2 / 6 per mode: the periodogram of a Gaussian process, as for
  // RoughSpectrumSampling::gaussian); random-phase profiles lie on the law exactly.
  double standard_error_if_exponential = 0.0;
  int min_mode = 0, max_mode = 0;
  double hurst() const { return -(1.0 + slope) / 2.0; }  // H from slope = -(1 + 2H)
};

// Throws sg::Error unless 1 <= min_mode < max_mode < power.size() and every P_k in the range
// is positive.
SpectralSlopeFit fit_spectral_slope(const std::vector<double>& power, int min_mode, int max_mode);

enum class FirstBodySide {
  bottom,  // body below the gap, rough surface facing +y
  top,     // body above the gap, rough surface facing -y
};

// A first body as a closed CCW polygon: the rough surface at y = mean_y + h(x) for x in
// [0, L] (the vertex at x = L repeats h(0): the two ends meet across the periodic
// boundary), closed by two vertical ends at x = 0 and x = L and a flat back side at
// mean_y -/+ thickness. Ends and back are subdivided at the profile spacing. The vertical
// ends are periodic seams, not contact surfaces.
struct FirstBodyStrip {
  Polygon contour;
  // contour[surface_begin .. surface_begin + surface_count) is the rough surface, n + 1
  // vertices, in contour order: x = L .. 0 for the bottom body, x = 0 .. L for the top one.
  int surface_begin = 0;
  int surface_count = 0;
};

// thickness must exceed the deepest valley (bottom) or highest peak (top) of the profile.
FirstBodyStrip make_first_body_strip(const RoughProfile& profile, FirstBodySide side, double mean_y,
                                     double thickness);

}  // namespace sg
