#include <gtest/gtest.h>

#include "analysis/energy_budget.h"
#include "analysis/run_parameters.h"
#include "core/error.h"
#include "synthetic.h"

namespace sg {
namespace {

// Cumulative dissipations with known rates: during the transient (t < 50) contacts
// dissipate 5 per unit time and damping 1; afterwards damping 3 and contacts 1. Over a
// window inside the steady part p_wb = 3/4, p_ws = 1/4 exactly (linear data, so the
// increments are exact up to rounding of the cumulative values, ~1e-15 relative).
Series make_budget_series() {
  std::vector<double> time;
  for (int i = 0; i <= 300; ++i)
    time.push_back(i);
  Series s = test::make_series(time);
  auto& damp = test::column_values(s, "damping_dissipation");
  auto& cont = test::column_values(s, "contact_dissipation");
  auto& work = test::column_values(s, "external_work");
  auto& residual = test::column_values(s, "energy_residual");
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double t = time[i];
    damp[i] = t < 50 ? t : 50 + 3 * (t - 50);
    cont[i] = t < 50 ? 5 * t : 250 + (t - 50);
    // The driving works at 6 while the layer stores energy, then at 4 = dissipation.
    work[i] = t < 50 ? 6 * t : 300 + 4 * (t - 50);
    residual[i] = 1e-3 * t;
  }
  return s;
}

TEST(EnergyBudget, SharesAndPartialFrictionsOverTheWindow) {
  const Series s = make_budget_series();
  const TimeWindow w = window_from_times(s, 100.0, 300.0);
  const double mu = 0.4, fn = 100.0, v = 0.1;
  const EnergyBudget e = compute_energy_budget(s, w, mu, fn, v);
  EXPECT_DOUBLE_EQ(e.duration, 200.0);
  EXPECT_NEAR(e.bulk_share, 0.75, 1e-14);
  EXPECT_NEAR(e.contact_share, 0.25, 1e-14);
  EXPECT_NEAR(e.bulk_share + e.contact_share, 1.0, 1e-15);
  EXPECT_NEAR(e.bulk_friction, 0.3, 1e-14);     // mu_b = p_wb mu, paper 001 eq. 5
  EXPECT_NEAR(e.contact_friction, 0.1, 1e-14);  // mu_s = p_ws mu, eq. 6
  EXPECT_NEAR(e.bulk_power, 3.0, 1e-13);
  EXPECT_NEAR(e.contact_power, 1.0, 1e-13);
  // Power balance: dissipation 4 = P_ext 4 = mu Fn V = 0.4 x 100 x 0.1: both checks give mu.
  EXPECT_NEAR(e.mu_from_dissipation, 0.4, 1e-13);
  EXPECT_NEAR(e.mu_from_work, 0.4, 1e-13);
  EXPECT_NEAR(e.residual_drift, 0.2, 1e-13);
  // A window reaching into the transient sees the transient's shares: the window matters.
  const EnergyBudget early = compute_energy_budget(s, window_from_times(s, 0.0, 100.0), mu, fn, v);
  EXPECT_NEAR(early.bulk_share, (50.0 + 150.0) / (50.0 + 150.0 + 250.0 + 50.0), 1e-14);
  // Unknown V: the checks are unknown, the shares are not.
  const EnergyBudget no_v = compute_energy_budget(s, w, mu, fn, RunParameters::kUnknown);
  EXPECT_TRUE(std::isnan(no_v.mu_from_work));
  EXPECT_NEAR(no_v.bulk_share, 0.75, 1e-14);
}

TEST(EnergyBudget, BrokenBookkeepingIsRefused) {
  Series s = make_budget_series();
  const TimeWindow w = window_from_times(s, 100.0, 300.0);
  auto& damp = test::column_values(s, "damping_dissipation");
  auto& cont = test::column_values(s, "contact_dissipation");
  // No dissipation at all over the window: the shares are 0/0.
  for (std::size_t i = 0; i < damp.size(); ++i)
    damp[i] = cont[i] = 1.0;
  EXPECT_THROW(compute_energy_budget(s, w, 0.4, 100.0, 0.1), Error);
  // A cumulative dissipation that decreases.
  damp[300] = 0.0;
  EXPECT_THROW(compute_energy_budget(s, w, 0.4, 100.0, 0.1), Error);
}

}  // namespace
}  // namespace sg
