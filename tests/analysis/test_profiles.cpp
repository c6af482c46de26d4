#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/profiles.h"
#include "core/error.h"
#include "synthetic.h"

namespace sg {
namespace {

// Grains in a simple shear vx = g (y - yc), vy = 0, placed in every bin at the same M
// offsets (m + 1/2)/M of the bin width, symmetric about the bin centre: the bin's mean vx
// is g (y_center - yc) exactly, and its sample std is g x (sample std of the offsets).
TEST(VelocityProfile, LinearShearIsRecoveredPerBin) {
  const double y_min = -5.0, y_max = 5.0, g = 0.1, yc = 0.0;
  const int bins = 10, per_bin = 4;
  const double width = (y_max - y_min) / bins;
  GrainSnapshot s;
  for (int b = 0; b < bins; ++b)
    for (int m = 0; m < per_bin; ++m)
      for (int column = 0; column < 3; ++column) {
        const double y = y_min + (b + (m + 0.5) / per_bin) * width;
        s.position.emplace_back(10.0 * column, y);
        s.velocity.emplace_back(g * (y - yc), 0.0);
        s.area.push_back(0.8);
        s.body.push_back("g");
      }
  // A grain in a roughness valley, below the layer: counted apart.
  s.position.emplace_back(0.0, -6.0);
  s.velocity.emplace_back(-1.0, 0.0);
  s.area.push_back(0.8);
  s.body.push_back("g");
  const std::vector<GrainSnapshot> snaps = {s, s};
  const VelocityProfile p = compute_velocity_profile(snaps, y_min, y_max, bins);
  ASSERT_EQ(p.bins.size(), 10u);
  EXPECT_EQ(p.outside, 2u);
  // Sample std of the offsets {-3/8, -1/8, 1/8, 3/8} x width, each appearing 6 times.
  double ss = 0.0;
  for (int m = 0; m < per_bin; ++m)
    ss += std::pow(((m + 0.5) / per_bin - 0.5) * width, 2);
  const double n = 6.0 * per_bin;
  const double offsets_std = std::sqrt(6.0 * ss / (n - 1.0));
  for (const auto& bin : p.bins) {
    EXPECT_EQ(bin.count, 24u);
    // Rounding of a handful of products of O(1) numbers: 1e-14.
    EXPECT_NEAR(bin.vx_mean, g * (bin.y_center - yc), 1e-14);
    EXPECT_NEAR(bin.vx_std, g * offsets_std, 1e-14);
    EXPECT_EQ(bin.vy_mean, 0.0);
    EXPECT_EQ(bin.vy_std, 0.0);
  }
  EXPECT_NEAR(p.bins.front().y_center, -4.5, 1e-15);
}

TEST(VelocityProfile, EmptyBinsAreNanAndLargeDriftKeepsFluctuations) {
  // All grains move at 1e6 +- 1e-3: the std must survive the large common velocity
  // (a naive sum of squares would lose it entirely).
  GrainSnapshot s;
  for (int k = 0; k < 4; ++k) {
    s.position.emplace_back(k, 0.5);
    s.velocity.emplace_back(1e6 + (k % 2 ? 1e-3 : -1e-3), 0.0);
    s.area.push_back(1.0);
    s.body.push_back("g");
  }
  const std::vector<GrainSnapshot> snaps = {s};
  const VelocityProfile p = compute_velocity_profile(snaps, 0.0, 2.0, 2);
  // The inputs 1e6 +- 1e-3 are themselves rounded to ulp(1e6) = 1.2e-10, so that is the
  // accuracy to expect (a raw sum of squares, ~4e12, would keep no digit of 1e-6).
  EXPECT_NEAR(p.bins[0].vx_std, 1e-3 * std::sqrt(4.0 / 3.0), 2.5e-10);
  EXPECT_TRUE(std::isnan(p.bins[1].vx_mean));
  EXPECT_THROW(compute_velocity_profile(snaps, 1.0, 1.0, 2), Error);
}

TEST(SolidFraction, SquarePackingOfDiscsIsPiOverFour) {
  // Discs of diameter d on a square lattice of pitch d fill pi/4 of the plane.
  const double d = 0.5, length = 20.0, height = 5.0;
  GrainSnapshot s;
  for (int i = 0; i < static_cast<int>(length / d); ++i)
    for (int j = 0; j < static_cast<int>(height / d); ++j) {
      s.position.emplace_back((i + 0.5) * d, (j + 0.5) * d);
      s.velocity.emplace_back(0.0, 0.0);
      s.area.push_back(std::numbers::pi * d * d / 4.0);
      s.body.push_back("g");
    }
  EXPECT_NEAR(solid_fraction(s, length, 0.0, height), std::numbers::pi / 4.0, 1e-13);
  const std::vector<GrainSnapshot> snaps = {s, s};
  EXPECT_NEAR(mean_solid_fraction(snaps, length, 0.0, 2.0 * height), std::numbers::pi / 8.0, 1e-13);
  EXPECT_THROW(solid_fraction(s, 0.0, 0.0, 1.0), Error);
}

TEST(VelocityProfile, CsvIsWrittenAtomically) {
  test::ScratchDir dir("profile_csv");
  GrainSnapshot s;
  s.position.emplace_back(0.0, 0.25);
  s.velocity.emplace_back(2.0, 0.0);
  s.area.push_back(1.0);
  s.body.push_back("g");
  const std::vector<GrainSnapshot> snaps = {s};
  const std::string path = dir.file("analysis/profile.csv");
  write_velocity_profile_csv(path, compute_velocity_profile(snaps, 0.0, 1.0, 2));
  std::ifstream in(path);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "y_center,count,vx_mean,vx_std,vy_mean,vy_std");
  EXPECT_EQ(first, "0.25,1,2,0,0,0");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

}  // namespace
}  // namespace sg
