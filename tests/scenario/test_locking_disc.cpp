// Volumetric locking at large strain (issue #31 item 2): the study's problem at the papers'
// Poisson ratio and node spacing, as a regression test.
//
// studies/locking/disc-between-plates.toml (written by studies/locking/locking_study.py
// scenario; the study and docs/verification.md "Locking at large strain" give every number
// below): an elastic neo-Hookean disc (D = 1, E = 1, nu = 0.495, 3 Gauss points per triangle,
// node spacing D/8) squeezed between two rigid rough (no-slip) plates to 20% and then 35% of
// its diameter, each stage a slow velocity pulse followed by a hold; the plate force is the
// mean over the end of each hold. About 7000 steps of 72 nodes: under a second.
//
// Locking is the error that grows with nu at a fixed spacing: at D/8 the force is 12% (20%)
// and 10% (35%) above the converged one at nu = 0.495, against 2% at nu = 0.3. The test
// compares the force with the study's finest run at nu = 0.495 and requires the error to stay
// within one point of what the study measured. A change that stiffens nearly incompressible
// grains further (a coarser contour, a lower-order quadrature, a lost MLS consistency) moves it
// out of the band; so does a cure of the locking, after which the band is to be re-measured.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/series_text.h"
#include "test_locations.h"  // SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;

const fs::path kScenario =
    fs::path(SOFTGRAIN_SOURCE_DIR) / "studies" / "locking" / "disc-between-plates.toml";

// The stages of the scenario: each ends at (k + 1) * kStageTime with its hold; the force is
// averaged over the hold's last kAverageTime (as locking_study.py does).
constexpr double kStageTime = 20.0;
constexpr double kAverageTime = 2.0;

struct HoldReading {
  double compression = 0.0;    // plate approach / D at the end of the hold
  double force = 0.0;          // mean plate force per unit length over the end of the hold
  double kinetic_ratio = 0.0;  // kinetic / elastic energy at the end of the hold
};

std::vector<HoldReading> read_holds(const scenes::SeriesText& s) {
  const std::size_t time = s.column("time"), top_fy = s.column("top_fy"),
                    bottom_fy = s.column("bottom_fy"), top_y = s.column("top_y"),
                    bottom_y = s.column("bottom_y"), kinetic = s.column("kinetic_energy"),
                    elastic = s.column("elastic_energy");
  const double gap0 = s.rows.front()[top_y] - s.rows.front()[bottom_y];
  std::vector<HoldReading> out;
  for (int k = 0; k < 2; ++k) {
    const double end = (k + 1) * kStageTime;
    HoldReading h;
    int count = 0;
    const std::vector<double>* last = nullptr;
    for (const std::vector<double>& row : s.rows) {
      if (row[time] < end - kAverageTime || row[time] >= end) continue;
      h.force += 0.5 * (row[top_fy] - row[bottom_fy]);
      ++count;
      last = &row;
    }
    if (count == 0) {
      ADD_FAILURE() << "no series row in the hold ending at " << end;
      return out;
    }
    h.force /= count;
    h.compression = gap0 - ((*last)[top_y] - (*last)[bottom_y]);
    h.kinetic_ratio = (*last)[kinetic] / (*last)[elastic];
    out.push_back(h);
  }
  return out;
}

TEST(Locking, NearlyIncompressibleDiscSqueezedToLargeStrainStaysInTheStudysBand) {
  const fs::path dir = scenes::process_temp_dir("locking_disc");
  RunOptions options;
  options.output_root_override = dir;
  const RunSummary summary = run_scenario(load_scenario(kScenario), options);
  const std::vector<HoldReading> holds =
      read_holds(scenes::read_series_text(summary.directory / "series.csv"));
  ASSERT_EQ(holds.size(), 2u);

  // The study's reference at nu = 0.495, 3 Gauss points: the finest run, D/48 (2082 nodes;
  // at 20% the Richardson extrapolation of D/24, 32, 48 is 0.17% below it). The study measured
  // this run's error against it at +12.11% (20%) and +10.49% (35%), where nu = 0.3 gives +2.2%
  // and +2.4% at the same spacing: about 10 and 8 points of locking. The band is the measured
  // error +- 1 point: a tenth of the locking, three times the scatter between neighbouring
  // spacings at nu = 0.3 (0.3%), below the 1.5-point change 6 Gauss points make at D/8.
  const double reference[2] = {0.150441, 0.464951};
  const double measured_error[2] = {0.1211, 0.1049};
  const double band = 0.01;
  const double target[2] = {0.20, 0.35};
  for (std::size_t k = 0; k < 2; ++k) {
    const double error = holds[k].force / reference[k] - 1.0;
    std::printf("compression %.5f: force %.6f, reference %.6f, error %+.2f%%, K/E %.1e\n",
                holds[k].compression, holds[k].force, reference[k], 100.0 * error,
                holds[k].kinetic_ratio);
    // The plates reach the stage's approach (the drive's knots fall between steps).
    EXPECT_NEAR(holds[k].compression, target[k], 1e-3 * target[k]);
    // Quasi-static: the disc is at rest at the end of each hold.
    EXPECT_LT(holds[k].kinetic_ratio, 1e-6);  // measured 2.6e-9 and 3e-16
    EXPECT_NEAR(error, measured_error[k], band) << "stage " << k;
  }
}

}  // namespace
}  // namespace sg
