// `softgrain analyze` on a real tiny compaction box (tiny_compaction_run.h): the compaction
// curve agrees with what generate and the builder say about the box, the solid fraction grows
// as the lid descends, and a shear cell's analysis has no trace of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "analysis/grain_snapshot.h"
#include "analysis/run_csv_table.h"
#include "analysis/series.h"
#include "render/plot_runner.h"
#include "render/png_reader.h"
#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"
#include "report/analyze_run.h"
#include "tiny_compaction_run.h"
#include "tiny_run.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

AnalyzeResult analyze(const fs::path& dir) {
  AnalyzeOptions o;
  o.agglomerates = false;  // not what these tests look at
  return analyze_run(dir, o);
}

// The grains' total area in the snapshot written at `time` (read straight from the files: the
// four walls are bodies 0-3, scenario/compaction_box.cpp).
double snapshot_grain_area(const fs::path& dir, double time) {
  for (const PvdEntry& e : read_pvd(dir / "fields.pvd"))
    if (e.time == time) {
      const GrainSnapshot s = without_bodies(
          read_grain_snapshot((dir / "grains" / e.file.stem()).string() + ".csv", time),
          {"0", "1", "2", "3"});
      EXPECT_EQ(s.size(), 8u);
      double area = 0.0;
      for (double a : s.area)
        area += a;
      return area;
    }
  ADD_FAILURE() << "no snapshot at t = " << time;
  return NAN;
}

TEST(CompactionAnalyze, CurveMatchesGenerateAndTheBuilderAndGrowsAsTheLidDescends) {
  const test::TinyCompactionRun& run = test::tiny_compaction_run();
  const AnalyzeResult r = analyze(run.dir);
  ASSERT_TRUE(r.compaction.has_value()) << (r.notes.empty() ? "" : r.notes.back());
  EXPECT_EQ(r.compaction_path, run.dir / "analysis" / "compaction.csv");
  const CompactionCurve& c = *r.compaction;
  const Series series = read_series((run.dir / "series.csv").string());
  ASSERT_EQ(c.points.size(), series.size());
  EXPECT_EQ(c.width, run.width);

  // Start: what `softgrain generate` reports (grain contour areas A0; the box W x H0 read off
  // the built walls). Every column of a series.csv row describes the row's time (run/run.cpp
  // takes the positions before the step whose force evaluation the row reports), so the first
  // row's lid is where the builder put it; only the CSVs' 12 digits separate the two.
  const nlohmann::json sample = read_json(run.dir / "sample" / "sample.json");
  const double generated = sample["packing"]["solid_fraction"].get<double>();
  const double a0 = sample["packing"]["grain_area"].get<double>();
  const double h0 = sample["packing"]["container_area"].get<double>() / run.width;
  const CompactionPoint& first = c.first_point();
  EXPECT_EQ(first.time, 0.0);
  EXPECT_TRUE(first.at_snapshot);
  std::printf(
      "first row: area %.3g, lid height %.3g, solid fraction %.3g off generate (relative)\n",
      first.grain_area / a0 - 1.0, first.lid_height / h0 - 1.0,
      first.solid_fraction / generated - 1.0);
  // 12 significant digits: up to 5e-12 relative per printed value (measured 3e-13, 8e-13 and
  // 5e-13; the lid was 1.6e-6 off when series.csv took the positions after the step).
  EXPECT_NEAR(first.grain_area, a0, 1e-11 * a0);
  EXPECT_NEAR(first.lid_height, h0, 1e-11 * h0);
  EXPECT_NEAR(first.solid_fraction, generated, 1e-11 * generated);

  // Every row's lid where the row's time puts it. The lid follows the builder's speed history,
  // 0 -> V over the ramp, then V until the ramp down, and the solver moves it by
  // dt v(t + dt/2), a midpoint rule exact on each linear piece: on the ramp
  // h(t) = H0 - (V / ramp) t^2 / 2 to round-off, at full speed h(t) = H0 - V ramp / 2 -
  // V (t - ramp) but for the one step straddling the knot t = ramp, off by at most
  // (V / ramp) dt^2 / 8 (1.4e-6 here). Positions one step late would be v dt off (5e-4 at
  // t = 0.1 on the ramp, 1.1e-3 at full speed).
  {
    const double v = run.lid_velocity, ramp = run.lid_ramp_time;
    double dt_max = 0.0;
    for (double d : series.column("dt"))
      dt_max = std::max(dt_max, d);
    const double knot = v / ramp * dt_max * dt_max / 8.0;
    double ramp_error = 0.0, full_speed_error = 0.0;
    int ramp_rows = 0, full_speed_rows = 0;
    for (const CompactionPoint& p : c.points) {
      const double t = p.time;
      if (t <= ramp) {
        const double error = std::abs(p.lid_height - (h0 - 0.5 * v / ramp * t * t));
        EXPECT_LT(error, 1e-11 * h0) << t;
        ramp_error = std::max(ramp_error, error);
        ++ramp_rows;
      } else if (t <= run.stop_time - ramp) {
        const double error = std::abs(p.lid_height - (h0 - 0.5 * v * ramp - v * (t - ramp)));
        EXPECT_LT(error, knot + 1e-11 * h0) << t;
        full_speed_error = std::max(full_speed_error, error);
        ++full_speed_rows;
      }
    }
    std::printf(
        "lid height against its history: ramp (%d rows) %.3g, full speed (%d rows) %.3g "
        "(knot bound %.3g)\n",
        ramp_rows, ramp_error, full_speed_rows, full_speed_error, knot);
    EXPECT_EQ(ramp_rows, 4);  // t = 0, 0.05, 0.10, 0.15 (rows fall on steps)
    EXPECT_GE(full_speed_rows, 25);
  }

  // End: the lid stopped at the builder's final height (the midpoint rule integrates the
  // piecewise-linear lid speed exactly but for the steps straddling its four knots: measured
  // 5e-7 off, i.e. 2e-7 relative), and the last row (t = 2.5) is a snapshot's, so its area is
  // measured, not interpolated: phi = A(2.5) / (W H_final).
  const CompactionPoint& last = c.last_point();
  EXPECT_GT(last.time, run.stop_time);
  ASSERT_TRUE(last.at_snapshot) << last.time;
  EXPECT_NEAR(last.lid_height, run.final_height, 1e-6 * run.final_height);
  const double area = snapshot_grain_area(run.dir, last.time);
  EXPECT_EQ(last.grain_area, area);
  const double expected = area / (run.width * run.final_height);
  std::printf(
      "solid fraction: start %.9f (generate %.9f), end %.9f (A / (W H_final) %.9f); "
      "lid height %.9f (builder %.9f); lid stress %.4f, peak %.4f\n",
      first.solid_fraction, generated, last.solid_fraction, expected, last.lid_height,
      run.final_height, last.lid_stress, c.peak_lid_stress());
  EXPECT_NEAR(last.solid_fraction, expected, 1e-6 * expected);
  // The grains press on the stopped lid: lid_fy / W from series.csv's last row.
  EXPECT_EQ(last.lid_stress, series.column("lid_fy")[series.size() - 1] / run.width);
  EXPECT_GT(last.lid_stress, 0.0);

  // Growing as the lid descends: at the snapshot rows (measured areas) strictly whenever the
  // lid went down between two of them, and between consecutive rows wherever the lid went
  // down by more than 1e-3 (full speed: 0.025 per row, 3.3e-3 from the first row to the second
  // on the ramp; the interpolated area is only an estimate, and the stopped lid stays put).
  const CompactionPoint* previous_snapshot = nullptr;
  int snapshot_rows = 0, descending_rows = 0;
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    const CompactionPoint& p = c.points[k];
    if (k > 0 && p.lid_height < c.points[k - 1].lid_height - 1e-3) {
      ++descending_rows;
      EXPECT_GT(p.solid_fraction, c.points[k - 1].solid_fraction) << p.time;
    }
    if (!p.at_snapshot) continue;
    ++snapshot_rows;
    if (previous_snapshot && p.lid_height < previous_snapshot->lid_height - 1e-9) {
      EXPECT_GT(p.solid_fraction, previous_snapshot->solid_fraction) << p.time;
    }
    previous_snapshot = &p;
  }
  EXPECT_EQ(snapshot_rows, 11);  // t = 0, 0.25, ..., 2.5
  EXPECT_GE(descending_rows, 25);
  EXPECT_GT(last.solid_fraction, first.solid_fraction + 0.15);

  // The files: compaction.csv row for row, and the scalars in summary.json.
  const RunCsvTable csv = read_run_csv_table(r.compaction_path.string());
  ASSERT_EQ(csv.rows.size(), c.points.size());
  const int phi = csv.column_index("solid_fraction");
  EXPECT_NEAR(csv.number(csv.rows.size() - 1, phi), last.solid_fraction, 1e-11);
  const nlohmann::json doc = read_json(r.summary_path);
  const nlohmann::json& q = doc["quantities"];
  EXPECT_EQ(q["compaction_initial_solid_fraction"]["value"].get<double>(), first.solid_fraction);
  EXPECT_EQ(q["compaction_final_solid_fraction"]["value"].get<double>(), last.solid_fraction);
  EXPECT_EQ(q["compaction_final_lid_stress"]["value"].get<double>(), last.lid_stress);
  EXPECT_EQ(q["compaction_final_lid_stress"]["unit"], "force/length");
  EXPECT_FALSE(q["compaction_final_solid_fraction"]["definition"].get<std::string>().empty());
  EXPECT_EQ(doc["compaction"]["file"], "compaction.csv");
  EXPECT_EQ(doc["compaction"]["rows"].get<std::size_t>(), c.points.size());
  EXPECT_NE(doc["compaction"]["grain_area_source"].get<std::string>().find("grains/*.csv"),
            std::string::npos);
}

TEST(CompactionAnalyze, PlotScriptDrawsTheCompactionCurve) {
  if (!python_has_matplotlib()) GTEST_SKIP() << kPlotPython << " cannot import matplotlib";
  const test::TinyCompactionRun& run = test::tiny_compaction_run();
  analyze(run.dir);
  const auto script = find_plot_script(current_executable(), nullptr);
  ASSERT_TRUE(script.has_value()) << "plot_run.py not found";
  const fs::path png = run.dir / "analysis" / "compaction.png";
  fs::remove(png);
  ASSERT_EQ(run_plot_script(*script, run.dir), 0);
  ASSERT_TRUE(fs::exists(png));
  const auto [w, h] = png_size(png);
  EXPECT_EQ(w, 1100);  // 10 x 4.2 inches at 110 dpi, as plot_run.py draws it
  EXPECT_EQ(h, 462);
}

TEST(CompactionAnalyze, ShearCellAnalysisHasNoCompactionCurve) {
  const fs::path& dir = test::tiny_shear_run_dir();
  const AnalyzeResult r = analyze(dir);
  EXPECT_FALSE(r.compaction.has_value());
  EXPECT_TRUE(r.compaction_path.empty());
  EXPECT_FALSE(fs::exists(dir / "analysis" / "compaction.csv"));
  const nlohmann::json doc = read_json(r.summary_path);
  EXPECT_FALSE(doc.contains("compaction"));
  for (const auto& [key, value] : doc["quantities"].items())
    EXPECT_EQ(key.find("compaction"), std::string::npos) << key;
}

}  // namespace
}  // namespace sg
