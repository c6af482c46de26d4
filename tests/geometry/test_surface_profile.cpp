// Surface profiles of periodic strips (geometry/surface_profile.h): sums of sines sampled on
// the period's grid, listed points checked, subdivided and wrapped across the seam.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "geometry/surface_profile.h"

namespace sg {
namespace {

TEST(SurfaceProfile, SinesAreSampledOnThePeriodGrid) {
  SurfaceProfileDef def;
  def.kind = ProfileKind::sines;
  def.modes = {{0.3, 4.0, 0.7}, {-0.1, 1.0, 0.0}};
  const std::vector<Vec2> p = sample_profile(def, 1.0, 8.0, 0.25, "test");
  ASSERT_EQ(p.size(), 32u);
  for (std::size_t j = 0; j < p.size(); ++j) {
    const double s = static_cast<double>(j) * 8.0 / 32.0;
    EXPECT_NEAR(p[j].x(), 1.0 + s, 1e-15);
    const double y = 0.3 * std::sin(2.0 * std::numbers::pi * s / 4.0 + 0.7) -
                     0.1 * std::sin(2.0 * std::numbers::pi * s);
    EXPECT_NEAR(p[j].y(), y, 1e-15);
  }
  def.modes[1].wavelength = 3.0;
  EXPECT_THROW(sample_profile(def, 1.0, 8.0, 0.25, "test"), Error);
}

TEST(SurfaceProfile, ListedPointsAreSubdividedAndWrappedAcrossTheSeam) {
  SurfaceProfileDef def;
  def.kind = ProfileKind::points;
  def.source = "test.csv";
  def.points = {{1.0, 0.0}, {2.0, 1.0}, {3.0, 0.0}};  // period [0, 4): the seam 3 -> 5 is long
  const std::vector<Vec2> p = sample_profile(def, 0.0, 4.0, 0.5, "test");
  // Segments of length sqrt(2) -> 2 pieces each; the seam (3, 0) -> (5, 0) of length 2 -> 3
  // pieces, of which the point at x = 4.33 wraps to 0.33 at the front.
  ASSERT_EQ(p.size(), 7u);
  EXPECT_NEAR(p[0].x(), 4.0 + 1.0 / 3.0 - 4.0, 1e-15);
  EXPECT_EQ(p[1], Vec2(1.0, 0.0));
  EXPECT_EQ(p[2], Vec2(1.5, 0.5));
  for (std::size_t k = 1; k < p.size(); ++k)
    EXPECT_GT(p[k].x(), p[k - 1].x());
  EXPECT_NEAR(p.back().x(), 3.0 + 2.0 / 3.0, 1e-15);
  EXPECT_EQ(p.back().y(), 0.0);

  def.points = {{1.0, 0.0}, {0.5, 1.0}};
  EXPECT_THROW(sample_profile(def, 0.0, 4.0, 0.5, "test"), Error);  // x decreasing
  def.points = {{1.0, 0.0}, {4.5, 1.0}};
  EXPECT_THROW(sample_profile(def, 0.0, 4.0, 0.5, "test"), Error);  // outside the period
}

}  // namespace
}  // namespace sg
