#include <gtest/gtest.h>

#include <cmath>

#include "analysis/activated_thickness.h"
#include "core/error.h"
#include "synthetic.h"

namespace sg {
namespace {

// A layer of thickness H between y = 0 and y = H: N rows of equal grains, `columns` per row,
// row centres at (r + 1/2) H / N, each row moving at vx = velocity(u_r) with u_r its share of
// the jump from v_bottom to v_top.
template <typename Share>
GrainSnapshot layer(int rows, int columns, double H, double v_bottom, double v_top, Share share) {
  GrainSnapshot s;
  for (int r = 0; r < rows; ++r) {
    const double y = (r + 0.5) * H / rows;
    const double u = share(y / H);
    for (int c = 0; c < columns; ++c) {
      s.position.emplace_back(c + 0.5, y);
      s.velocity.emplace_back(v_bottom + u * (v_top - v_bottom), 0.01 * c);
      s.area.push_back(0.7);
      s.body.push_back(std::to_string(r * columns + c));
    }
  }
  return s;
}

// Couette: u = y / H. The grains whose centre lies in [0.2 H, 0.8 H] are 60% of the matter
// up to one row (1/N of H), and the profile's bins aligned on 0.2 H and 0.8 H give 0.6 H.
TEST(ActivatedThickness, CouetteProfileGivesSixtyPercentOfTheGap) {
  const double H = 8.0, vb = -0.5, vt = 0.5;
  const int rows = 1000;
  const GrainSnapshot s = layer(rows, 3, H, vb, vt, [](double y) { return y; });
  EXPECT_NEAR(activated_thickness_from_grains(s, vb, vt, H), 0.6 * H, H / rows);
  for (int bins : {10, 20, 40}) {
    const VelocityProfile p =
        compute_velocity_profile(std::span<const GrainSnapshot>(&s, 1), 0.0, H, bins);
    EXPECT_NEAR(activated_thickness_from_profile(p, vb, vt), 0.6 * H, 1e-9) << bins << " bins";
  }
  // Other thresholds: 10%-90% is 80% of the gap.
  const AttThresholds wide{0.1, 0.9};
  EXPECT_NEAR(activated_thickness_from_grains(s, vb, vt, H, wide), 0.8 * H, H / rows);
  // The direction of the jump does not matter (u is a share of it).
  EXPECT_NEAR(activated_thickness_from_grains(s, vt, vb, H), 0.6 * H, H / rows);
}

// Plug flow: everything below y = 4 moves with the bottom, everything above 5 with the top,
// the band [4, 5] (two rows of a 16-row layer of H = 8) at half the jump. Both measures give
// the band's thickness, 1.
TEST(ActivatedThickness, PlugFlowWithAThinBandGivesTheBandsThickness) {
  const double H = 8.0, vb = 0.0, vt = 2.0;
  const auto share = [](double y) { return y < 0.5 ? 0.0 : y < 0.625 ? 0.5 : 1.0; };
  const GrainSnapshot s = layer(16, 10, H, vb, vt, share);
  EXPECT_NEAR(activated_thickness_from_grains(s, vb, vt, H), 1.0, 1e-12);
  const VelocityProfile p =
      compute_velocity_profile(std::span<const GrainSnapshot>(&s, 1), 0.0, H, 16);
  EXPECT_NEAR(activated_thickness_from_profile(p, vb, vt), 1.0, 1e-12);
  // The series: two snapshots, the band twice as thick in the second.
  GrainSnapshot wider = layer(16, 10, H, vb, vt, [](double y) {
    return y < 0.375 ? 0.0 : y < 0.625 ? 0.4 : 1.0;
  });
  wider.time = 1.0;
  const std::vector<GrainSnapshot> frames = {s, wider};
  const AttSeries series = activated_thickness_series(frames, vb, vt, H, 0.0, H, 16, {});
  ASSERT_EQ(series.samples.size(), 2u);
  EXPECT_NEAR(series.samples[1].from_grains, 2.0, 1e-12);
  EXPECT_NEAR(series.samples[1].from_profile, 2.0, 1e-12);
  EXPECT_NEAR(series.mean_from_grains, 1.5, 1e-12);
  EXPECT_NEAR(series.mean_from_profile, 1.5, 1e-12);
}

TEST(ActivatedThickness, RefusesAMissingJumpOrBadThresholds) {
  const GrainSnapshot s = layer(4, 2, 1.0, 0.0, 1.0, [](double y) { return y; });
  EXPECT_THROW(activated_thickness_from_grains(s, 1.0, 1.0, 1.0), Error);
  EXPECT_THROW(activated_thickness_from_grains(s, 0.0, 1.0, 1.0, {0.8, 0.2}), Error);
  EXPECT_THROW(activated_thickness_from_grains(s, 0.0, 1.0, 0.0), Error);
}

}  // namespace
}  // namespace sg
