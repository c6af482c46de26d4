// Whole runs with F-bar grains (`volumetric = "fbar"`, material.h VolumetricFormulation): the
// energy ledger closes on a short shear cell (explicit and IMEX), a run is bitwise the same on
// 1 and 2 threads and after a stop and resume, and the locking problem of
// studies/locking (docs/verification.md "Locking at large strain") shows the cure.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/scenario_run.h"
#include "scenes/series_text.h"
#include "scenes/shear_cell_scenario.h"
#include "test_locations.h"  // SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;

// `text` with `volumetric = "fbar"` added to the material named `material`.
std::string with_fbar(std::string text, const std::string& material) {
  const std::string key = "name = \"" + material + "\"\n";
  const std::size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos) << key;
  return text.insert(at + key.size(), "volumetric = \"fbar\"\n");
}

// A small cohesive shear cell of F-bar grains (nu = 0.495): compaction, then shear.
std::string fbar_cell(const std::string& name, bool imex, double damping, double duration) {
  scenes::CohesiveShearCell c;
  c.name = name;
  c.poisson = 0.495;
  c.damping = damping;
  c.duration = duration;
  c.extra_time = imex ? "integrator = \"imex\"\n" : "integrator = \"explicit\"\n";
  c.checkpoint_period = duration / 3.0;
  c.compaction_time = 0.3 * duration;
  c.velocity = 2.0;
  c.grains = 10;
  return with_fbar(scenes::shear_cell_scenario(c), "soft");
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The ledger at the end of the run: W_ext = dK + dE_el(F_bar) + D_bulk + D_contact.
void expect_ledger_closes(const std::string& tag, bool imex, double damping, double tolerance) {
  const fs::path dir = scenes::process_temp_dir("fbar_ledger_" + tag);
  const RunSummary summary =
      scenes::run_scenario_text(dir, "cell.toml", fbar_cell("cell", imex, damping, 3.0), 2);
  ASSERT_TRUE(summary.completed);
  const scenes::SeriesText s = scenes::read_series_text(summary.directory / "series.csv");
  ASSERT_GT(s.rows.size(), 100u);
  const auto [work, residual, bulk] = scenes::final_ledger(s);
  std::printf(
      "F-bar cell, %s, alpha %.2f: external work %.5g, bulk dissipation %.5g, residual "
      "%.3g (%.4f%%)\n",
      tag.c_str(), damping, work, bulk, residual, 100.0 * residual / work);
  EXPECT_GT(work, 0.1);
  EXPECT_GT(bulk, 0.0);
  EXPECT_LT(std::abs(residual), tolerance * work);
  fs::remove_all(dir);
}

TEST(FBarRun, ExplicitLedgerClosesOnAShearCell) {
  // The standard cells close within 1% (test_shear_cell_run.cpp); measured here 0.0022%.
  expect_ledger_closes("explicit", false, 0.01, 0.01);
}

TEST(FBarRun, ImexLedgerClosesOnAShearCell) {
  // The standard IMEX cell closes within 0.1% (test_shear_cell_run.cpp); measured here 0.084%.
  expect_ledger_closes("imex", true, 0.3, 0.001);
}

// Every file of run folder `a` but run.log and run.lock is in `b` with the same bytes.
int expect_same_files(const fs::path& a, const fs::path& b) {
  int compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), a);
    if (relative == "run.log" || relative == "run.lock") continue;
    EXPECT_TRUE(fs::exists(b / relative)) << relative;
    EXPECT_TRUE(read_bytes(entry.path()) == read_bytes(b / relative)) << relative << " differs";
    ++compared;
  }
  return compared;
}

TEST(FBarRun, OneAndTwoThreadsAndARestartGiveTheSameBits) {
  const std::string text = fbar_cell("cell", false, 0.01, 0.6);
  auto dir = [](const std::string& tag) { return scenes::process_temp_dir("fbar_bits_" + tag); };
  const RunSummary two = scenes::run_scenario_text(dir("two"), "cell.toml", text, 2);
  const RunSummary one = scenes::run_scenario_text(dir("one"), "cell.toml", text, 1);
  ASSERT_TRUE(two.completed && one.completed);
  EXPECT_GE(expect_same_files(two.directory, one.directory), 3);
  // Stopped after the first checkpoint, then resumed.
  const RunSummary stopped =
      scenes::run_scenario_text(dir("resumed"), "cell.toml", text, 2, two.steps / 2);
  EXPECT_FALSE(stopped.completed);
  EXPECT_GE(stopped.checkpoints_written, 1);
  const RunSummary resumed =
      scenes::run_scenario_text(dir("resumed"), "cell.toml", text, 2, -1, true);
  EXPECT_TRUE(resumed.completed);
  EXPECT_GT(resumed.resumed_from_step, 0);
  EXPECT_GE(expect_same_files(two.directory, resumed.directory), 3);
  // The option is in force: the same cell with standard grains differs.
  std::string standard = text;
  standard.erase(standard.find("volumetric = \"fbar\"\n"), 20);
  const RunSummary plain = scenes::run_scenario_text(dir("standard"), "cell.toml", standard, 2);
  EXPECT_NE(read_bytes(two.directory / "series.csv"), read_bytes(plain.directory / "series.csv"));
  for (const char* tag : {"two", "one", "resumed", "standard"})
    fs::remove_all(dir(tag));
}

// The study's problem (tests/scenario/test_locking_disc.cpp: nu = 0.495, D/8, 3 Gauss points,
// squeezed to 20% and 35%) with F-bar grains.
TEST(FBarRun, LockingDiscIsCured) {
  const fs::path scenario =
      fs::path(SOFTGRAIN_SOURCE_DIR) / "studies" / "locking" / "disc-between-plates.toml";
  const fs::path dir = scenes::process_temp_dir("fbar_locking");
  const RunSummary summary =
      scenes::run_scenario_text(dir, "disc.toml", with_fbar(read_bytes(scenario), "disc"), 1);
  const scenes::SeriesText s = scenes::read_series_text(summary.directory / "series.csv");
  const std::size_t time = s.column("time"), top = s.column("top_fy"),
                    bottom = s.column("bottom_fy");
  // The standard formulation's D/48 forces (the study's reference) and the errors the study
  // measured for this run: +2.9% and +6.2%, where the standard run is +12.1% and +10.5%
  // (locking: 10 and 8 points above nu = 0.3's +2.2% and +2.4%). The band is one point, as in
  // test_locking_disc.cpp: a ninth (20%) and a quarter (35%) of what F-bar removes.
  const double reference[2] = {0.150441, 0.464951};
  const double measured_error[2] = {0.0293, 0.0624};
  for (int k = 0; k < 2; ++k) {
    const double end = 20.0 * (k + 1);
    double force = 0.0;
    int count = 0;
    for (const std::vector<double>& row : s.rows)
      if (row[time] >= end - 2.0 && row[time] < end) {
        force += 0.5 * (row[top] - row[bottom]);
        ++count;
      }
    ASSERT_GT(count, 0);
    force /= count;
    const double error = force / reference[k] - 1.0;
    std::printf("F-bar disc, stage %d: force %.6f, error against the standard D/48 %+.2f%%\n", k,
                force, 100.0 * error);
    EXPECT_NEAR(error, measured_error[k], 0.01) << "stage " << k;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sg
