// Self-affine rough surfaces: RMS, zero mean, periodicity, spectral slope, determinism,
// and the first-body strip polygon built on them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "geometry/rough_surface.h"

namespace sg {
namespace {

// periodogram and fit_spectral_slope (geometry/rough_surface.h) are a direct DFT and a
// least-squares fit, independent of the generator's synthesis; `softgrain generate` reports
// the same measure of the built first bodies.

double rms_of(const std::vector<double>& y) {
  double s = 0.0;
  for (double v : y)
    s += v * v;
  return std::sqrt(s / static_cast<double>(y.size()));
}

class HurstTest : public ::testing::TestWithParam<double> {};

TEST_P(HurstTest, RandomPhaseProfileHasExactRmsMeanAndSlope) {
  RoughSurfaceDef def;  // paper 001: L = 100, RMS 1
  def.hurst = GetParam();
  def.points = 1024;
  const RoughProfile p = make_rough_profile(def, 17);
  ASSERT_EQ(p.heights.size(), 1024u);
  EXPECT_DOUBLE_EQ(p.spacing(), 100.0 / 1024.0);
  EXPECT_NEAR(rms_of(p.heights), 1.0, 1e-12);
  double mean = 0.0;
  for (double v : p.heights)
    mean += v / 1024.0;
  EXPECT_NEAR(mean, 0.0, 1e-12);
  // Amplitudes exactly on the power law: the fitted slope is -(1 + 2H) up to rounding.
  const std::vector<double> power = periodogram(p.heights);
  const SpectralSlopeFit fit = fit_spectral_slope(power, 1, 511);
  std::printf("H = %.2f: periodogram slope %.12f (exact %.12f)\n", def.hurst, fit.slope,
              -(1.0 + 2.0 * def.hurst));
  EXPECT_NEAR(fit.slope, -(1.0 + 2.0 * def.hurst), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Hurst, HurstTest, ::testing::Values(0.3, 0.5, 0.8));

TEST(RoughSurface, GaussianProfileSlopeWithinFourStandardErrors) {
  RoughSurfaceDef def;
  def.hurst = 0.7;
  def.points = 4096;
  def.rms = 0.5;
  def.sampling = RoughSpectrumSampling::gaussian;
  const RoughProfile p = make_rough_profile(def, 5);
  EXPECT_NEAR(rms_of(p.heights), 0.5, 1e-12);
  const std::vector<double> power = periodogram(p.heights);
  const SpectralSlopeFit fit = fit_spectral_slope(power, 1, 2047);
  // ln P_k = ln(c k^-(1+2H)) + ln(chi^2_2 / 2): exponential scatter, variance pi^2/6 per
  // mode, hence the standard error of the fitted slope (about 0.03 for 2047 modes).
  std::printf("gaussian H = 0.7: slope %.4f, exact %.4f, standard error %.4f\n", fit.slope, -2.4,
              fit.standard_error_if_exponential);
  EXPECT_NEAR(fit.slope, -2.4, 4.0 * fit.standard_error_if_exponential);
}

TEST(RoughSurface, ExactlyPeriodicBandLimitedTrigonometricSum) {
  // Only the requested modes carry power: y is a trigonometric polynomial of period L, so
  // y(L) = y(0) and every derivative matches across the seam. With max_mode = 64 on 512
  // points, the modes 65 .. 256 and the mean (k = 0) must be empty to rounding.
  RoughSurfaceDef def;
  def.points = 512;
  def.min_mode = 2;
  def.max_mode = 64;
  const RoughProfile p = make_rough_profile(def, 3);
  const std::vector<double> power = periodogram(p.heights);
  double total = 0.0, outside = 0.0;
  for (std::size_t k = 0; k < power.size(); ++k) {
    total += power[k];
    if (k < 2 || k > 64) outside += power[k];
  }
  EXPECT_LT(outside, 1e-24 * total);
  // The jump across the seam, y(0) - y(L - dx), is an ordinary increment: no larger than
  // the largest increment inside the profile.
  double largest = 0.0;
  for (std::size_t j = 0; j + 1 < p.heights.size(); ++j)
    largest = std::max(largest, std::abs(p.heights[j + 1] - p.heights[j]));
  EXPECT_LE(std::abs(p.heights.front() - p.heights.back()), largest);
}

TEST(RoughSurface, DeterministicForASeed) {
  RoughSurfaceDef def;
  def.points = 256;
  EXPECT_EQ(make_rough_profile(def, 1).heights, make_rough_profile(def, 1).heights);
  EXPECT_NE(make_rough_profile(def, 1).heights, make_rough_profile(def, 2).heights);
}

TEST(RoughSurface, InvalidDefinitionsAreRejected) {
  RoughSurfaceDef def;
  def.hurst = 1.2;
  EXPECT_THROW(make_rough_profile(def, 1), Error);
  def = RoughSurfaceDef{};
  def.max_mode = 600;  // above N/2 - 1 = 511
  EXPECT_THROW(make_rough_profile(def, 1), Error);
}

TEST(FirstBodyStrip, BottomAndTopBodiesAreSimpleCcwAndCarryTheProfile) {
  RoughSurfaceDef def;
  def.points = 256;
  def.length = 20.0;
  def.rms = 0.3;
  const RoughProfile p = make_rough_profile(def, 9);
  for (FirstBodySide side : {FirstBodySide::bottom, FirstBodySide::top}) {
    const double mean_y = side == FirstBodySide::bottom ? 0.0 : 10.0;
    const FirstBodyStrip s = make_first_body_strip(p, side, mean_y, 3.0);
    EXPECT_TRUE(is_counter_clockwise(s.contour));
    EXPECT_FALSE(is_self_intersecting(s.contour));
    ASSERT_EQ(s.surface_count, 257);
    // Area: L * thickness, plus (bottom) or minus (top) the integral of h, which is zero
    // (zero-mean samples, trapezoid rule on a periodic function).
    EXPECT_NEAR(signed_area(s.contour), 20.0 * 3.0, 1e-9);
    const bool bottom = side == FirstBodySide::bottom;
    for (int i = 0; i < s.surface_count; ++i) {
      const Vec2& v = s.contour[static_cast<std::size_t>(s.surface_begin + i)];
      const int j = bottom ? 256 - i : i;  // bottom surface runs x = L .. 0
      EXPECT_NEAR(v.x(), j * p.spacing(), 1e-12);
      EXPECT_EQ(v.y(), mean_y + p.heights[static_cast<std::size_t>(j % 256)]);
    }
    // The two ends meet across the periodic boundary at the same height.
    const Vec2& first = s.contour[static_cast<std::size_t>(s.surface_begin)];
    const Vec2& last = s.contour[static_cast<std::size_t>(s.surface_begin + 256)];
    EXPECT_EQ(first.y(), last.y());
    EXPECT_NEAR(std::abs(first.x() - last.x()), 20.0, 1e-12);
  }
  EXPECT_THROW(make_first_body_strip(p, FirstBodySide::bottom, 0.0, 0.1), Error);
}

}  // namespace
}  // namespace sg
