#include "geometry/rough_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "geometry/size_distribution.h"

namespace sg {

namespace {

// Standard normal from two uniforms (Box-Muller); written out because
// std::normal_distribution differs between standard libraries.
double standard_normal(RandomEngine& engine) {
  const double u1 = 1.0 - uniform01(engine);  // (0, 1]: log is finite
  const double u2 = uniform01(engine);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace

RoughProfile make_rough_profile(const RoughSurfaceDef& def, std::uint64_t seed) {
  SG_VERIFY(def.length > 0.0, "rough surface: length must be positive, got " << def.length);
  SG_VERIFY(def.points >= 8, "rough surface: points must be >= 8, got " << def.points);
  SG_VERIFY(def.hurst > 0.0 && def.hurst < 1.0,
            "rough surface: Hurst exponent must be in (0, 1), got " << def.hurst);
  SG_VERIFY(def.rms >= 0.0, "rough surface: rms must be >= 0, got " << def.rms);
  const int n = def.points;
  // Modes up to N/2 - 1: the Nyquist mode N/2 has no sine part on the grid.
  const int k_max = def.max_mode == 0 ? n / 2 - 1 : def.max_mode;
  SG_VERIFY(def.min_mode >= 1 && def.min_mode <= k_max && k_max <= n / 2 - 1,
            "rough surface: need 1 <= min_mode <= max_mode <= points/2 - 1 = "
                << n / 2 - 1 << ", got min_mode = " << def.min_mode << ", max_mode = " << k_max);

  // cos and sin of 2 pi m / N: the phase of mode k at sample j is 2 pi (k j mod N) / N, so
  // the table gives every term exactly as at an integer argument, and y is periodic.
  std::vector<double> cos_table(static_cast<std::size_t>(n)), sin_table(cos_table.size());
  for (int m = 0; m < n; ++m) {
    const double angle = 2.0 * std::numbers::pi * m / n;
    cos_table[static_cast<std::size_t>(m)] = std::cos(angle);
    sin_table[static_cast<std::size_t>(m)] = std::sin(angle);
  }

  RandomEngine engine(seed);
  RoughProfile profile;
  profile.length = def.length;
  profile.heights.assign(static_cast<std::size_t>(n), 0.0);
  const double exponent = -(1.0 + 2.0 * def.hurst) / 2.0;  // amplitude ∝ sqrt(C(q_k))
  for (int k = def.min_mode; k <= k_max; ++k) {
    const double amplitude = std::pow(static_cast<double>(k), exponent);
    // y_k(x) = a cos(q x) - b sin(q x).
    double a = 0.0, b = 0.0;
    if (def.sampling == RoughSpectrumSampling::random_phase) {
      const double phase = 2.0 * std::numbers::pi * uniform01(engine);
      a = amplitude * std::cos(phase);
      b = amplitude * std::sin(phase);
    } else {
      // Var(a) = Var(b) = amplitude^2 / 2: same expected power as the random-phase mode.
      a = amplitude * std::sqrt(0.5) * standard_normal(engine);
      b = amplitude * std::sqrt(0.5) * standard_normal(engine);
    }
    for (int j = 0; j < n; ++j) {
      const auto m = static_cast<std::size_t>((static_cast<std::int64_t>(k) * j) % n);
      profile.heights[static_cast<std::size_t>(j)] += a * cos_table[m] - b * sin_table[m];
    }
  }

  // Zero mean (exact up to rounding already: every mode sums to zero over the grid), then
  // scale to the requested RMS.
  double mean = 0.0;
  for (double y : profile.heights)
    mean += y;
  mean /= n;
  double sum_sq = 0.0;
  for (double& y : profile.heights) {
    y -= mean;
    sum_sq += y * y;
  }
  const double rms = std::sqrt(sum_sq / n);
  SG_VERIFY(rms > 0.0 || def.rms == 0.0, "rough surface: the synthesized profile is flat");
  const double scale = rms > 0.0 ? def.rms / rms : 0.0;
  for (double& y : profile.heights)
    y *= scale;
  return profile;
}

std::vector<double> periodogram(const std::vector<double>& y) {
  const std::size_t n = y.size();
  std::vector<double> c(n), s(n);
  for (std::size_t m = 0; m < n; ++m) {
    c[m] = std::cos(2.0 * std::numbers::pi * static_cast<double>(m) / static_cast<double>(n));
    s[m] = std::sin(2.0 * std::numbers::pi * static_cast<double>(m) / static_cast<double>(n));
  }
  std::vector<double> p(n / 2 + 1);
  for (std::size_t k = 0; k <= n / 2 && n > 0; ++k) {
    double re = 0.0, im = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      re += y[j] * c[(k * j) % n];
      im -= y[j] * s[(k * j) % n];
    }
    p[k] = re * re + im * im;
  }
  return p;
}

SpectralSlopeFit fit_spectral_slope(const std::vector<double>& p, int k0, int k1) {
  SG_VERIFY(k0 >= 1 && k0 < k1 && static_cast<std::size_t>(k1) < p.size(),
            "spectral slope: modes [" << k0 << ", " << k1 << "] not within 1 .. " << p.size() - 1
                                      << " with at least two modes");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = k1 - k0 + 1;
  for (int k = k0; k <= k1; ++k) {
    const double power = p[static_cast<std::size_t>(k)];
    SG_VERIFY(power > 0.0, "spectral slope: mode " << k << " carries no power (" << power << ")");
    const double x = std::log(static_cast<double>(k)), v = std::log(power);
    sx += x;
    sy += v;
    sxx += x * x;
    sxy += x * v;
  }
  const double spread = sxx - sx * sx / n;  // sum (x - mean)^2
  SpectralSlopeFit fit;
  fit.slope = (sxy - sx * sy / n) / spread;
  fit.standard_error_if_exponential = std::sqrt(std::numbers::pi * std::numbers::pi / 6.0 / spread);
  fit.min_mode = k0;
  fit.max_mode = k1;
  return fit;
}

FirstBodyStrip make_first_body_strip(const RoughProfile& profile, FirstBodySide side, double mean_y,
                                     double thickness) {
  const int n = static_cast<int>(profile.heights.size());
  SG_VERIFY(n >= 2 && profile.length > 0.0, "first body strip: empty rough profile");
  const auto [lowest, highest] =
      std::minmax_element(profile.heights.begin(), profile.heights.end());
  const double depth = side == FirstBodySide::bottom ? -*lowest : *highest;
  SG_VERIFY(thickness > depth,
            "first body strip: thickness "
                << thickness << " must exceed the profile's "
                << (side == FirstBodySide::bottom ? "deepest valley " : "highest peak ") << depth);
  const double dx = profile.spacing();
  const double length = profile.length;
  auto surface = [&](int j) {  // j = 0 .. n, j = n is the periodic image of j = 0
    return Vec2(j * dx, mean_y + profile.heights[static_cast<std::size_t>(j % n)]);
  };
  // Points strictly between a and b at about the profile spacing.
  auto subdivide = [&](Polygon& out, const Vec2& a, const Vec2& b) {
    const int pieces = std::max(1, static_cast<int>(std::lround((b - a).norm() / dx)));
    for (int i = 1; i < pieces; ++i)
      out.push_back(a + (b - a) * (static_cast<double>(i) / pieces));
  };

  FirstBodyStrip strip;
  Polygon& c = strip.contour;
  if (side == FirstBodySide::bottom) {
    // CCW with the material below the surface: back left-to-right, up the x = L end, then
    // the surface from x = L back to x = 0, down the x = 0 end.
    const double back = mean_y - thickness;
    const Vec2 back_left(0.0, back), back_right(length, back);
    c.push_back(back_left);
    subdivide(c, back_left, back_right);
    c.push_back(back_right);
    subdivide(c, back_right, surface(n));
    strip.surface_begin = static_cast<int>(c.size());
    for (int j = n; j >= 0; --j)
      c.push_back(surface(j));
    strip.surface_count = n + 1;
    subdivide(c, surface(0), back_left);
  } else {
    // CCW with the material above: the surface from x = 0 to x = L, up the x = L end, the
    // back right-to-left, down the x = 0 end.
    const double back = mean_y + thickness;
    const Vec2 back_left(0.0, back), back_right(length, back);
    strip.surface_begin = 0;
    for (int j = 0; j <= n; ++j)
      c.push_back(surface(j));
    strip.surface_count = n + 1;
    subdivide(c, surface(n), back_right);
    c.push_back(back_right);
    subdivide(c, back_right, back_left);
    c.push_back(back_left);
    subdivide(c, back_left, surface(0));
  }
  return strip;
}

}  // namespace sg
