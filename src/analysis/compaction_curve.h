#pragma once
// The compaction curve of a compaction-box run (paper 000 §4, "Mixed powders compaction":
// the lid comes down at an imposed velocity; what one reads off such a test is how dense the
// powder gets under how much stress).
//
// From series.csv, one point per row (time t):
//   h(t)     = lid_y(t) - t_lid / 2 - y_floor     lid height: the lid's lower face above the
//                                                 floor (lid_y is the lid's centre of mass, a
//                                                 rectangle of thickness t_lid; length)
//   sigma(t) = lid_fy(t) / W                      lid stress: the force the grains exert on
//                                                 the lid per unit width (> 0 in compression;
//                                                 force/length, the stress of a 2D run)
//   phi(t)   = A(t) / (W h(t))                    solid fraction: grain area over the box area
//                                                 below the lid
// Every column of a series.csv row describes the row's time t (run/run.cpp reads the positions
// before the step whose force evaluation the row reports), so h, sigma and phi are one instant.
//
// W is the inner width between the side walls. A(t) is the total grain area: from the grain
// snapshots (grains/NNNNNN.csv, each grain's current contour area, which sees deformable grains
// shrink), linear in time between two snapshots and held before the first and after the last;
// without snapshots, a constant (the generated grains' contour areas), and the curve says so.
// The interpolation is only an estimate (a deformable grain loses its area when it is pressed,
// not evenly over the snapshot period): the rows written at a snapshot's time (the run writes
// a series row and a snapshot at the same step when the periods allow) carry the measured A,
// and say so in the column `snapshot`.
//
// analysis/compaction.csv columns: time, lid_height, lid_force, lid_stress, grain_area,
// solid_fraction, snapshot (1: A is a snapshot's own, 0: interpolated, held or the constant);
// one row per series.csv row, 12 significant digits.
#include <span>
#include <string>
#include <vector>

#include "analysis/run_parameters.h"
#include "analysis/series.h"
#include "analysis/summary.h"

namespace sg {

// The driven body of series.csv whose columns make the curve.
inline constexpr const char* kCompactionLid = "lid";

// What the curve needs from the scenario (scenario/compaction_box.h builds the box).
struct CompactionBoxGeometry {
  double width = RunParameters::kUnknown;          // W, between the side walls (length)
  double lid_thickness = RunParameters::kUnknown;  // t_lid (length)
  double floor_y = 0.0;  // top face of the bottom wall (length); the builder puts it at 0
  // Sum of the generated grains' contour areas (t = 0; length^2): the fallback for A(t).
  double generated_grain_area = RunParameters::kUnknown;
};

// The total grain area of one snapshot.
struct GrainAreaSample {
  double time = 0.0;
  double area = 0.0;  // length^2
};

struct CompactionPoint {
  double time = 0.0;
  double lid_height = 0.0;      // h (length)
  double lid_force = 0.0;       // lid_fy (force)
  double lid_stress = 0.0;      // sigma = lid_fy / W (force/length)
  double grain_area = 0.0;      // A (length^2)
  double solid_fraction = 0.0;  // phi = A / (W h)
  bool at_snapshot = false;     // A measured at this time (not interpolated)
};

struct CompactionCurve {
  std::vector<CompactionPoint> points;  // one per series row, time order
  std::string area_source;              // where A(t) came from (for summary.json notes)
  double width = 0.0, lid_thickness = 0.0;

  const CompactionPoint& first_point() const { return points.front(); }
  const CompactionPoint& last_point() const { return points.back(); }
  double peak_lid_stress() const;
};

// The curve over every row of `series`. `areas` (time order, possibly empty) are the
// snapshots' total grain areas; when empty, `constant_area` (> 0) is used for every row and
// `area_source` should say so. Throws sg::Error naming series.path if the lid's columns
// (lid_fy, lid_y) are missing, if W or t_lid is not a positive number, or if the lid's lower
// face reaches the floor (h <= 0: no box left).
CompactionCurve compute_compaction_curve(const Series& series, const CompactionBoxGeometry& box,
                                         std::span<const GrainAreaSample> areas,
                                         double constant_area, const std::string& area_source);

// compaction.csv as text, and written atomically.
std::string compaction_csv(const CompactionCurve& curve);
void write_compaction_csv(const std::string& path, const CompactionCurve& curve);

// The curve's scalars for summary.json and the terminal table (keys compaction_*), with units
// and definitions.
std::vector<SummaryEntry> compaction_summary_entries(const CompactionCurve& curve);

// Those entries as table rows in the layout of format_summary_table (analysis/summary.h).
std::string format_compaction_table(const CompactionCurve& curve);

}  // namespace sg
