#include "geometry/surface_profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace sg {

namespace {

std::vector<Vec2> sampled_sines(const std::vector<SineMode>& modes, double x_begin, double period,
                                int n, const std::string& what) {
  for (const SineMode& m : modes) {
    SG_VERIFY(m.wavelength > 0.0,
              what << ": profile mode wavelength must be positive, got " << m.wavelength);
    const double cycles = period / m.wavelength;
    SG_VERIFY(std::abs(cycles - std::round(cycles)) < 1e-9 * std::max(1.0, cycles),
              what << ": profile mode wavelength " << m.wavelength << " does not divide the period "
                   << period << " (the surface would not be periodic)");
  }
  std::vector<Vec2> points;
  for (int j = 0; j < n; ++j) {
    const double s = static_cast<double>(j) * period / n;
    points.emplace_back(x_begin + s, sum_of_sines(modes, s));
  }
  return points;
}

// The given points, checked, with the seam's duplicate dropped and long segments subdivided.
std::vector<Vec2> listed_points(const SurfaceProfileDef& def, double x_begin, double period,
                                double spacing, const std::string& what) {
  const std::string where = what + " (" + def.source + ")";
  std::vector<Vec2> p = def.points;
  SG_VERIFY(p.size() >= 2, where << ": a profile needs at least 2 points, got " << p.size());
  const double tolerance = 1e-9 * period;
  const double x_end = x_begin + period;
  for (std::size_t i = 0; i < p.size(); ++i) {
    SG_VERIFY(p[i].x() >= x_begin - tolerance && p[i].x() <= x_end + tolerance,
              where << ": point " << i + 1 << " at x = " << p[i].x() << " is outside the period ["
                    << x_begin << ", " << x_end << "]");
    SG_VERIFY(i == 0 || p[i].x() > p[i - 1].x(), where << ": point " << i + 1
                                                       << ": x must increase strictly, got "
                                                       << p[i].x() << " after " << p[i - 1].x());
  }
  if (p.back().x() >= x_end - tolerance) {
    // The image of the first point: it must close the profile without a step.
    SG_VERIFY(
        std::abs(p.back().y() - p.front().y()) <= tolerance && p.front().x() <= x_begin + tolerance,
        where << ": the last point (x = " << p.back().x() << ", y = " << p.back().y()
              << ") is the first one's periodic image, but (x = " << p.front().x()
              << ", y = " << p.front().y() << ") does not match it: a step at the seam");
    p.pop_back();
  }
  SG_VERIFY(p.size() >= 2, where << ": a profile needs at least 2 points over one period");
  // Subdivide every segment, the seam's (last -> first + L) included.
  std::vector<Vec2> out, wrapped;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i];
    const Vec2 b = i + 1 < p.size() ? p[i + 1] : Vec2(p[0].x() + period, p[0].y());
    out.push_back(a);
    const int pieces = static_cast<int>(std::ceil((b - a).norm() / (1.5 * spacing)));
    for (int k = 1; k < pieces; ++k) {
      const Vec2 q = a + (b - a) * (static_cast<double>(k) / pieces);
      if (q.x() < x_end)
        out.push_back(q);
      else
        wrapped.emplace_back(q.x() - period, q.y());  // seam points past the end: to the front
    }
  }
  wrapped.insert(wrapped.end(), out.begin(), out.end());
  return wrapped;
}

}  // namespace

double sum_of_sines(const std::vector<SineMode>& modes, double x) {
  double y = 0.0;
  for (const SineMode& m : modes)
    y += m.amplitude * std::sin(2.0 * std::numbers::pi * x / m.wavelength + m.phase);
  return y;
}

std::vector<Vec2> sample_profile(const SurfaceProfileDef& def, double x_begin, double period,
                                 double spacing, const std::string& what) {
  SG_VERIFY(period > 0.0 && spacing > 0.0, what << ": profile period and spacing must be positive");
  const int n = std::max(8, static_cast<int>(std::lround(period / spacing)));
  switch (def.kind) {
    case ProfileKind::sines:
      return sampled_sines(def.modes, x_begin, period, n, what);
    case ProfileKind::points:
      return listed_points(def, x_begin, period, spacing, what);
    case ProfileKind::self_affine:
      break;
  }
  RoughSurfaceDef rough;
  rough.length = period;
  rough.points = n;
  rough.hurst = def.hurst;
  rough.rms = def.rms;
  const RoughProfile profile = make_rough_profile(rough, def.seed);
  std::vector<Vec2> points;
  for (std::size_t j = 0; j < profile.heights.size(); ++j)
    points.emplace_back(x_begin + static_cast<double>(j) * profile.spacing(), profile.heights[j]);
  return points;
}

}  // namespace sg
