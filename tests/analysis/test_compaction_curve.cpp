// The compaction curve (analysis/compaction_curve.h) on a synthetic compaction box whose answer
// is closed-form: a lid descending at constant speed v from H0 over grains of known total
// area A gives phi(t) = A / (W (H0 - v t)) and sigma(t) = F(t) / W exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/compaction_curve.h"
#include "analysis/run_csv_table.h"
#include "core/error.h"
#include "synthetic.h"

namespace sg {
namespace {

constexpr double kWidth = 4.0, kLidThickness = 0.8, kH0 = 5.0, kSpeed = 0.25;

// series.csv of a box: the required columns, then the driven walls bottom and lid (the
// builder's names); the lid's centre sits t_lid / 2 above its lower face at H0 - v t, and the
// grains push it with F(t) = 3 t^2.
Series box_series(const std::vector<double>& time) {
  Series s;
  s.path = "synthetic box series.csv";
  for (const auto name : required_series_columns())
    s.columns.emplace_back(name);
  for (const std::string body : {"bottom", "lid"}) {
    s.body_names.push_back(body);
    for (const std::string suffix : {"_fx", "_fy", "_x", "_y"})
      s.columns.push_back(body + suffix);
  }
  s.values.assign(s.columns.size(), std::vector<double>(time.size(), 0.0));
  s.values[0] = time;
  for (std::size_t r = 0; r < time.size(); ++r) {
    test::column_values(s, "lid_y")[r] = kH0 - kSpeed * time[r] + 0.5 * kLidThickness;
    test::column_values(s, "lid_fy")[r] = 3.0 * time[r] * time[r];
    test::column_values(s, "bottom_y")[r] = -0.5 * kLidThickness;
  }
  check_series(s);
  return s;
}

std::vector<double> times(int n, double dt) {
  std::vector<double> t(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
    t[static_cast<std::size_t>(k)] = k * dt;
  return t;
}

CompactionBoxGeometry box_geometry() {
  CompactionBoxGeometry g;
  g.width = kWidth;
  g.lid_thickness = kLidThickness;
  g.floor_y = 0.0;
  g.generated_grain_area = 12.0;
  return g;
}

std::string error_of(const auto& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(CompactionCurve, LidAtConstantSpeedOverConstantAreaIsClosedForm) {
  const Series s = box_series(times(81, 0.1));  // t in [0, 8]: h from 5 down to 3
  const double area = 12.0;
  const CompactionCurve c =
      compute_compaction_curve(s, box_geometry(), {}, area, "generated grains (constant)");
  ASSERT_EQ(c.points.size(), 81u);
  for (const CompactionPoint& p : c.points) {
    const double h = kH0 - kSpeed * p.time;
    // Only rounding separates the two (lid_y - t_lid / 2 and one division).
    EXPECT_NEAR(p.lid_height, h, 1e-14 * kH0) << p.time;
    EXPECT_NEAR(p.solid_fraction, area / (kWidth * h), 1e-14) << p.time;
    EXPECT_DOUBLE_EQ(p.lid_stress, 3.0 * p.time * p.time / kWidth) << p.time;
    EXPECT_EQ(p.grain_area, area);
    EXPECT_FALSE(p.at_snapshot);
  }
  EXPECT_NEAR(c.first_point().solid_fraction, 12.0 / 20.0, 1e-15);
  EXPECT_NEAR(c.last_point().solid_fraction, 12.0 / 12.0, 1e-14);
  EXPECT_DOUBLE_EQ(c.peak_lid_stress(), 3.0 * 64.0 / kWidth);
  EXPECT_EQ(c.area_source, "generated grains (constant)");

  // The scalars, by key, with the values above.
  double initial = NAN, final_phi = NAN, final_stress = NAN;
  for (const SummaryEntry& e : compaction_summary_entries(c)) {
    EXPECT_FALSE(e.definition.empty()) << e.key;
    if (e.key == "compaction_initial_solid_fraction") initial = e.value;
    if (e.key == "compaction_final_solid_fraction") final_phi = e.value;
    if (e.key == "compaction_final_lid_stress") final_stress = e.value;
  }
  EXPECT_EQ(initial, c.first_point().solid_fraction);
  EXPECT_EQ(final_phi, c.last_point().solid_fraction);
  EXPECT_EQ(final_stress, 3.0 * 64.0 / kWidth);
  const std::string table = format_compaction_table(c);
  EXPECT_NE(table.find("compaction_final_solid_fraction"), std::string::npos) << table;
}

TEST(CompactionCurve, SnapshotAreasAreInterpolatedLinearlyAndHeldOutside) {
  // Deformable grains losing area: A = 12 at t = 1, 11 at t = 5 (linear in between, so the
  // interpolation is exact), held before 1 and after 5.
  const Series s = box_series(times(81, 0.1));
  const std::vector<GrainAreaSample> areas{{1.0, 12.0}, {3.0, 11.5}, {5.0, 11.0}};
  const CompactionCurve c = compute_compaction_curve(s, box_geometry(), areas, 0.0, "snapshots");
  int marked = 0;
  for (const CompactionPoint& p : c.points) {
    marked += p.at_snapshot;
    const double a = p.time <= 1.0 ? 12.0 : p.time >= 5.0 ? 11.0 : 12.0 - 0.25 * (p.time - 1.0);
    EXPECT_NEAR(p.grain_area, a, 1e-14 * a) << p.time;
    EXPECT_NEAR(p.solid_fraction, a / (kWidth * (kH0 - kSpeed * p.time)), 1e-14) << p.time;
    // Rows at a snapshot's time carry its area exactly, and are marked.
    const bool at = p.time == 1.0 || p.time == 3.0 || p.time == 5.0;
    EXPECT_EQ(p.at_snapshot, at) << p.time;
    if (at) {
      EXPECT_EQ(p.grain_area, a) << p.time;
    }
  }
  EXPECT_EQ(marked, 3);  // t = 10 x 0.1, 30 x 0.1, 50 x 0.1 round to 1, 3, 5 exactly
}

TEST(CompactionCurve, CsvHoldsOneRowPerSeriesRowAtFullPrecision) {
  const test::ScratchDir dir("compaction_csv");
  const Series s = box_series(times(11, 0.5));
  const CompactionCurve c = compute_compaction_curve(s, box_geometry(), {}, 12.0, "constant");
  write_compaction_csv(dir.file("compaction.csv"), c);
  const RunCsvTable t = read_run_csv_table(dir.file("compaction.csv"));
  const std::vector<std::string> header{"time",       "lid_height",     "lid_force", "lid_stress",
                                        "grain_area", "solid_fraction", "snapshot"};
  EXPECT_EQ(t.columns, header);
  ASSERT_EQ(t.rows.size(), 11u);
  const int phi = t.column_index("solid_fraction");
  for (std::size_t r = 0; r < t.rows.size(); ++r)  // 12 significant digits
    EXPECT_NEAR(t.number(r, phi), c.points[r].solid_fraction, 1e-12 * c.points[r].solid_fraction);
}

TEST(CompactionCurve, BadInputGivesOneClearError) {
  // A shear cell's series: no lid.
  const Series shear = test::make_series(times(5, 0.1));
  std::string message =
      error_of([&] { compute_compaction_curve(shear, box_geometry(), {}, 12.0, ""); });
  EXPECT_NE(message.find("synthetic series.csv"), std::string::npos) << message;
  EXPECT_NE(message.find("no column 'lid_fy'"), std::string::npos) << message;
  EXPECT_NE(message.find("[compaction_box]"), std::string::npos) << message;

  const Series s = box_series(times(5, 0.1));
  CompactionBoxGeometry g = box_geometry();
  g.width = RunParameters::kUnknown;
  message = error_of([&] { compute_compaction_curve(s, g, {}, 12.0, ""); });
  EXPECT_NE(message.find("box width"), std::string::npos) << message;
  g = box_geometry();
  g.lid_thickness = 0.0;
  message = error_of([&] { compute_compaction_curve(s, g, {}, 12.0, ""); });
  EXPECT_NE(message.find("lid thickness"), std::string::npos) << message;
  // No snapshot and no area to fall back on.
  message = error_of([&] { compute_compaction_curve(s, box_geometry(), {}, 0.0, ""); });
  EXPECT_NE(message.find("no grain snapshot"), std::string::npos) << message;
  // Snapshots out of order.
  const std::vector<GrainAreaSample> unordered{{1.0, 12.0}, {0.5, 12.0}};
  message = error_of([&] { compute_compaction_curve(s, box_geometry(), unordered, 0.0, ""); });
  EXPECT_NE(message.find("not increasing"), std::string::npos) << message;
  // A lid driven through the floor: h = 5 - 0.25 t <= 0 from t = 20.
  const Series through = box_series(times(30, 1.0));
  message = error_of([&] { compute_compaction_curve(through, box_geometry(), {}, 12.0, ""); });
  EXPECT_NE(message.find("synthetic box series.csv: row 21 (t = 20)"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace sg
