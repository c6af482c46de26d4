#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "geometry/polygon.h"
#include "geometry/shapes.h"

namespace sg {
namespace {

TEST(Polygon, RectangleAreaCentroidMomentAreExact) {
  // A 2 x 1 rectangle at (1, 2): area 2, centroid (2, 2.5), J = b h (b^2 + h^2) / 12.
  const Polygon r = make_rectangle(Vec2(1, 2), Vec2(3, 3), 0.25);
  EXPECT_DOUBLE_EQ(signed_area(r), 2.0);
  EXPECT_NEAR((centroid(r) - Vec2(2, 2.5)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(polar_second_moment(r), 2.0 * 1.0 * (4.0 + 1.0) / 12.0, 1e-13);
  EXPECT_DOUBLE_EQ(perimeter(r), 6.0);
  EXPECT_TRUE(is_counter_clockwise(r));
  EXPECT_FALSE(is_self_intersecting(r));
}

TEST(Polygon, ReversedContourIsClockwise) {
  Polygon r = make_rectangle(Vec2(0, 0), Vec2(1, 1), 0.5);
  std::reverse(r.begin(), r.end());
  EXPECT_LT(signed_area(r), 0.0);
  EXPECT_FALSE(is_counter_clockwise(r));
}

TEST(Polygon, DiscApproachesCircleQuadratically) {
  // Inscribed regular n-gon: area = n/2 R^2 sin(2 pi / n), error O(h^2).
  const double radius = 1.0;
  const Polygon coarse = make_disc(Vec2(0, 0), radius, 0.2);
  const Polygon fine = make_disc(Vec2(0, 0), radius, 0.1);
  const double e_coarse = std::numbers::pi - signed_area(coarse);
  const double e_fine = std::numbers::pi - signed_area(fine);
  EXPECT_GT(e_coarse, 0.0);
  EXPECT_NEAR(e_coarse / e_fine, 4.0, 0.3);
  // Vertices lie on the circle.
  for (const Vec2& v : fine)
    EXPECT_NEAR(v.norm(), radius, 1e-14);
  EXPECT_NEAR(polar_second_moment(fine), std::numbers::pi / 2.0, 2e-2);
}

TEST(Polygon, EllipseVerticesOnCurveAndEvenlySpaced) {
  const double a = 2.0, b = 0.5, angle = 0.3;
  const Polygon e = make_ellipse(Vec2(1, -1), a, b, angle, 0.1);
  const Mat2 back = rotation(-angle);
  double min_edge = 1e9, max_edge = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const Vec2 local = back * (e[i] - Vec2(1, -1));
    EXPECT_NEAR(std::pow(local.x() / a, 2) + std::pow(local.y() / b, 2), 1.0, 1e-12);
    const double edge = (e[(i + 1) % e.size()] - e[i]).norm();
    min_edge = std::min(min_edge, edge);
    max_edge = std::max(max_edge, edge);
  }
  EXPECT_GT(min_edge, 0.8 * max_edge);
  EXPECT_NEAR(signed_area(e), std::numbers::pi * a * b, 0.01 * std::numbers::pi * a * b);
}

TEST(Polygon, ContainsAndDistance) {
  const Polygon r = make_rectangle(Vec2(0, 0), Vec2(2, 1), 0.5);
  EXPECT_TRUE(contains(r, Vec2(1.0, 0.5)));
  EXPECT_FALSE(contains(r, Vec2(2.5, 0.5)));
  EXPECT_FALSE(contains(r, Vec2(1.0, -0.1)));
  EXPECT_DOUBLE_EQ(distance_to_contour(r, Vec2(1.0, 0.4)), 0.4);
  EXPECT_DOUBLE_EQ(distance_to_contour(r, Vec2(3.0, 2.0)), std::sqrt(2.0));
}

TEST(Polygon, SelfIntersectionDetected) {
  const Polygon bow_tie = {Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)};
  EXPECT_TRUE(is_self_intersecting(bow_tie));
  const Polygon square = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  EXPECT_FALSE(is_self_intersecting(square));
}

TEST(Polygon, SegmentProjectionClampsToEnds) {
  const auto p = project_on_segment(Vec2(2, 1), Vec2(0, 0), Vec2(1, 0));
  EXPECT_DOUBLE_EQ(p.t, 1.0);
  EXPECT_DOUBLE_EQ(p.distance, std::sqrt(2.0));
  const auto q = project_on_segment(Vec2(0.25, -3), Vec2(0, 0), Vec2(1, 0));
  EXPECT_DOUBLE_EQ(q.t, 0.25);
  EXPECT_DOUBLE_EQ(q.distance, 3.0);
}

TEST(Shapes, BadInputIsRejected) {
  EXPECT_THROW(make_disc(Vec2(0, 0), -1.0, 0.1), Error);
  EXPECT_THROW(make_ellipse(Vec2(0, 0), 1.0, 1.0, 0.0, 0.0), Error);
}

}  // namespace
}  // namespace sg
