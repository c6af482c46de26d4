#include "geometry/shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace sg {

namespace {

// A contour of length `length` sampled at `spacing` must stay a sane number of points: a
// spacing far too small for the body (or a body far too large) is refused here, with the
// limit, before any memory is allocated for it.
constexpr double kMaxContourPoints = 1e6;

void verify_contour_points(double length, double spacing, const char* what) {
  SG_VERIFY(std::isfinite(length) && length / spacing <= kMaxContourPoints,
            "contour spacing " << spacing << " is too small for " << what << " of perimeter "
                               << length << " (" << length / spacing << " contour points, at most "
                               << kMaxContourPoints
                               << "): need spacing >= " << length / kMaxContourPoints);
}

}  // namespace

Polygon make_disc(const Vec2& center, double radius, double spacing) {
  return make_ellipse(center, radius, radius, 0.0, spacing);
}

Polygon make_ellipse(const Vec2& center, double a, double b, double angle, double spacing) {
  SG_VERIFY(a > 0.0 && b > 0.0, "ellipse semi-axes must be positive, got " << a << ", " << b);
  SG_VERIFY(spacing > 0.0, "contour spacing must be positive, got " << spacing);
  verify_contour_points(2.0 * std::numbers::pi * std::max(a, b), spacing, "an ellipse");
  // A fine polygon first, then uniform resampling by arc length: parametric angles are
  // not uniform in arc length for an elongated ellipse.
  const int fine =
      std::max(64, static_cast<int>(32.0 * 2.0 * std::numbers::pi * std::max(a, b) / spacing));
  Polygon dense;
  dense.reserve(static_cast<std::size_t>(fine));
  for (int k = 0; k < fine; ++k) {
    const double t = 2.0 * std::numbers::pi * k / fine;
    dense.emplace_back(a * std::cos(t), b * std::sin(t));
  }
  Polygon out = resample_by_arc_length(dense, spacing, 3);
  // Project the resampled points back onto the exact ellipse (radially in parameter space).
  const Mat2 r = rotation(angle);
  for (Vec2& v : out) {
    const double t = std::atan2(v.y() / b, v.x() / a);
    v = center + r * Vec2(a * std::cos(t), b * std::sin(t));
  }
  return out;
}

Polygon make_rectangle(const Vec2& lower_left, const Vec2& upper_right, double spacing) {
  SG_VERIFY(upper_right.x() > lower_left.x() && upper_right.y() > lower_left.y(),
            "rectangle corners must be ordered (lower-left then upper-right)");
  SG_VERIFY(spacing > 0.0, "contour spacing must be positive, got " << spacing);
  verify_contour_points(2.0 * (upper_right - lower_left).sum(), spacing, "a rectangle");
  const Vec2 corners[4] = {lower_left, Vec2(upper_right.x(), lower_left.y()), upper_right,
                           Vec2(lower_left.x(), upper_right.y())};
  Polygon out;
  for (int c = 0; c < 4; ++c) {
    const Vec2 a = corners[c], b = corners[(c + 1) % 4];
    const int n = std::max(1, static_cast<int>(std::lround((b - a).norm() / spacing)));
    for (int k = 0; k < n; ++k)
      out.push_back(a + (b - a) * (static_cast<double>(k) / n));
  }
  return out;
}

}  // namespace sg
