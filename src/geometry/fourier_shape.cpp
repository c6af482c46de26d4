#include "geometry/fourier_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace sg {

namespace {

void verify_spectrum(const FourierSpectrumDef& s) {
  SG_VERIFY(s.max_mode >= 2 && s.max_mode <= 4096,
            "Fourier spectrum: max_mode must be in [2, 4096], got " << s.max_mode);
  SG_VERIFY(s.elongation >= 0.0 && s.irregularity >= 0.0 && s.roughness >= 0.0,
            "Fourier spectrum: descriptors must be >= 0, got D2 = "
                << s.elongation << ", D3 = " << s.irregularity << ", D8 = " << s.roughness);
  SG_VERIFY(s.amplitude_scatter >= 0.0 && s.amplitude_scatter < 1.0,
            "Fourier spectrum: amplitude_scatter must be in [0, 1), got " << s.amplitude_scatter);
}

}  // namespace

std::vector<double> fourier_descriptor_spectrum(const FourierSpectrumDef& s) {
  verify_spectrum(s);
  std::vector<double> d(static_cast<std::size_t>(s.max_mode) + 1, 0.0);
  d[0] = 1.0;
  d[2] = s.elongation;
  const double d3 = s.irregularity, d8 = s.roughness;
  const bool log_line = d3 > 0.0 && d8 > 0.0;
  // Slope of log D_n against log n through the anchors (3, D3) and (8, D8).
  const double slope = log_line ? std::log(d8 / d3) / std::log(8.0 / 3.0) : -2.0;
  for (int n = 3; n <= s.max_mode; ++n) {
    double value = 0.0;
    if (n <= 8) {
      const double t = std::log(n / 3.0) / std::log(8.0 / 3.0);  // 0 at n = 3, 1 at n = 8
      value = log_line ? d3 * std::pow(d8 / d3, t) : d3 + (d8 - d3) * t;
    } else {
      value = d8 * std::pow(n / 8.0, slope);
    }
    d[static_cast<std::size_t>(n)] = value;
  }
  return d;
}

std::vector<FourierMode> sample_fourier_modes(const FourierSpectrumDef& s, RandomEngine& engine) {
  const std::vector<double> d = fourier_descriptor_spectrum(s);
  std::vector<FourierMode> modes;
  modes.reserve(d.size());
  for (int n = 2; n <= s.max_mode; ++n) {
    // Two draws per mode whatever the amplitude, so the stream does not depend on values.
    const double scatter = 1.0 + s.amplitude_scatter * (2.0 * uniform01(engine) - 1.0);
    const double phase = 2.0 * std::numbers::pi * uniform01(engine);
    const double amplitude = d[static_cast<std::size_t>(n)] * scatter;
    if (amplitude > 0.0) modes.push_back({n, amplitude, phase});
  }
  return modes;
}

double fourier_relative_radius(const std::vector<FourierMode>& modes, double theta) {
  double r = 1.0;
  for (const FourierMode& m : modes)
    r += m.amplitude * std::cos(m.order * theta - m.phase);
  return r;
}

Polygon make_fourier_shape(const Vec2& center, double mean_radius,
                           const std::vector<FourierMode>& modes, double spacing) {
  SG_VERIFY(mean_radius > 0.0, "Fourier shape: mean radius must be positive, got " << mean_radius);
  SG_VERIFY(spacing > 0.0, "Fourier shape: contour spacing must be positive, got " << spacing);
  int highest = 1;
  for (const FourierMode& m : modes)
    highest = std::max(highest, m.order);
  // Dense polar polygon first (resolving the highest mode with >= 16 points per period and
  // the requested spacing 32 times over), then uniform resampling by arc length, then each
  // resampled point moved radially back onto the exact curve.
  const int dense_count = std::max(
      {256, 16 * highest, static_cast<int>(32.0 * 2.0 * std::numbers::pi * mean_radius / spacing)});
  Polygon dense;
  dense.reserve(static_cast<std::size_t>(dense_count));
  double min_relative = 1.0;
  for (int k = 0; k < dense_count; ++k) {
    const double theta = 2.0 * std::numbers::pi * k / dense_count;
    const double r = fourier_relative_radius(modes, theta);
    min_relative = std::min(min_relative, r);
    dense.emplace_back(mean_radius * r * std::cos(theta), mean_radius * r * std::sin(theta));
  }
  SG_VERIFY(min_relative > 0.0, "Fourier shape: radius becomes non-positive (min r/r_mean = "
                                    << min_relative << "): amplitudes too large");
  Polygon out = resample_by_arc_length(dense, spacing, 8);
  for (Vec2& v : out) {
    const double theta = std::atan2(v.y(), v.x());
    const double r = mean_radius * fourier_relative_radius(modes, theta);
    v = center + r * Vec2(std::cos(theta), std::sin(theta));
  }
  return out;
}

Polygon sample_fourier_shape(const Vec2& center, double mean_radius,
                             const FourierSpectrumDef& spectrum, double spacing,
                             RandomEngine& engine, int max_attempts) {
  double worst = 0.0;
  for (int attempt = 0; attempt < max_attempts; ++attempt) {
    const std::vector<FourierMode> modes = sample_fourier_modes(spectrum, engine);
    // A margin of 5 % of the mean radius: thinner necks would need more nodes than the
    // contour spacing gives, and are not grains anyone asks for.
    double min_relative = 1.0;
    const int probe = 64 * spectrum.max_mode;
    for (int k = 0; k < probe; ++k)
      min_relative = std::min(min_relative,
                              fourier_relative_radius(modes, 2.0 * std::numbers::pi * k / probe));
    worst = min_relative;
    if (min_relative < 0.05) continue;
    Polygon contour = make_fourier_shape(center, mean_radius, modes, spacing);
    if (is_counter_clockwise(contour) && !is_self_intersecting(contour)) return contour;
  }
  SG_THROW("Fourier shape: no valid shape in "
           << max_attempts << " draws (D2 = " << spectrum.elongation
           << ", D3 = " << spectrum.irregularity << ", D8 = " << spectrum.roughness
           << ", last min r/r_mean = " << worst << "): reduce the descriptors");
}

}  // namespace sg
