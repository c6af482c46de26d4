// Pressure loading (analysis/pressure_loading.h): E~ and c~ take sigma_n = p, the stress
// imposed on the loaded first body, rather than the measured mean of the top and the bottom;
// the loaded body's measured stress is checked against p; summary.json says which sigma_n the
// coordinates use.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "analysis/friction.h"
#include "analysis/pressure_loading.h"
#include "analysis/summary.h"

namespace sg {
namespace {

FrictionResult stresses(double top, double bottom) {
  FrictionResult r;
  FrictionStats t, b;
  t.body = "top";
  t.normal_stress = top;
  b.body = "bottom";
  b.normal_stress = bottom;
  r.bodies = {t, b};
  r.mean.body = "mean";
  r.mean.normal_stress = 0.5 * (top + bottom);
  return r;
}

TEST(PressureLoading, CoordinatesTakeTheImposedPressureNotTheMeasuredMean) {
  // A settling layer (issue #29): top 1.0, bottom 0.6, mean 0.8, under p = 1.
  const FrictionResult f = stresses(1.0, 0.6);
  RunParameters run;
  run.young_modulus = 10.0;
  run.cohesion = 0.1;
  const DimensionlessParameters imposed =
      compute_dimensionless(run, coordinate_normal_stress(1.0, f.mean.normal_stress));
  EXPECT_DOUBLE_EQ(imposed.stiffness, 1.0);  // log10(10 / 1)
  EXPECT_DOUBLE_EQ(imposed.cohesion, -1.0);  // log10(0.1 / 1)
  // The mean would have put them log10(1 / 0.8) = 0.097 higher.
  const DimensionlessParameters measured =
      compute_dimensionless(run, coordinate_normal_stress(RunParameters::kUnknown, 0.8));
  EXPECT_NEAR(measured.stiffness - imposed.stiffness, std::log10(1.0 / 0.8), 1e-12);
  // Gap loading (no p, or p = 0): the measured mean, as paper 001 §2.3.
  EXPECT_DOUBLE_EQ(coordinate_normal_stress(RunParameters::kUnknown, 0.8), 0.8);
  EXPECT_DOUBLE_EQ(coordinate_normal_stress(0.0, 0.8), 0.8);
}

TEST(PressureLoading, ALayerTheServoHasNotLoadedIsFlagged) {
  // Issue #29: the top crept down and carried a fraction of p over the window.
  const auto creeping = check_imposed_pressure(stresses(0.14, 0.10), 1.0, 0.1);
  ASSERT_TRUE(creeping);
  EXPECT_EQ(creeping->check, "pressure_not_reached");
  EXPECT_NE(creeping->message.find("0.14"), std::string::npos) << creeping->message;
  EXPECT_NE(creeping->message.find("-86%"), std::string::npos) << creeping->message;
  // Loaded: within 10% of p (the bottom's own stress is the stress_imbalance check's).
  EXPECT_FALSE(check_imposed_pressure(stresses(0.93, 0.55), 1.0, 0.1));
  EXPECT_FALSE(check_imposed_pressure(stresses(1.09, 1.0), 1.0, 0.1));
  EXPECT_TRUE(check_imposed_pressure(stresses(1.11, 1.0), 1.0, 0.1));
  // No p (gap loading) or no stress of the top: nothing to check.
  EXPECT_FALSE(check_imposed_pressure(stresses(0.1, 0.1), RunParameters::kUnknown, 0.1));
  EXPECT_FALSE(check_imposed_pressure(stresses(RunParameters::kUnknown, 0.1), 1.0, 0.1));
}

TEST(PressureLoading, SummaryGivesThePressureAndWhichStressTheCoordinatesUse) {
  AnalysisSummary s;
  s.friction = stresses(0.98, 0.9);
  s.imposed_pressure = 1.0;
  const nlohmann::json doc = nlohmann::json::parse(summary_json(s));
  const auto& q = doc["quantities"];
  EXPECT_EQ(q["imposed_pressure"]["value"], 1.0);
  EXPECT_EQ(q["imposed_pressure"]["unit"], "stress");
  // Each first body's measured sigma_n beside it.
  EXPECT_EQ(q["top_normal_stress"]["value"], 0.98);
  EXPECT_EQ(q["bottom_normal_stress"]["value"], 0.9);
  const std::string def = q["stiffness_tilde"]["definition"];
  EXPECT_NE(def.find("imposed_pressure"), std::string::npos) << def;
  // Under gap loading: null, and the coordinates say they use the measured mean.
  s.imposed_pressure = RunParameters::kUnknown;
  const nlohmann::json gap = nlohmann::json::parse(summary_json(s));
  EXPECT_TRUE(gap["quantities"]["imposed_pressure"]["value"].is_null());
  const std::string gap_def = gap["quantities"]["cohesion_tilde"]["definition"];
  EXPECT_NE(gap_def.find("measured mean"), std::string::npos) << gap_def;
}

}  // namespace
}  // namespace sg
