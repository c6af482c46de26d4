// MLS shape functions: partition of unity and exact reproduction of linear fields and of
// their gradients (the consistency conditions of a linear basis; Belytschko 1994 §2).
#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "meshfree/mls.h"

namespace sg {
namespace {

// A jittered square lattice of n x n nodes on [0, 1]^2: irregular but without clusters.
std::vector<Vec2> jittered_lattice(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Vec2> nodes;
  const double h = 1.0 / (n - 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const bool edge = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      const Vec2 d = edge ? Vec2(0, 0) : Vec2(jitter(rng), jitter(rng));
      nodes.emplace_back((i + d.x()) * h, (j + d.y()) * h);
    }
  return nodes;
}

TEST(Mls, CubicSplineIsC2WithCompactSupport) {
  EXPECT_DOUBLE_EQ(cubic_spline_weight(0.0), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(cubic_spline_weight(1.0), 0.0);
  EXPECT_DOUBLE_EQ(cubic_spline_weight(1.5), 0.0);
  // Value and slope continuous at r = 1/2 and r = 1.
  const double e = 1e-9;
  EXPECT_NEAR(cubic_spline_weight(0.5 - e), cubic_spline_weight(0.5 + e), 1e-8);
  EXPECT_NEAR(cubic_spline_weight_derivative(0.5 - e), cubic_spline_weight_derivative(0.5 + e),
              1e-8);
  EXPECT_NEAR(cubic_spline_weight_derivative(1.0 - e), 0.0, 1e-8);
  // Derivative matches central differences.
  for (double r : {0.1, 0.3, 0.6, 0.9}) {
    const double fd = (cubic_spline_weight(r + 1e-6) - cubic_spline_weight(r - 1e-6)) / 2e-6;
    EXPECT_NEAR(cubic_spline_weight_derivative(r), fd, 1e-8);
  }
}

TEST(Mls, PartitionOfUnityAndLinearReproductionAtRandomPoints) {
  const std::vector<Vec2> nodes = jittered_lattice(12, 7);
  const MlsShapeFunctions mls(nodes, MlsParams{}, "lattice");
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // A linear field a + b X + c Y with its gradient (b, c).
  const double a = 0.7, b = -1.3, c = 2.1;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec2 x(u(rng), u(rng));
    ShapeRows rows;
    mls.evaluate(x, rows);
    double sum = 0, sum_dx = 0, sum_dy = 0, field = 0, grad_x = 0, grad_y = 0;
    Vec2 position(0, 0);
    Mat2 position_gradient = Mat2::Zero();  // sum_J X_J (x) grad N_J must be the identity
    for (std::size_t k = 0; k < rows.entries(); ++k) {
      const Vec2& xj = nodes[static_cast<std::size_t>(rows.node[k])];
      sum += rows.value[k];
      sum_dx += rows.dndx[k];
      sum_dy += rows.dndy[k];
      position += rows.value[k] * xj;
      position_gradient += xj * Vec2(rows.dndx[k], rows.dndy[k]).transpose();
      const double fj = a + b * xj.x() + c * xj.y();
      field += rows.value[k] * fj;
      grad_x += rows.dndx[k] * fj;
      grad_y += rows.dndy[k] * fj;
    }
    // 1e-10 relative to O(1) fields and O(1/h) gradients (h = 1/11): round-off is ~1e-14.
    EXPECT_NEAR(sum, 1.0, 1e-10);
    EXPECT_NEAR(sum_dx, 0.0, 1e-10 * 11);
    EXPECT_NEAR(sum_dy, 0.0, 1e-10 * 11);
    EXPECT_NEAR((position - x).norm(), 0.0, 1e-10);
    EXPECT_NEAR((position_gradient - Mat2::Identity()).norm(), 0.0, 1e-10);
    EXPECT_NEAR(field, a + b * x.x() + c * x.y(), 1e-10 * 4);
    EXPECT_NEAR(grad_x, b, 1e-10 * 4);
    EXPECT_NEAR(grad_y, c, 1e-10 * 4);
    EXPECT_GE(rows.entries(), 3u);  // the minimum for a linear basis
  }
}

TEST(Mls, ReproductionIsScaleInvariant) {
  // Same lattice in micrometres: the shifted, scaled basis keeps A well conditioned.
  std::vector<Vec2> nodes = jittered_lattice(8, 3);
  for (Vec2& p : nodes)
    p = 1e-6 * p + Vec2(3e-3, -2e-3);
  const MlsShapeFunctions mls(nodes, MlsParams{}, "micro");
  ShapeRows rows;
  const Vec2 x = 1e-6 * Vec2(0.37, 0.61) + Vec2(3e-3, -2e-3);
  mls.evaluate(x, rows);
  Vec2 position(0, 0);
  double grad = 0;
  for (std::size_t k = 0; k < rows.entries(); ++k) {
    position += rows.value[k] * nodes[static_cast<std::size_t>(rows.node[k])];
    grad += rows.dndx[k] * nodes[static_cast<std::size_t>(rows.node[k])].x();
  }
  EXPECT_NEAR((position - x).norm() / 1e-6, 0.0, 1e-9);
  EXPECT_NEAR(grad, 1.0, 1e-9);
}

TEST(Mls, CollinearNodesAreRefusedWithBodyAndPoint) {
  std::vector<Vec2> nodes;
  for (int i = 0; i < 20; ++i)
    nodes.emplace_back(0.1 * i, 0.0);
  const MlsShapeFunctions mls(nodes, MlsParams{}, "needle");
  ShapeRows rows;
  try {
    mls.evaluate(Vec2(0.95, 0.0), rows);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("needle"), std::string::npos) << what;
    EXPECT_NE(what.find("ill-conditioned"), std::string::npos) << what;
    EXPECT_NE(what.find("0.95"), std::string::npos) << what;
  }
}

TEST(Mls, PointOutsideAllSupportsIsRefused) {
  const std::vector<Vec2> nodes = jittered_lattice(6, 1);
  const MlsShapeFunctions mls(nodes, MlsParams{}, "square");
  ShapeRows rows;
  EXPECT_THROW(mls.evaluate(Vec2(5.0, 5.0), rows), Error);
}

TEST(Mls, TooFewNodesForTheSupportIsRefused) {
  const std::vector<Vec2> nodes = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(1, 1)};
  EXPECT_THROW(MlsShapeFunctions(nodes, MlsParams{}, "tiny"), Error);
}

}  // namespace
}  // namespace sg
