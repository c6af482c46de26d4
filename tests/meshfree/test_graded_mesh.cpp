// Graded node density (issue #32): a graded grain has the node count and the contour spacing
// asked for, within the mesher's tolerance; a graded periodic strip coarsens towards its back
// face; bad gradings are refused naming the body.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "geometry/polygon.h"
#include "geometry/shapes.h"
#include "meshfree/domain_mesh.h"
#include "meshfree/periodic_strip.h"

namespace sg {
namespace {

DomainMesh mesh(const Polygon& contour, double h, double interior = 0.0) {
  DomainMeshParams params;
  params.spacing = h;
  params.interior_spacing = interior;
  return mesh_domain(contour, params, "test_body");
}

struct ContourSpacing {
  double smallest = 1e300, largest = 0.0;
};
ContourSpacing contour_spacing(const DomainMesh& m) {
  ContourSpacing s;
  const auto n = static_cast<std::size_t>(m.boundary_count);
  for (std::size_t i = 0; i < n; ++i) {
    const double edge = (m.nodes[(i + 1) % n] - m.nodes[i]).norm();
    s.smallest = std::min(s.smallest, edge);
    s.largest = std::max(s.largest, edge);
  }
  return s;
}

// Mean distance from the interior node nearest to `at` to its 6 nearest other nodes: the local
// spacing there.
double local_spacing(const DomainMesh& m, const Vec2& at) {
  std::size_t nearest = static_cast<std::size_t>(m.boundary_count);
  for (std::size_t i = nearest; i < m.nodes.size(); ++i)
    if ((m.nodes[i] - at).norm() < (m.nodes[nearest] - at).norm()) nearest = i;
  std::vector<double> d;
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (i != nearest) d.push_back((m.nodes[i] - m.nodes[nearest]).norm());
  std::partial_sort(d.begin(), d.begin() + 6, d.end());
  return (d[0] + d[1] + d[2] + d[3] + d[4] + d[5]) / 6.0;
}

// The node count a graded disc asks for: the uniform mesh's interior nodes at the contour
// spacing h, thinned by the mean of (h / s(d))^2 over the disc, s(d) = h (1 + (g - 1) d / R)
// the requested spacing at depth d (linear from the contour to the centre, g = interior / h).
double requested_interior_nodes(double uniform_interior_nodes, double radius, double grading) {
  double integral = 0.0, area = 0.0;
  const int n = 10000;
  for (int k = 0; k < n; ++k) {
    const double d = radius * (k + 0.5) / n;
    const double ring = 2.0 * std::numbers::pi * (radius - d) * radius / n;
    const double s = 1.0 + (grading - 1.0) * d / radius;
    integral += ring / (s * s);
    area += ring;
  }
  return uniform_interior_nodes * integral / area;
}

// A disc of radius 1 with contour spacing 0.05 graded to 0.15 at its centre (the paper 003
// ratio of 3 between contour and centre): the contour is the one asked for (no point added,
// edges within 2% of h), the node count is the requested one within the mesher's tolerance,
// 10% (the interior node density of the refinement and smoothing, calibrated on the uniform
// mesh of the same contour spacing), and the spacing at the centre is the interior spacing
// within 25% (refinement stops with edges between 0.6 and 1 times the size bound).
// Measured: 720 nodes graded against 1444 uniform (requested 720, -0.0%); contour edges all
// 0.04986; centre spacing 0.135 (-10%).
TEST(GradedMesh, NodeCountAndContourSpacingMatchTheRequestedOnes) {
  const double radius = 1.0, h = 0.05, interior = 0.15;
  const Polygon disc = make_disc(Vec2(0, 0), radius, h);
  const DomainMesh uniform = mesh(disc, h);
  const DomainMesh graded = mesh(disc, h, interior);
  EXPECT_EQ(graded.boundary_count, static_cast<int>(disc.size()));
  EXPECT_EQ(graded.boundary_count, uniform.boundary_count);
  const ContourSpacing c = contour_spacing(graded);
  EXPECT_GT(c.smallest, 0.98 * h);
  EXPECT_LT(c.largest, 1.02 * h);
  const double uniform_interior =
      static_cast<double>(uniform.nodes.size()) - uniform.boundary_count;
  const double requested =
      graded.boundary_count + requested_interior_nodes(uniform_interior, radius, interior / h);
  const double count = static_cast<double>(graded.nodes.size());
  const double centre = local_spacing(graded, Vec2(0, 0));
  std::printf(
      "graded disc: %zu nodes (requested %.0f, %+.1f%%), uniform %zu; contour %.5f-%.5f; "
      "centre spacing %.4f (%+.1f%%)\n",
      graded.nodes.size(), requested, 100.0 * (count / requested - 1.0), uniform.nodes.size(),
      c.smallest, c.largest, centre, 100.0 * (centre / interior - 1.0));
  EXPECT_NEAR(count / requested, 1.0, 0.10);
  EXPECT_NEAR(centre / interior, 1.0, 0.25);
  // Next to the contour the spacing stays the contour's.
  EXPECT_NEAR(local_spacing(graded, Vec2(radius - 1.5 * h, 0.0)) / h, 1.0, 0.25);
}

// Ellipses grade to their depth (the smaller semi-axis): paper 003's ellipse of 1.5 x 0.9 um
// at 60 nm on the contour, up to 170 nm at the centre. Measured: 196 nodes against 357
// uniform; centre spacing 0.130 (-24%: the slope reaches 170 nm only at the centre, where a
// node's neighbours are still closer).
TEST(GradedMesh, EllipseCoarsensToItsCentreWithItsContourKept) {
  const double h = 0.06, interior = 0.17;
  const Polygon ellipse = make_ellipse(Vec2(0.3, -0.2), 0.75, 0.45, 0.4, h);
  const DomainMesh uniform = mesh(ellipse, h);
  const DomainMesh graded = mesh(ellipse, h, interior);
  EXPECT_EQ(graded.boundary_count, static_cast<int>(ellipse.size()));
  const ContourSpacing c = contour_spacing(graded);
  EXPECT_GT(c.smallest, 0.9 * h);
  EXPECT_LT(c.largest, 1.1 * h);
  const double centre = local_spacing(graded, Vec2(0.3, -0.2));
  std::printf("graded ellipse: %zu nodes, uniform %zu; centre spacing %.4f\n", graded.nodes.size(),
              uniform.nodes.size(), centre);
  EXPECT_LT(graded.nodes.size(), uniform.nodes.size());
  EXPECT_NEAR(centre / interior, 1.0, 0.3);
  double area = 0.0;
  for (const auto& t : graded.triangles)
    area += 0.5 * cross(graded.nodes[static_cast<std::size_t>(t[1])] -
                            graded.nodes[static_cast<std::size_t>(t[0])],
                        graded.nodes[static_cast<std::size_t>(t[2])] -
                            graded.nodes[static_cast<std::size_t>(t[0])]);
  EXPECT_NEAR(area, signed_area(ellipse), 1e-10 * signed_area(ellipse));
}

TEST(GradedMesh, MeshingTwiceGivesIdenticalOutput) {
  const Polygon e = make_ellipse(Vec2(0.1, 0.2), 1.5, 0.8, 0.3, 0.08);
  const DomainMesh a = mesh(e, 0.08, 0.24);
  const DomainMesh b = mesh(e, 0.08, 0.24);
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.triangles, b.triangles);
}

// A flat strip 1 deep at surface spacing 0.05, graded to 0.2 at its back face: each column
// has the nodes of the linear law (11 instead of 21), the first interval under the surface is
// the surface spacing and the last one at the back face close to the interior spacing.
TEST(GradedMesh, PeriodicStripCoarsensTowardsItsBackFace) {
  const double h = 0.05, interior = 0.2, period = 2.0;
  Polygon surface;
  for (int k = 39; k >= 0; --k)
    surface.emplace_back(k * h, 0.0);
  DiscretizationParams params;
  params.mesh.spacing = h;
  params.mesh.interior_spacing = interior;
  const PeriodicStripDiscretization strip =
      discretize_periodic_strip(surface, -period, -1.0, params, "strip");
  // Column of x = 0: the surface node (index 39 of the surface) and the nodes below it.
  std::vector<double> ys;
  for (const Vec2& p : strip.body.mesh.nodes)
    if (std::abs(p.x()) < 1e-12) ys.push_back(p.y());
  std::sort(ys.begin(), ys.end());
  ASSERT_EQ(ys.size(), 11u);
  EXPECT_NEAR(ys.back() - ys[ys.size() - 2], h, 0.05 * h);
  EXPECT_GT(ys[1] - ys[0], 0.8 * interior);
  EXPECT_LT(ys[1] - ys[0], interior);
  EXPECT_EQ(ys.front(), -1.0);
  double area = 0.0;
  for (double w : strip.body.gauss_weight)
    area += w;
  EXPECT_NEAR(area, period * 1.0, 1e-10);
  double lumped = 0.0;
  for (double v : strip.body.lumped_volume)
    lumped += v;
  EXPECT_NEAR(lumped, period * 1.0, 1e-10);
}

void expect_error(const DomainMeshParams& params, const std::string& expected) {
  try {
    mesh_domain(make_disc(Vec2(0, 0), 0.5, 0.1), params, "grain_7");
    ADD_FAILURE() << "accepted; expected an error mentioning " << expected;
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("grain_7"), std::string::npos) << what;
    EXPECT_NE(what.find(expected), std::string::npos) << what;
  }
}

TEST(GradedMesh, BadGradingsAreRefusedWithBodyAndValue) {
  DomainMeshParams p;
  p.spacing = 0.1;
  p.interior_spacing = 0.05;
  expect_error(p, "interior spacing 0.05 must be 0 (uniform) or at least the contour spacing");
  p.interior_spacing = -1.0;
  expect_error(p, "interior spacing -1");
  p.interior_spacing = 0.3;
  p.boundary_grading = 2.0;
  expect_error(p, "give one");
}

}  // namespace
}  // namespace sg
