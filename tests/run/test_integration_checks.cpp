// What a run says about its own time integration (run/integration_checks.h): a fixed step
// beyond the estimated stability limit, and a ledger that leaves more than 1% of the energy the
// run received unexplained.
#include <gtest/gtest.h>

#include "run/integration_checks.h"
#include "scenes/free_grains.h"
#include "solver/stable_time_step.h"

namespace sg {
namespace {

TEST(IntegrationChecks, AFixedStepBeyondTheEstimatedLimitIsWarnedAbout) {
  const Model model = scenes::single_disc(scenes::elastic_material(), 0.5, 0.1);
  const IntegratorParams explicit_integrator;
  const double limit = estimate_stable_time_step(model, 1.0, 0.0, explicit_integrator).dt;
  ASSERT_GT(limit, 0.0);
  const std::string warning = check_fixed_step(1.2 * limit, model, 0.0, explicit_integrator);
  EXPECT_NE(warning.find("fixed_step"), std::string::npos) << warning;
  EXPECT_NE(warning.find("1.2 times the estimated stability limit"), std::string::npos) << warning;
  EXPECT_NE(warning.find("body 'disc'"), std::string::npos) << warning;
  // Within the limit, or no fixed step: nothing to say.
  EXPECT_EQ(check_fixed_step(0.95 * limit, model, 0.0, explicit_integrator), "");
  EXPECT_EQ(check_fixed_step(0.0, model, 0.0, explicit_integrator), "");
}

EnergyLedger ledger(double external_work, double contact_dissipated, double residual) {
  // Closed but for `residual`: the work goes to the bulk damping and the contacts.
  EnergyLedger e;
  e.initial_kinetic = 1.0;  // received: |W_ext| + 1
  e.kinetic = 1.0;
  e.external_work = external_work;
  e.contact_dissipated = contact_dissipated;
  e.damping_dissipated = external_work - contact_dissipated - residual;
  return e;
}

TEST(IntegrationChecks, ALedgerOffByMoreThanOnePercentIsWarnedAbout) {
  // 99 of external work and 1 of initial kinetic energy: 100 received.
  EXPECT_NEAR(ledger(99.0, 10.0, 2.0).residual(), 2.0, 1e-12);
  EXPECT_EQ(check_energy_balance(ledger(99.0, 10.0, 0.9)), "");   // 0.9%: within
  EXPECT_EQ(check_energy_balance(ledger(99.0, 10.0, -0.9)), "");  // either sign
  const std::string off = check_energy_balance(ledger(99.0, 10.0, 2.0));
  EXPECT_NE(off.find("off by 2% of the energy the run received"), std::string::npos) << off;
  EXPECT_EQ(off.find("gave back"), std::string::npos) << off;
  EXPECT_NE(check_energy_balance(ledger(99.0, 10.0, -2.0)).find("off by -2%"), std::string::npos);
  // The tolerance is a parameter.
  EXPECT_NE(check_energy_balance(ledger(99.0, 10.0, 0.9), 0.005), "");
  // Nothing received, nothing to compare with.
  EXPECT_EQ(check_energy_balance(EnergyLedger{}), "");
}

TEST(IntegrationChecks, ContactsThatGaveEnergyBackAreNamed) {
  // The 400-grain imex cell at 1.5 times its estimated step: contact dissipation -71 of 301.
  const std::string off = check_energy_balance(ledger(300.0, -71.0, 84.0));
  EXPECT_NE(off.find("the contacts gave back 71 more than they took"), std::string::npos) << off;
  // A small negative contact dissipation (within the tolerance) is the trapezoid's error, not
  // named.
  EXPECT_EQ(check_energy_balance(ledger(300.0, -2.0, 10.0)).find("gave back"), std::string::npos);
}

}  // namespace
}  // namespace sg
