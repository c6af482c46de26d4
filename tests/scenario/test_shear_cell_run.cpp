// A whole small shear-cell run through `softgrain run`'s engine (run_scenario): the issue's
// acceptance tests for the energy balance and steady shear (issue #4).
//
//   - energy balance: W_ext = dK + dE_el + D_bulk + D_contact within 1% of W_ext at the end;
//   - steady shear: after compaction the friction coefficient mu = -<F_x>/<F_y> of the top
//     first body lies in [0.1, 1.1] over both quarters of the second half of the run, and the
//     normal force has settled (the two quarters' mean normal forces agree within 25%);
//   - the run folder's series.csv is byte-identical on 1 and 2 threads;
//   - under the IMEX integrator at alpha = 0.3, the same balance within 0.1%.
//
// The cell: L = 14, 40 soft cohesive grains (E = 10, c = 0.1, alpha = 0.01), fixed gap 3,
// compaction 3 time units then V = 1 for 9. Measured (2-core x86-64, g++ 12, 2026-12-02):
// residual 0.010% of W_ext (it was 9% before the periodic-image and time-centred-release fixes
// of contact_system.cpp / contact_law.cpp), mu 0.2729 and 0.1293, normal force 5.17 and 4.79
// over t in [6, 9) and [9, 12).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/scenario_run.h"
#include "scenes/series_text.h"
#include "scenes/shear_cell_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// The cell; `imex` integrates the grains' damping implicitly (integrator = "imex").
std::string cell_scenario(double damping = 0.01, bool imex = false,
                          const std::string& time_keys = "",
                          const std::string& damping_model = "") {
  scenes::CohesiveShearCell c;
  c.damping = damping;
  c.damping_model = damping_model;
  if (imex) c.extra_time = "integrator = \"imex\"\n" + time_keys;
  c.duration = 12.0;
  c.series_period = 0.02;
  c.field_period = 6.0;
  c.node_spacing = 0.2;
  c.length = 14.0;
  c.grains = 40;
  c.roughness_rms = 0.3;
  c.gap = 3.0;
  c.compaction_time = 3.0;
  c.seed = 1;
  return scenes::shear_cell_scenario(c);
}

using Series = scenes::SeriesText;

Series run_cell(int threads, double damping = 0.01, bool imex = false) {
  const fs::path dir =
      scenes::process_temp_dir("cell_" + std::to_string(threads) + (imex ? "_imex" : ""));
  scenes::run_scenario_text(dir, "cell.toml", cell_scenario(damping, imex), threads);

  Series s = scenes::read_series_text(dir / "out" / "cell" / "series.csv");
  fs::remove_all(dir);
  return s;
}

struct Friction {
  double mu = 0.0, normal = 0.0;
};

Friction friction_over(const Series& s, double t0, double t1) {
  const std::size_t t = s.column("time"), fx = s.column("top_fx"), fy = s.column("top_fy");
  double sum_x = 0.0, sum_y = 0.0;
  int n = 0;
  for (const auto& row : s.rows)
    if (row[t] >= t0 && row[t] < t1) {
      sum_x += row[fx];
      sum_y += row[fy];
      ++n;
    }
  return {-sum_x / sum_y, sum_y / n};
}

TEST(ShearCellRun, EnergyBalanceSteadyFrictionAndThreadIndependence) {
  const Series one = run_cell(1);
  ASSERT_GT(one.rows.size(), 500u);
  const std::vector<double>& last = one.rows.back();
  const double work = last[one.column("external_work")];
  const double residual = last[one.column("energy_residual")];
  std::printf("external work %.5g, residual %.3g (%.3f%%)\n", work, residual,
              100.0 * residual / work);
  ASSERT_GT(work, 1.0);
  EXPECT_LT(std::abs(residual), 0.01 * work);

  const Friction first = friction_over(one, 6.0, 9.0), second = friction_over(one, 9.0, 12.0);
  std::printf("mu %.4f then %.4f; normal force %.4g then %.4g\n", first.mu, second.mu, first.normal,
              second.normal);
  for (const Friction& f : {first, second}) {
    EXPECT_GE(f.mu, 0.1);
    EXPECT_LE(f.mu, 1.1);
    EXPECT_GT(f.normal, 0.0);  // the top body presses on the layer
  }
  EXPECT_NEAR(second.normal, first.normal, 0.25 * first.normal);

  const Series two = run_cell(2);
  EXPECT_TRUE(one.text == two.text) << "series.csv differs between 1 and 2 threads";
}

struct ImexRun {
  Series series;
  double iterations_per_solve = 0.0;  // conjugate gradients per body solve (run.log)
};

// The cell under IMEX at alpha = 0.3 (objective damping model unless another is named), 1
// thread, with `time_keys`.
ImexRun run_imex_cell(const std::string& tag, const std::string& time_keys,
                      const std::string& damping_model = "") {
  const fs::path dir = scenes::process_temp_dir("cell_imex_" + tag);
  scenes::run_scenario_text(dir, "cell.toml", cell_scenario(0.3, true, time_keys, damping_model),
                            1);
  ImexRun run{scenes::read_series_text(dir / "out" / "cell" / "series.csv")};
  std::ifstream log(dir / "out" / "cell" / "run.log");
  std::string line;
  while (std::getline(log, line))
    if (line.rfind("# imex: ", 0) == 0) {
      std::istringstream words(line.substr(8));
      double solves = 0.0, iterations = 0.0;
      std::string unit;
      words >> solves >> unit >> unit >> iterations;  // "N body solves, M conjugate-..."
      run.iterations_per_solve = iterations / solves;
    }
  fs::remove_all(dir);
  return run;
}

// The same cell under the IMEX integrator at the papers' upper viscosity, with the objective
// model's default split solve: the implicit update's viscous work is booked exactly
// (solver/implicit_viscosity.h), so the ledger closes well within the 1% of the external work
// asked of it. Measured with the exact solve: residual 0.037% of the external work (the bulk
// damping dissipates 90% of it); with the implicit correction of the viscous force left out of
// the booking (node_update.cpp, tried by hand) the residual is 0.33%, so the check is at 0.1%:
// it sees that booking, which 1% would not.
//
// The exact solve (imex_objective = "exact") against the split one: mu within 2% (measured
// +0.34%; without the split's margin the 13-time-unit cell of bench/scenes/imex-cell.toml moved
// by -5.5% at this viscosity; the scatter between two packings is 8%, docs/verification.md),
// both ledgers closed (split 0.062%, exact 0.036% of the external work). And, within the exact
// solve, the grains' dense factors (the default) against sparse ones (imex_dense_factors = false,
// the arithmetic before them): the same CG iterations per solve (a wrong factor would need more:
// the conjugate gradients would still meet their tolerance), the same ledger residual and mu within
// the bounds below. Measured: mu 0.25273799 both (1.7e-12 relative), residual 0.0364% both, 1.2296
// iterations per solve both (alpha = 0.3 damps the chaos: the last bits stay there).
TEST(ShearCellRun, ImexLedgerClosesWithinOnePercentOfTheExternalWork) {
  const ImexRun split = run_imex_cell("split", "");
  const Series& s = split.series;
  ASSERT_GT(s.rows.size(), 500u);
  const auto ledger = [](const Series& series, const char* what) {
    const auto [work, residual, bulk] = scenes::final_ledger(series);
    std::printf(
        "imex (%s), alpha 0.3: external work %.5g, bulk dissipation %.5g (%.1f%%), residual %.3g "
        "(%.3f%%)\n",
        what, work, bulk, 100.0 * bulk / work, residual, 100.0 * residual / work);
    EXPECT_GT(work, 1.0) << what;
    EXPECT_GT(bulk, 0.5 * work) << what;  // the damping is most of the dissipation
    EXPECT_LT(std::abs(residual), 0.001 * work) << what;
    return std::pair{residual, work};
  };
  ledger(s, "split");
  EXPECT_EQ(split.iterations_per_solve, 0.0);

  const ImexRun dense = run_imex_cell("dense", "imex_objective = \"exact\"\n");
  const Series& d = dense.series;
  ASSERT_EQ(d.rows.size(), s.rows.size());
  const auto [residual, work] = ledger(d, "exact");
  const double mu = friction_over(d, 6.0, 12.0).mu, split_mu = friction_over(s, 6.0, 12.0).mu;
  std::printf("split / exact solve: mu %.6f / %.6f (%+.2f%%)\n", split_mu, mu,
              100.0 * (split_mu / mu - 1.0));
  EXPECT_NEAR(split_mu, mu, 0.02 * mu);

  const ImexRun sparse =
      run_imex_cell("sparse", "imex_objective = \"exact\"\nimex_dense_factors = false\n");
  const Series& p = sparse.series;
  ASSERT_EQ(p.rows.size(), d.rows.size());
  const double sparse_residual = scenes::final_ledger(p).residual;
  const double sparse_mu = friction_over(p, 6.0, 12.0).mu;
  std::printf(
      "dense / sparse factors: mu %.8f / %.8f (%.1e relative), residual %.4f%% / %.4f%% of the "
      "external work, %.4f / %.4f CG iterations per solve\n",
      mu, sparse_mu, mu / sparse_mu - 1.0, 100.0 * residual / work, 100.0 * sparse_residual / work,
      dense.iterations_per_solve, sparse.iterations_per_solve);
  EXPECT_GT(sparse.iterations_per_solve, 0.5);
  EXPECT_NEAR(dense.iterations_per_solve, sparse.iterations_per_solve,
              0.02 * sparse.iterations_per_solve);
  EXPECT_NEAR(mu, sparse_mu, 1e-9 * sparse_mu);
  EXPECT_NEAR(residual, sparse_residual, 1e-7 * work);
}

// The corotational model's grains under IMEX: single-precision Cholesky factors (the default,
// solver/implicit_viscosity.h) against sparse double-precision ones (imex_dense_factors =
// false, the arithmetic before them). Both ledgers closed within 0.1% of the external work,
// and mu and the bulk dissipation as close as the bounds below. Measured (this machine): mu
// 0.23879192 against 0.23879193 (-2.7e-8 relative), residual 0.0062% both, bulk dissipation
// 89.0458% of the external work both.
TEST(ShearCellRun, ImexSinglePrecisionFactorsKeepMuAndTheLedger) {
  const ImexRun single = run_imex_cell("corot_single", "", "corotational");
  const ImexRun sparse =
      run_imex_cell("corot_sparse", "imex_dense_factors = false\n", "corotational");
  ASSERT_GT(single.series.rows.size(), 500u);
  ASSERT_EQ(single.series.rows.size(), sparse.series.rows.size());
  const auto [work, residual, bulk] = scenes::final_ledger(single.series);
  const auto [sparse_work, sparse_residual, sparse_bulk] = scenes::final_ledger(sparse.series);
  const double mu = friction_over(single.series, 6.0, 12.0).mu;
  const double sparse_mu = friction_over(sparse.series, 6.0, 12.0).mu;
  std::printf(
      "corotational, single / sparse double factors: mu %.8f / %.8f (%.1e relative), residual "
      "%.4f%% / %.4f%%, bulk dissipation %.4f%% / %.4f%% of the external work\n",
      mu, sparse_mu, mu / sparse_mu - 1.0, 100.0 * residual / work,
      100.0 * sparse_residual / sparse_work, 100.0 * bulk / work,
      100.0 * sparse_bulk / sparse_work);
  EXPECT_GT(bulk, 0.5 * work);
  EXPECT_LT(std::abs(residual), 0.001 * work);
  EXPECT_LT(std::abs(sparse_residual), 0.001 * sparse_work);
  // (alpha = 0.3 damps the chaos: the factors' 1e-7 relative difference per solve stays small)
  EXPECT_NEAR(mu, sparse_mu, 1e-5 * sparse_mu);
  EXPECT_NEAR(bulk, sparse_bulk, 1e-5 * sparse_bulk);
}

}  // namespace
}  // namespace sg
