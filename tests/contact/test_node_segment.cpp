// Narrow phase (node_segment.h): projections, signed gaps, corners, slip, tributary lengths.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "contact/node_segment.h"
#include "geometry/polygon.h"
#include "geometry/shapes.h"

namespace sg {
namespace {

// Unit square, counter-clockwise: segments 0 bottom, 1 right, 2 top (1,1)->(0,1), 3 left.
const std::vector<Vec2> kSquare = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
// L-shape, counter-clockwise, with a concave (reflex) vertex at (1, 1) = point 3:
// segments 2: (2,1)->(1,1) normal +y, 3: (1,1)->(1,2) normal +x.
const std::vector<Vec2> kEll = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1),
                                Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)};

// Round-off of a projection on unit-size contours: a few ulps of 1.
constexpr double kTol = 1e-14;

TEST(NodeSegment, ProjectionOnAnEdgeAndSignOfTheGap) {
  const ContourView square{kSquare};
  const NodeProjection outside = project_on_contour(Vec2(0.5, 1.2), square);
  EXPECT_EQ(outside.segment, 2);
  EXPECT_NEAR(outside.t, 0.5, kTol);
  EXPECT_NEAR(outside.gap, 0.2, kTol);  // open: positive
  EXPECT_NEAR((outside.normal - Vec2(0, 1)).norm(), 0.0, kTol);
  EXPECT_NEAR((outside.tangent - Vec2(-1, 0)).norm(), 0.0, kTol);  // direction of travel

  const NodeProjection inside = project_on_contour(Vec2(0.3, 0.9), square);
  EXPECT_EQ(inside.segment, 2);
  EXPECT_NEAR(inside.gap, -0.1, kTol);  // penetration: negative
  EXPECT_NEAR((inside.point - Vec2(0.3, 1.0)).norm(), 0.0, kTol);
  EXPECT_NEAR((inside.normal - Vec2(0, 1)).norm(), 0.0, kTol);
}

TEST(NodeSegment, ConvexCornerUsesTheDirectionFromTheVertex) {
  const ContourView square{kSquare};
  const NodeProjection p = project_on_contour(Vec2(1.1, 1.2), square);
  EXPECT_NEAR((p.point - Vec2(1, 1)).norm(), 0.0, kTol);
  EXPECT_NEAR(p.gap, std::sqrt(0.05), kTol);
  EXPECT_NEAR((p.normal - Vec2(0.1, 0.2) / std::sqrt(0.05)).norm(), 0.0, kTol);
  EXPECT_EQ(p.segment, 1);  // vertex shared by segments 1 (t = 1) and 2 (t = 0): lower wins
  EXPECT_EQ(p.t, 1.0);
}

TEST(NodeSegment, ConcaveCornerChoosesTheCloserSegmentAndTiesGoLow) {
  const ContourView ell{kEll};
  const NodeProjection near_floor = project_on_contour(Vec2(1.3, 1.1), ell);
  EXPECT_EQ(near_floor.segment, 2);
  EXPECT_NEAR(near_floor.gap, 0.1, kTol);
  EXPECT_NEAR((near_floor.normal - Vec2(0, 1)).norm(), 0.0, kTol);

  const NodeProjection near_wall = project_on_contour(Vec2(1.1, 1.3), ell);
  EXPECT_EQ(near_wall.segment, 3);
  EXPECT_NEAR(near_wall.gap, 0.1, kTol);
  EXPECT_NEAR((near_wall.normal - Vec2(1, 0)).norm(), 0.0, kTol);

  // On the bisector both segments are at 0.25: the lower index, whatever the candidate order.
  const int forward[] = {2, 3}, backward[] = {3, 2};
  const NodeProjection tie_a = project_on_contour(Vec2(1.25, 1.25), ell, forward);
  const NodeProjection tie_b = project_on_contour(Vec2(1.25, 1.25), ell, backward);
  EXPECT_EQ(tie_a.segment, 2);
  EXPECT_EQ(tie_b.segment, 2);
  EXPECT_NEAR(tie_a.gap, 0.25, kTol);

  // Penetrating behind the reflex vertex, both projections clamp to it: the gap is minus the
  // distance to the vertex and the normal points outward, from the node to the vertex.
  const NodeProjection behind = project_on_contour(Vec2(0.9, 0.8), ell);
  EXPECT_NEAR((behind.point - Vec2(1, 1)).norm(), 0.0, kTol);
  EXPECT_NEAR(behind.gap, -std::sqrt(0.05), kTol);
  EXPECT_NEAR((behind.normal - Vec2(0.1, 0.2) / std::sqrt(0.05)).norm(), 0.0, kTol);
}

// The signed gap is the signed distance to the contour: 1-Lipschitz in the node position.
// Along a path sampled every h, |gap(x + h) - gap(x)| <= h (+ round-off) everywhere, in
// particular where the closest feature switches from an edge to a vertex or to another
// edge; a jump of the gap at a corner would break the bound by orders of magnitude.
void expect_gap_continuous_along(const ContourView& contour, const Vec2& from, const Vec2& to,
                                 double expected_min_gap, double expected_max_gap) {
  const int steps = 4000;
  const double h = (to - from).norm() / steps;
  double previous = project_on_contour(from, contour).gap;
  double lowest = previous, highest = previous;
  for (int i = 1; i <= steps; ++i) {
    const Vec2 x = from + (to - from) * (static_cast<double>(i) / steps);
    const double gap = project_on_contour(x, contour).gap;
    ASSERT_LE(std::abs(gap - previous), h + 1e-13) << "at " << x.transpose();
    lowest = std::min(lowest, gap);
    highest = std::max(highest, gap);
    previous = gap;
  }
  EXPECT_NEAR(lowest, expected_min_gap, h);
  EXPECT_NEAR(highest, expected_max_gap, h);
}

TEST(NodeSegment, GapIsContinuousAsANodeSlidesOverVertices) {
  const ContourView square{kSquare};
  // Outside, over the convex vertex (1,1): gap 0.05 along the top, then the distance to the
  // vertex, up to hypot(0.5, 0.05) where the path ends at (1.5, 1.05).
  expect_gap_continuous_along(square, Vec2(0.5, 1.05), Vec2(1.5, 1.05), 0.05,
                              std::hypot(0.5, 0.05));
  // Penetrating, across the bisector of the convex vertex (the closest edge switches from
  // the top to the right one at (0.725, 0.725), 0.275 deep).
  expect_gap_continuous_along(square, Vec2(0.5, 0.95), Vec2(0.95, 0.5), -0.275, -0.05);
  const ContourView ell{kEll};
  // Outside in the concave corner, across the bisector: gap 0.1 on both sides.
  expect_gap_continuous_along(ell, Vec2(1.6, 1.1), Vec2(1.1, 1.6), 0.1, 0.35);
  // Through the reflex vertex from outside to inside.
  expect_gap_continuous_along(ell, Vec2(1.2, 1.2), Vec2(0.8, 0.8), -0.2 * std::sqrt(2.0), 0.2);
}

TEST(NodeSegment, NormalTurnsContinuouslyAroundAConvexVertex) {
  const ContourView square{kSquare};
  // Node on a circle of radius 0.1 around (1,1), from the top side to the right side:
  // the normal is the radial direction, the gap constant.
  for (int i = 0; i <= 90; ++i) {
    const double angle = std::numbers::pi / 2.0 * (1.0 - i / 90.0);
    const Vec2 radial(std::cos(angle), std::sin(angle));
    const NodeProjection p = project_on_contour(Vec2(1, 1) + 0.1 * radial, square);
    EXPECT_NEAR(p.gap, 0.1, kTol);
    EXPECT_NEAR((p.normal - radial).norm(), 0.0, 1e-13);
  }
}

TEST(NodeSegment, PeriodicStripUsesItsClosingSegment) {
  // Top surface of a lower first body, material below: it runs from right to left, and the
  // closing segment joins (0.25, 0) to points[0] + (-1, 0) = (0, 0). Period 1.
  const std::vector<Vec2> strip = {Vec2(1, 0), Vec2(0.75, 0), Vec2(0.5, 0), Vec2(0.25, 0)};
  const ContourView view{strip, true, Vec2(-1, 0)};
  const NodeProjection p = project_on_contour(Vec2(0.1, -0.02), view);
  EXPECT_EQ(p.segment, 3);
  EXPECT_NEAR(p.gap, -0.02, kTol);
  EXPECT_NEAR((p.normal - Vec2(0, 1)).norm(), 0.0, kTol);
  std::vector<double> lengths(strip.size());
  tributary_lengths(view, lengths);
  for (const double l : lengths)
    EXPECT_NEAR(l, 0.25, kTol);
}

TEST(NodeSegment, TheDistanceAloneIsTheProjectionsToTheBit) {
  // contour_segment_distance stands for project_on_contour_segment's distance where a search
  // compares candidates (ContactSystem::project_group): any difference in the last bit could
  // pick another segment. Nodes all around the segments (interiors and both vertices) of a zigzag
  // whose coordinates change sign (where a + 1 (b - a) can round off b: the vertex case must use
  // the vertex itself), of a closing segment with a shift, and of a segment of zero length.
  std::vector<Vec2> zigzag;
  for (int k = 0; k < 40; ++k)
    zigzag.emplace_back(0.1 * std::sin(1.3 * k) * (k + 1) / 7.0, 0.13 * std::cos(2.1 * k));
  const ContourView closed{zigzag, true};
  const std::vector<Vec2> strip = {Vec2(1, 0), Vec2(0.75, 0.01), Vec2(0.5, 0), Vec2(0.25, -0.02)};
  const ContourView shifted{strip, true, Vec2(-1, 0)};
  const std::vector<Vec2> degenerate = {Vec2(0.2, 0.2), Vec2(0.2, 0.2), Vec2(0.7, 0.1)};
  const ContourView with_a_point{degenerate, false};
  int vertices = 0, interiors = 0, rounded_ends = 0;
  for (const ContourView* view : {&closed, &shifted, &with_a_point})
    for (int segment = 0; segment < view->segment_count(); ++segment) {
      const Vec2 a = view->segment_start(segment), b = view->segment_end(segment);
      for (int k = 0; k < 400; ++k) {
        const double angle = 0.0157 * k * std::numbers::pi, radius = 0.003 + 0.0011 * k;
        const Vec2 node =
            a + radius * Vec2(std::cos(angle), std::sin(angle)) + (0.37 * (k % 3)) * (b - a);
        const NodeProjection p = project_on_contour_segment(node, *view, segment);
        (p.t > 0.0 && p.t < 1.0 ? interiors : vertices) += 1;
        if (p.t >= 1.0 && a + 1.0 * (b - a) != b) ++rounded_ends;
        EXPECT_EQ(contour_segment_distance(node, *view, segment), p.distance)
            << "segment " << segment << ", node (" << node.x() << ", " << node.y() << ")";
      }
    }
  EXPECT_GT(vertices, 1000);
  EXPECT_GT(interiors, 1000);
  EXPECT_GT(rounded_ends, 100);
}

TEST(NodeSegment, OpenContourEndsHaveOneNeighbour) {
  const std::vector<Vec2> wall = {Vec2(2, 0), Vec2(1, 0), Vec2(0, 0)};  // material below
  const ContourView view{wall, false};
  EXPECT_EQ(view.segment_count(), 2);
  EXPECT_NEAR(tributary_length(view, 0), 0.5, kTol);
  EXPECT_NEAR(tributary_length(view, 1), 1.0, kTol);
  EXPECT_NEAR(tributary_length(view, 2), 0.5, kTol);
  // Beyond the free end (0,0): the distance to the end point, sign from the end's normal.
  const NodeProjection p = project_on_contour(Vec2(-0.3, 0.4), view);
  EXPECT_NEAR(p.gap, 0.5, kTol);
  EXPECT_NEAR((p.normal - Vec2(-0.6, 0.8)).norm(), 0.0, kTol);
}

TEST(NodeSegment, TributaryLengthsSumToThePerimeter) {
  // An irregular polygon (ellipse with uneven spacing after a shear) and a disc.
  Polygon ellipse = make_ellipse(Vec2(0.3, -0.2), 1.3, 0.6, 0.4, 0.07);
  for (Vec2& p : ellipse)
    p.x() += 0.2 * p.y() * p.y();
  for (const Polygon& contour : {ellipse, make_disc(Vec2(5, 5), 0.5, 0.05)}) {
    std::vector<double> lengths(contour.size());
    tributary_lengths(ContourView{contour}, lengths);
    double sum = 0.0;
    for (const double l : lengths)
      sum += l;
    // Each edge is counted as two halves: equal up to n ulps of the perimeter.
    EXPECT_NEAR(sum, perimeter(contour), 1e-13 * perimeter(contour)) << contour.size();
  }
}

TEST(NodeSegment, SlipIncrementMeasuresRelativeTangentialMotion) {
  const Vec2 a(0, 0), b(2, 0);  // material below (runs left to right: normal -y; fine here)
  const double t = 0.25;
  // Node slides by 0.3 along the segment at constant height: ds = 0.3.
  EXPECT_NEAR(tangential_slip_increment(Vec2(0.5, 0.01), a, b, Vec2(0.8, 0.01), a, b, t), 0.3,
              kTol);
  // Node fixed, segment translated by +0.2 along itself: ds = -0.2.
  EXPECT_NEAR(tangential_slip_increment(Vec2(0.5, 0.01), a, b, Vec2(0.5, 0.01), a + Vec2(0.2, 0),
                                        b + Vec2(0.2, 0), t),
              -0.2, kTol);
  // Rigid rotation (0.3 rad about (4, -3)) plus translation of node and segment together:
  // no slip, although the node sits at a gap of 0.05 (a non-objective measure would give
  // about gap x angle = 0.015).
  const Mat2 rot = rotation(0.3);
  const Vec2 c(4, -3), move(0.7, -1.1);
  const auto rigid = [&](const Vec2& x) -> Vec2 { return c + rot * (x - c) + move; };
  const Vec2 node(0.6, 0.05);
  EXPECT_NEAR(tangential_slip_increment(node, a, b, rigid(node), rigid(a), rigid(b), t), 0.0,
              1e-13);  // round-off of coordinates of size ~5
}

}  // namespace
}  // namespace sg
