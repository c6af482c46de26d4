#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "analysis/coherence.h"
#include "analysis/velocity_grid.h"
#include "core/error.h"
#include "synthetic.h"

namespace sg {
namespace {

// A grid velocity field V(x, y) sampled at every node, all nodes valid.
VelocityGrid sample(const RegularGrid& g, const std::function<Vec2(double, double)>& field) {
  VelocityGrid v;
  v.grid = g;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      v.velocity.push_back(field(g.x(i), g.y(j)));
  v.valid.assign(g.size(), 1);
  return v;
}

// Nodes whose disc of radius R lies inside the grid, away from the x seam too (for fields
// that are not periodic).
template <class F>
void for_interior(const RegularGrid& g, double radius, F f) {
  const int m = static_cast<int>(std::ceil(radius / g.hx));
  for (int j = m; j < g.ny - m; ++j)
    for (int i = m; i < g.nx - m; ++i)
      f(i, j);
}

const RegularGrid kGrid = make_periodic_grid(0.0, 40.0, 0.0, 19.0, 1.0);  // 40 x 20, h = 1

TEST(Coherence, RigidRotationIsPlusOrMinusOne) {
  // V = U + w e_z x (M - O), any centre O and drift U: relative to its disc mean, the
  // field is exactly w e_z x (M - P) on a full symmetric disc, so C = sign(w) (eq. 5).
  // Rounding in the three sums: ~1e-15 relative; 1e-12.
  CoherenceParams params;
  params.radius = 2.5;
  for (const double w : {0.3, -0.3}) {
    const VelocityGrid v = sample(kGrid, [&](double x, double y) -> Vec2 {
      return Vec2(0.7, -0.2) + w * Vec2(-(y - 9.3), x - 21.1);
    });
    const CoherenceField c = compute_coherence(v, params);
    int checked = 0;
    for_interior(kGrid, params.radius, [&](int i, int j) {
      const std::size_t n = kGrid.index(i, j);
      ASSERT_TRUE(c.defined[n]);
      EXPECT_NEAR(c.value[n], w > 0 ? 1.0 : -1.0, 1e-12) << i << ", " << j;
      ++checked;
    });
    EXPECT_GT(checked, 400);
  }
}

TEST(Coherence, UniformTranslationIsZeroByConvention) {
  // V - V_ave = 0: eq. 5 is 0/0; defined as C = 0 (coherence.h), node still defined.
  CoherenceParams params;
  const VelocityGrid v = sample(kGrid, [](double, double) -> Vec2 { return Vec2(0.5, -0.25); });
  const CoherenceField c = compute_coherence(v, params);
  for (std::size_t n = 0; n < kGrid.size(); ++n) {
    EXPECT_TRUE(c.defined[n]);
    EXPECT_EQ(c.value[n], 0.0);
  }
  // At rest too.
  const CoherenceField rest = compute_coherence(
      sample(kGrid, [](double, double) -> Vec2 { return Vec2(0.0, 0.0); }), params);
  for (std::size_t n = 0; n < kGrid.size(); ++n)
    EXPECT_EQ(rest.value[n], 0.0);
}

TEST(Coherence, SimpleShearIsMinusOneOverRootTwo) {
  // V = (g y, 0), periodic in x. On a disc centred on P (offsets r), V - V_ave = (g r_y, 0)
  // since the disc's nodes are symmetric (sum r_y = 0). Then
  //   num = sum g r_y (-r_y) = -g S_y,  den = |g| sqrt(S_y) sqrt(S_x + S_y),
  // with S_x = sum r_x^2 = S_y = sum r_y^2 on a square grid (hx = hy: the disc's nodes are
  // symmetric under x <-> y). So C = -sign(g) / sqrt(2) exactly, as in the continuum.
  CoherenceParams params;
  params.radius = 3.0;
  for (const double g : {0.05, -2.0}) {
    const VelocityGrid v =
        sample(kGrid, [&](double, double y) -> Vec2 { return Vec2(g * y, 0.0); });
    const CoherenceField c = compute_coherence(v, params);
    for (int j = 3; j < kGrid.ny - 3; ++j)
      for (int i = 0; i < kGrid.nx; ++i)  // every column: the seam is no boundary
        EXPECT_NEAR(c.value[kGrid.index(i, j)], -std::copysign(1.0, g) / std::sqrt(2.0), 1e-12);
  }
}

TEST(Coherence, PeriodicSeamIsExact) {
  // An arbitrary periodic field; shifting it by k columns shifts C by k columns, bit for
  // bit: the disc wraps across the seam with the same offsets in the same order.
  test::Gaussian noise(11);
  std::vector<Vec2> base(kGrid.size());
  for (auto& b : base)
    b = Vec2(noise(), noise());
  VelocityGrid v;
  v.grid = kGrid;
  v.velocity = base;
  v.valid.assign(kGrid.size(), 1);
  v.valid[kGrid.index(5, 7)] = 0;  // with a hole, to check validity travels too
  CoherenceParams params;
  params.radius = 2.5;
  const CoherenceField c0 = compute_coherence(v, params);
  for (const int k : {1, 7, 20, 39}) {
    VelocityGrid shifted = v;
    for (int j = 0; j < kGrid.ny; ++j)
      for (int i = 0; i < kGrid.nx; ++i) {
        shifted.velocity[kGrid.index(kGrid.wrap_i(i + k), j)] = v.velocity[kGrid.index(i, j)];
        shifted.valid[kGrid.index(kGrid.wrap_i(i + k), j)] = v.valid[kGrid.index(i, j)];
      }
    const CoherenceField ck = compute_coherence(shifted, params);
    for (int j = 0; j < kGrid.ny; ++j)
      for (int i = 0; i < kGrid.nx; ++i) {
        EXPECT_EQ(ck.value[kGrid.index(kGrid.wrap_i(i + k), j)], c0.value[kGrid.index(i, j)]);
        EXPECT_EQ(ck.defined[kGrid.index(kGrid.wrap_i(i + k), j)], c0.defined[kGrid.index(i, j)]);
      }
  }
  // |C| <= 1 (Cauchy-Schwarz) on random data.
  for (const double x : c0.value)
    EXPECT_LE(std::abs(x), 1.0 + 1e-15);
  EXPECT_FALSE(c0.defined[kGrid.index(5, 7)]);
}

TEST(Coherence, EdgesAndHolesFollowTheValidFraction) {
  // A field valid only in the lower half: nodes of the upper half are undefined, and so
  // are lower nodes whose disc is mostly invalid.
  CoherenceParams params;
  params.radius = 2.5;
  VelocityGrid v = sample(kGrid, [](double x, double y) -> Vec2 { return Vec2(-y, x); });
  for (int j = 10; j < kGrid.ny; ++j)
    for (int i = 0; i < kGrid.nx; ++i)
      v.valid[kGrid.index(i, j)] = 0;
  const CoherenceField c = compute_coherence(v, params);
  EXPECT_FALSE(c.defined[kGrid.index(10, 12)]);
  EXPECT_TRUE(c.defined[kGrid.index(10, 5)]);
  EXPECT_TRUE(c.defined[kGrid.index(10, 9)]);  // half of its disc is valid: kept
  EXPECT_THROW(compute_coherence(v, CoherenceParams{25.0, 0.5, 1e-10}), Error);
}

// ---- the MLS transfer of grain velocities to the grid ----------------------------------

// Grains on a jittered lattice (pitch 1) in [0, L) x [y0, y1), velocities from `field`.
GrainSnapshot scatter(double length, double y0, double y1, std::uint64_t seed,
                      const std::function<Vec2(const Vec2&)>& field) {
  test::Gaussian rng(seed);
  GrainSnapshot s;
  for (double y = y0 + 0.5; y < y1; y += 1.0)
    for (double x = 0.5; x < length; x += 1.0) {
      const Vec2 p(x + 0.3 * (rng.uniform() - 0.5), y + 0.3 * (rng.uniform() - 0.5));
      s.position.push_back(p);
      s.velocity.push_back(field(p));
      s.area.push_back(0.7 + 0.2 * rng.uniform());
      s.body.push_back("g");
    }
  return s;
}

TEST(VelocityGrid, CubicSplineWeightIsC2) {
  // Values, first and second derivatives continuous at q = 1/2 and vanishing at q = 1
  // (one-sided finite differences, step 1e-4: truncation error ~1e-4 x W''' ~ 1e-3).
  EXPECT_DOUBLE_EQ(cubic_spline_weight(0.0), 2.0 / 3.0);
  EXPECT_EQ(cubic_spline_weight(1.0), 0.0);
  EXPECT_EQ(cubic_spline_weight(1.5), 0.0);
  const double h = 1e-4;
  for (const double q : {0.5, 1.0}) {
    auto w = [](double x) { return cubic_spline_weight(x); };
    const double d1_left = (w(q) - w(q - h)) / h, d1_right = (w(q + h) - w(q)) / h;
    const double d2_left = (w(q) - 2 * w(q - h) + w(q - 2 * h)) / (h * h);
    const double d2_right = (w(q + 2 * h) - 2 * w(q + h) + w(q)) / (h * h);
    EXPECT_NEAR(d1_left, d1_right, 1e-3) << q;
    EXPECT_NEAR(d2_left, d2_right, 1e-2) << q;
  }
}

TEST(VelocityGrid, LinearFieldsReachTheGridExactly) {
  // MLS with a linear basis reproduces linear fields: grain velocities of an affine field
  // give the affine field at every valid node, to rounding (~1e-14 for O(10) values).
  const double length = 30.0;
  const RegularGrid grid = make_periodic_grid(0.0, length, 1.0, 9.0, 1.0);
  auto affine = [](const Vec2& p) -> Vec2 { return Vec2(0.2 + 0.05 * p.y(), -0.1 + 0.03 * p.y()); };
  const GrainSnapshot grains = scatter(length, 0.0, 10.0, 5, affine);
  const VelocityGrid v = interpolate_velocity_grid(grains, grid, VelocityFitParams{});
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t n = grid.index(i, j);
      ASSERT_TRUE(v.valid[n]) << i << ", " << j;
      EXPECT_NEAR((v.velocity[n] - affine(Vec2(grid.x(i), grid.y(j)))).norm(), 0.0, 1e-13);
    }
}

TEST(VelocityGrid, RigidRotationOfGrainsGivesCoherenceOne) {
  // A rotating patch of grains away from the seam, nothing elsewhere. Rotation is linear,
  // so the grid field is the exact rotation where defined (MLS is exact), and C = +1 at
  // nodes whose disc is fully defined; 1e-10 covers the rounding of the MLS solve.
  const double length = 60.0;
  const RegularGrid grid = make_periodic_grid(0.0, length, 0.0, 20.0, 1.0);
  GrainSnapshot grains = scatter(length, 0.0, 20.0, 9, [](const Vec2& p) -> Vec2 {
    return Vec2(1.0, 0.0) + 0.4 * Vec2(-(p.y() - 10.0), p.x() - 30.0);
  });
  GrainSnapshot patch;
  for (std::size_t k = 0; k < grains.size(); ++k)
    if (std::abs(grains.position[k].x() - 30.0) < 10.0) {
      patch.position.push_back(grains.position[k]);
      patch.velocity.push_back(grains.velocity[k]);
      patch.area.push_back(grains.area[k]);
      patch.body.push_back("g");
    }
  const VelocityGrid v = interpolate_velocity_grid(patch, grid, VelocityFitParams{});
  EXPECT_FALSE(v.valid[grid.index(5, 10)]);  // no grain within 2 of x = 5
  const CoherenceField c = compute_coherence(v, CoherenceParams{});
  int checked = 0;
  for (int j = 3; j <= 17; ++j)
    for (int i = 24; i <= 36; ++i) {
      EXPECT_NEAR(c.value[grid.index(i, j)], 1.0, 1e-10) << i << ", " << j;
      ++checked;
    }
  EXPECT_EQ(checked, 15 * 13);
}

TEST(VelocityGrid, ShiftingTheGrainsAcrossTheSeamShiftsTheGrid) {
  // Grains shifted by k grid columns (and wrapped back into the period) give the grid
  // field shifted by k columns: the nearest-image distances are the same numbers up to
  // the rounding of x + shift - L (1e-15 x L); the fitted values then agree to 1e-12.
  const double length = 25.0;
  const RegularGrid grid = make_periodic_grid(0.0, length, 0.0, 9.0, 1.0);
  test::Gaussian noise(4);
  GrainSnapshot grains =
      scatter(length, 0.0, 10.0, 3, [&](const Vec2&) -> Vec2 { return Vec2(noise(), noise()); });
  const VelocityGrid v0 = interpolate_velocity_grid(grains, grid, VelocityFitParams{});
  const CoherenceField c0 = compute_coherence(v0, CoherenceParams{});
  for (const int k : {3, 12, 24}) {
    GrainSnapshot moved = grains;
    for (auto& p : moved.position) {
      p.x() += k * grid.hx;
      if (p.x() >= length) p.x() -= length;
    }
    const VelocityGrid vk = interpolate_velocity_grid(moved, grid, VelocityFitParams{});
    const CoherenceField ck = compute_coherence(vk, CoherenceParams{});
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const std::size_t a = grid.index(i, j), b = grid.index(grid.wrap_i(i + k), j);
        ASSERT_EQ(v0.valid[a], vk.valid[b]);
        EXPECT_NEAR((v0.velocity[a] - vk.velocity[b]).norm(), 0.0, 1e-12);
        EXPECT_NEAR(c0.value[a], ck.value[b], 1e-12);
      }
  }
  // A whole period: positions differ only by L.
  GrainSnapshot far = grains;
  for (auto& p : far.position)
    p.x() += 3.0 * length;
  const VelocityGrid vf = interpolate_velocity_grid(far, grid, VelocityFitParams{});
  for (std::size_t n = 0; n < grid.size(); ++n)
    EXPECT_NEAR((vf.velocity[n] - v0.velocity[n]).norm(), 0.0, 1e-12);
  EXPECT_THROW(interpolate_velocity_grid(grains, grid, VelocityFitParams{13.0, 3, 1e-6}), Error);
}

}  // namespace
}  // namespace sg
