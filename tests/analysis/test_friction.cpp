#include <gtest/gtest.h>

#include <cmath>

#include "analysis/friction.h"
#include "analysis/steady_state.h"
#include "core/error.h"
#include "synthetic.h"

namespace sg {
namespace {

// A shear cell that compacts and then slides steadily. With tau = 10, over t in [0, 300]
// sampled every 0.1 (3001 rows):
//   Fn(t) = 100 + 50 exp(-t/tau) + 2 n1,   Ft(t) = Fn(t) (0.4 - 0.3 exp(-t/tau)) + n2,
// n1, n2 independent standard normal noises. The bottom body receives the opposite force.
// Known answers in steady state: mu = E[Ft]/E[Fn] = 0.4; mu(t) = 0.4 + n2/Fn, so
// std(mu(t)) = 1/100 to first order (the noise of Fn cancels in the ratio).
struct TransientCell {
  Series series;
  static constexpr double tau = 10.0;
};

TransientCell make_transient_cell(std::uint64_t seed) {
  std::vector<double> time;
  for (int i = 0; i <= 3000; ++i)
    time.push_back(0.1 * i);
  TransientCell cell{test::make_series(time)};
  test::Gaussian noise(seed);
  auto& tfx = test::column_values(cell.series, "top_fx");
  auto& tfy = test::column_values(cell.series, "top_fy");
  auto& bfx = test::column_values(cell.series, "bottom_fx");
  auto& bfy = test::column_values(cell.series, "bottom_fy");
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double decay = std::exp(-time[i] / TransientCell::tau);
    const double fn = 100.0 + 50.0 * decay + 2.0 * noise();
    const double ft = fn * (0.4 - 0.3 * decay) + noise();
    tfx[i] = -ft;  // the layer resists the top body, which slides towards +x
    tfy[i] = fn;   // and pushes it up
    bfx[i] = ft;
    bfy[i] = -fn;
  }
  return cell;
}

TEST(SteadyState, MserFindsTheEndOfAStepTransient) {
  // 200 samples offset by 1 (10 noise std), then 1800 stationary samples: MSER-5 must cut
  // at the step, to within one batch.
  test::Gaussian noise(1);
  std::vector<double> signal;
  for (int i = 0; i < 2000; ++i)
    signal.push_back((i < 200 ? 1.0 : 0.0) + 0.1 * noise());
  const MserResult r = mser_truncation(signal, 5);
  EXPECT_GE(r.truncation, 200u);
  EXPECT_LE(r.truncation, 205u);
  EXPECT_FALSE(r.at_limit);
}

TEST(SteadyState, MserKeepsMostOfAStationarySignal) {
  // No transient: MSER may trim a few batches by chance, never a large part.
  test::Gaussian noise(2);
  std::vector<double> signal;
  for (int i = 0; i < 2000; ++i)
    signal.push_back(3.0 + noise());
  EXPECT_LT(mser_truncation(signal, 5).truncation, 200u);
}

TEST(SteadyState, MserFlagsASeriesThatNeverSettles) {
  // A steady drift: every truncation lowers the variance, the minimum sits at half.
  std::vector<double> signal;
  for (int i = 0; i < 1000; ++i)
    signal.push_back(std::exp(-i / 300.0));
  EXPECT_TRUE(mser_truncation(signal, 5).at_limit);
}

TEST(SteadyState, DetectedWindowExcludesTheTransientAndGivesTheKnownFriction) {
  const TransientCell cell = make_transient_cell(42);
  const auto bodies = shear_cell_bodies();
  const TimeWindow w = detect_steady_window(cell.series, bodies);
  EXPECT_TRUE(w.detected);
  EXPECT_FALSE(w.truncation_at_limit);
  // The transient's bias in Ft (~10 exp(-t/tau)) exceeds its noise (1) until
  // t = tau ln 10 = 23, and that of Fn (50 exp(-t/tau)) its noise (2) until tau ln 25 = 32:
  // the window must start after. Keeping data is worth it once the bias is far below the
  // noise: 1% of it by tau ln(5000) = 85, so a start later than 100 wastes the run.
  EXPECT_GT(w.t_begin, 32.0);
  EXPECT_LT(w.t_begin, 100.0);
  EXPECT_EQ(w.t_end, 300.0);

  const FrictionResult f = compute_friction(cell.series, bodies, w, 100.0);
  ASSERT_EQ(f.bodies.size(), 2u);
  // Standard error of mu = Ft_bar/Fn_bar over >= 2000 rows: about
  // sqrt(0.4^2 2^2 + 1)/100/sqrt(2000) = 3e-4; 2e-3 is 7 of them.
  EXPECT_NEAR(f.mean.mu, 0.4, 2e-3);
  // std(mu(t)) = 0.01; its relative standard error 1/sqrt(2N) = 1.6%; allow 5%.
  EXPECT_NEAR(f.mean.mu_std, 0.01, 5e-4);
  // The bottom body receives exactly the opposite force: same statistics, bit for bit
  // up to the summation order.
  EXPECT_NEAR(f.bodies[0].mu, f.bodies[1].mu, 1e-15);
  EXPECT_NEAR(f.bodies[0].mu_std, f.bodies[1].mu_std, 1e-15);
  EXPECT_EQ(f.bodies[0].body, "top");
  // sigma = F / L, exactly.
  EXPECT_DOUBLE_EQ(f.mean.normal_stress, f.mean.normal_force / 100.0);
  EXPECT_DOUBLE_EQ(f.mean.shear_stress, f.mean.tangential_force / 100.0);
  EXPECT_NEAR(f.mean.normal_stress, 1.0, 2e-3);  // Fn_bar = 100 +- 2/sqrt(2000)
}

TEST(SteadyState, GivenWindowIsHonoured) {
  const TransientCell cell = make_transient_cell(7);
  const TimeWindow w = window_from_times(cell.series, 100.0, 250.0);
  EXPECT_FALSE(w.detected);
  EXPECT_NEAR(w.t_begin, 100.0, 1e-9);
  EXPECT_NEAR(w.t_end, 250.0, 1e-9);
  EXPECT_EQ(w.size(), 1501u);
  const auto bodies = shear_cell_bodies();
  EXPECT_NEAR(compute_friction(cell.series, bodies, w, 100.0).mean.mu, 0.4, 3e-3);
  EXPECT_THROW(window_from_times(cell.series, 400.0, 500.0), Error);
}

TEST(SteadyState, WindowWithoutLoadIsRefused) {
  // Fn = 0 in the first rows: mu(t) is undefined there, and the error says so.
  TransientCell cell = make_transient_cell(3);
  test::column_values(cell.series, "top_fy")[10] = 0.0;
  const auto bodies = shear_cell_bodies();
  const TimeWindow w = window_from_times(cell.series, 0.0, 300.0);
  try {
    compute_friction(cell.series, bodies, w, 100.0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("body 'top'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("time 1"), std::string::npos) << e.what();
  }
}

TEST(Dimensionless, PaperDefinitions) {
  RunParameters run;
  run.young_modulus = 10.0;
  run.cohesion = 0.5;
  run.damping_alpha = 0.02;
  run.velocity = 1.0;
  run.gap = 20.0;
  // sigma_n = 0.25: E~ = log10(40), c~ = log10(2), alpha~ = log10(0.001) = -3 (eqs 2-4).
  const DimensionlessParameters p = compute_dimensionless(run, 0.25);
  EXPECT_DOUBLE_EQ(p.stiffness, std::log10(40.0));
  EXPECT_DOUBLE_EQ(p.cohesion, std::log10(2.0));
  EXPECT_NEAR(p.viscosity, -3.0, 1e-15);
  // Unknown inputs give unknown outputs, never a number.
  const DimensionlessParameters q = compute_dimensionless(RunParameters{}, 0.25);
  EXPECT_TRUE(std::isnan(q.stiffness) && std::isnan(q.cohesion) && std::isnan(q.viscosity));
}

}  // namespace
}  // namespace sg
