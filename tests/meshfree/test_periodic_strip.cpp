// Periodic strips (first bodies spanning the cell): MLS rows that see the periodic images of
// the nodes reproduce constant and linear fields exactly, also at Gauss points whose supports
// cross the seam, and the quadrature covers exactly one period.
#include "meshfree/periodic_strip.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "geometry/rough_surface.h"

namespace sg {
namespace {

constexpr double kPeriod = 6.0;
constexpr double kSpacing = 0.2;

// A rough surface over one period starting at x0 (columns at x0 + j L / n), for a body below
// (x decreasing, closing shift -L) or above (x increasing, +L) it.
Polygon rough_surface(double x0, bool body_below, double mean_y) {
  RoughSurfaceDef def;
  def.length = kPeriod;
  def.points = static_cast<int>(std::lround(kPeriod / kSpacing));
  def.rms = 0.15;
  const RoughProfile profile = make_rough_profile(def, 7);
  Polygon surface;
  const std::size_t n = profile.heights.size();
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = body_below ? n - 1 - j : j;
    surface.emplace_back(x0 + static_cast<double>(k) * profile.spacing(),
                         mean_y + profile.heights[k]);
  }
  return surface;
}

PeriodicStripDiscretization strip(bool body_below, double x0 = -0.37) {
  DiscretizationParams params;
  params.mesh.spacing = kSpacing;
  return body_below
             ? discretize_periodic_strip(rough_surface(x0, true, 0.0), -kPeriod, -1.0, params, "s")
             : discretize_periodic_strip(rough_surface(x0, false, 2.0), kPeriod, 3.0, params, "s");
}

struct RowCheck {
  int rows_with_images = 0;
  double worst_unity = 0.0, worst_position = 0.0, worst_gradient = 0.0;
  double worst_unshifted = 0.0;  // the position error when the image shifts are ignored
};

// Sum N = 1, sum N (X + image L) = x, sum grad N = 0, sum grad N (X + image L)^T = I.
RowCheck check_rows(const PeriodicStripDiscretization& s, const ShapeRows& rows,
                    const std::vector<std::int8_t>& image, const std::vector<Vec2>& at) {
  RowCheck c;
  const std::vector<Vec2>& nodes = s.body.mesh.nodes;
  for (std::size_t p = 0; p < rows.points(); ++p) {
    double unity = 0.0;
    Vec2 position(0, 0), unshifted(0, 0), grad_sum(0, 0);
    Mat2 grad = Mat2::Zero();
    bool crosses = false;
    for (auto k = static_cast<std::size_t>(rows.offset[p]);
         k < static_cast<std::size_t>(rows.offset[p + 1]); ++k) {
      const Vec2 x = nodes[static_cast<std::size_t>(rows.node[k])];
      const Vec2 shifted = x + Vec2(image[k] * s.period, 0.0);
      crosses = crosses || image[k] != 0;
      unity += rows.value[k];
      position += rows.value[k] * shifted;
      unshifted += rows.value[k] * x;
      grad_sum += Vec2(rows.dndx[k], rows.dndy[k]);
      grad += shifted * Vec2(rows.dndx[k], rows.dndy[k]).transpose();
    }
    c.worst_unity = std::max(c.worst_unity, std::abs(unity - 1.0));
    c.worst_position = std::max(c.worst_position, (position - at[p]).norm());
    c.worst_gradient =
        std::max({c.worst_gradient, grad_sum.norm() * kSpacing, (grad - Mat2::Identity()).norm()});
    if (crosses) {
      ++c.rows_with_images;
      c.worst_unshifted = std::max(c.worst_unshifted, (unshifted - at[p]).norm());
    }
  }
  return c;
}

TEST(PeriodicStrip, RowsReproduceLinearFieldsAcrossTheSeam) {
  for (const bool below : {true, false}) {
    const PeriodicStripDiscretization s = strip(below);
    const BodyDiscretization& d = s.body;
    // Gauss points.
    const RowCheck g = check_rows(s, d.gauss_rows, s.gauss_image, d.gauss_position);
    // Rows near the seam see images: at least the seam column's Gauss points do (two
    // columns of triangles, a few points each).
    EXPECT_GT(g.rows_with_images, 20);
    // Round-off of a 3x3 solve at coordinates ~L: 1e-12 relative is far below any
    // discretization error (ignoring the shifts costs a whole period, checked below).
    EXPECT_LT(g.worst_unity, 1e-12);
    EXPECT_LT(g.worst_position, 1e-12 * kPeriod);
    EXPECT_LT(g.worst_gradient, 1e-10);
    EXPECT_GT(g.worst_unshifted, 0.1 * kPeriod);  // the images are really used
    // Node rows (positions and contact forces of the contour nodes). A contour node's row is
    // the hat average of the rows along its two segments (meshfree/contour_rows.h): it
    // reproduces linear fields at the hat centroid Xbar = X - d, not at X.
    ASSERT_EQ(d.contour_offset.size(), static_cast<std::size_t>(d.mesh.boundary_count));
    std::vector<Vec2> reproduced_at = d.mesh.nodes;
    double largest_offset = 0.0;  // nonzero on a rough surface (its hats are not symmetric)
    for (std::size_t k = 0; k < d.contour_offset.size(); ++k) {
      reproduced_at[k] -= d.contour_offset[k];
      largest_offset = std::max(largest_offset, d.contour_offset[k].norm());
    }
    EXPECT_GT(largest_offset, 1e-3 * kSpacing);
    const RowCheck n = check_rows(s, d.node_rows, s.node_image, reproduced_at);
    EXPECT_GT(n.rows_with_images, 10);
    EXPECT_LT(n.worst_unity, 1e-12);
    EXPECT_LT(n.worst_position, 1e-12 * kPeriod);
    EXPECT_LT(n.worst_gradient, 1e-10);
  }
}

TEST(PeriodicStrip, NodesAreNotDuplicatedAndQuadratureCoversOnePeriod) {
  for (const bool below : {true, false}) {
    const PeriodicStripDiscretization s = strip(below);
    const BodyDiscretization& d = s.body;
    const Polygon surface = rough_surface(-0.37, below, below ? 0.0 : 2.0);
    // Surface nodes first, in the given order.
    ASSERT_EQ(d.mesh.boundary_count, static_cast<int>(surface.size()));
    for (std::size_t k = 0; k < surface.size(); ++k)
      EXPECT_EQ(d.mesh.nodes[k], surface[k]);
    // Every node within one period [x0, x0 + L): none at x0 + L (that is the first column).
    for (const Vec2& p : d.mesh.nodes) {
      EXPECT_GE(p.x(), -0.37 - 1e-12);
      EXPECT_LT(p.x(), -0.37 + kPeriod - 0.5 * kSpacing);
    }
    // The area of one period: trapezoids between consecutive surface points (the last one
    // across the seam) over the back face.
    double area = 0.0;
    const double back = s.back_y;
    for (std::size_t k = 0; k < surface.size(); ++k) {
      const Vec2 a = surface[k];
      const Vec2 b =
          k + 1 < surface.size() ? surface[k + 1] : surface[0] + Vec2(s.closing_shift_x, 0.0);
      area += 0.5 * std::abs(b.x() - a.x()) * (std::abs(a.y() - back) + std::abs(b.y() - back));
    }
    double weights = 0.0, lumped = 0.0;
    for (double w : d.gauss_weight)
      weights += w;
    for (double v : d.lumped_volume)
      lumped += v;
    EXPECT_NEAR(weights, area, 1e-12 * area);
    EXPECT_NEAR(lumped, area, 1e-12 * area);  // partition of unity
    // Back face: one node per column, at back_y.
    EXPECT_EQ(s.back_nodes.size(), surface.size());
    for (int i : s.back_nodes)
      EXPECT_EQ(d.mesh.nodes[static_cast<std::size_t>(i)].y(), back);
    // The drawn triangles never cross the seam (no band across the cell).
    for (const auto& t : d.mesh.triangles)
      for (int e = 0; e < 3; ++e)
        EXPECT_LT(
            std::abs(
                d.mesh.nodes[static_cast<std::size_t>(t[static_cast<std::size_t>(e)])].x() -
                d.mesh.nodes[static_cast<std::size_t>(t[static_cast<std::size_t>((e + 1) % 3)])]
                    .x()),
            1.5 * kSpacing);
    EXPECT_FALSE(s.seam_triangles.empty());
  }
}

TEST(PeriodicStrip, BadInputIsRefusedWithTheBodyName) {
  DiscretizationParams params;
  params.mesh.spacing = kSpacing;
  auto message = [&](const Polygon& surface, double shift, double back) {
    try {
      discretize_periodic_strip(surface, shift, back, params, "bottom");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const Polygon below = rough_surface(0.0, true, 0.0);
  // Back face above the surface of a body below it.
  EXPECT_NE(message(below, -kPeriod, 0.5).find("back face"), std::string::npos);
  // x increasing with a negative closing shift.
  Polygon reversed(below.rbegin(), below.rend());
  EXPECT_NE(message(reversed, -kPeriod, -1.0).find("decreasing"), std::string::npos);
  // A period shorter than the surface.
  EXPECT_NE(message(below, -0.5 * kPeriod, -1.0).find("period"), std::string::npos);
  // A period too short for the MLS supports: 3 columns, the supports wrap onto themselves.
  const Polygon tiny = {Vec2(0.4, 0.0), Vec2(0.2, 0.0), Vec2(0.0, 0.0)};
  const std::string e = message(tiny, -0.6, -1.0);
  EXPECT_NE(e.find("bottom"), std::string::npos) << e;
  EXPECT_NE(e.find("period is too short"), std::string::npos) << e;
}

}  // namespace
}  // namespace sg
