#include "analysis/compaction_curve.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"

namespace sg {
namespace {

// A(t): linear between the two snapshots around t, held outside their span; `exact` is set
// when t is a snapshot's time (then A is that snapshot's sum, bit for bit).
double area_at(std::span<const GrainAreaSample> areas, double t, bool& exact) {
  const auto after =
      std::upper_bound(areas.begin(), areas.end(), t,
                       [](double time, const GrainAreaSample& s) { return time < s.time; });
  exact = after != areas.begin() && (after - 1)->time == t;
  if (after == areas.begin()) return areas.front().area;
  if (after == areas.end()) return areas.back().area;
  const GrainAreaSample& b = *after;
  const GrainAreaSample& a = *(after - 1);
  const double w = (t - a.time) / (b.time - a.time);
  return (1.0 - w) * a.area + w * b.area;
}

std::string cell(double v) {
  std::ostringstream s;
  s << std::setprecision(12) << v;
  return s.str();
}

}  // namespace

double CompactionCurve::peak_lid_stress() const {
  double peak = -INFINITY;
  for (const CompactionPoint& p : points)
    peak = std::max(peak, p.lid_stress);
  return peak;
}

CompactionCurve compute_compaction_curve(const Series& series, const CompactionBoxGeometry& box,
                                         std::span<const GrainAreaSample> areas,
                                         double constant_area, const std::string& area_source) {
  const std::string fy = std::string(kCompactionLid) + "_fy";
  const std::string y = std::string(kCompactionLid) + "_y";
  for (const std::string& column : {fy, y})
    SG_VERIFY(series.has(column), series.path << ": no column '" << column
                                              << "': the compaction curve needs the driven lid '"
                                              << kCompactionLid
                                              << "' (a [compaction_box] run's series.csv)");
  SG_VERIFY(series.size() >= 1, series.path << ": no rows: no compaction curve");
  SG_VERIFY(box.width > 0.0 && std::isfinite(box.width),
            "compaction curve: box width " << box.width << " is not a positive length");
  SG_VERIFY(box.lid_thickness > 0.0 && std::isfinite(box.lid_thickness),
            "compaction curve: lid thickness " << box.lid_thickness << " is not a positive length");
  if (areas.empty())
    SG_VERIFY(constant_area > 0.0 && std::isfinite(constant_area),
              "compaction curve: no grain snapshot and no grain area (" << constant_area << ")");
  for (std::size_t k = 0; k < areas.size(); ++k) {
    SG_VERIFY(areas[k].area > 0.0, "compaction curve: snapshot at t = "
                                       << areas[k].time << " has grain area " << areas[k].area);
    SG_VERIFY(k == 0 || areas[k].time > areas[k - 1].time,
              "compaction curve: snapshot times not increasing at t = " << areas[k].time);
  }

  const auto time = series.column("time");
  const auto force = series.column(fy);
  const auto centre = series.column(y);
  CompactionCurve curve;
  curve.area_source = area_source;
  curve.width = box.width;
  curve.lid_thickness = box.lid_thickness;
  curve.points.reserve(series.size());
  for (std::size_t r = 0; r < series.size(); ++r) {
    CompactionPoint p;
    p.time = time[r];
    // The lid is a rectangle: its centre of mass is mid-thickness above its lower face.
    p.lid_height = centre[r] - 0.5 * box.lid_thickness - box.floor_y;
    SG_VERIFY(p.lid_height > 0.0, series.path << ": row " << r + 1 << " (t = " << p.time
                                              << "): the lid's lower face is at height "
                                              << p.lid_height << " above the floor");
    p.lid_force = force[r];
    p.lid_stress = p.lid_force / box.width;  // force per unit width: the 2D stress
    p.grain_area = areas.empty() ? constant_area : area_at(areas, p.time, p.at_snapshot);
    p.solid_fraction = p.grain_area / (box.width * p.lid_height);
    curve.points.push_back(p);
  }
  return curve;
}

std::string compaction_csv(const CompactionCurve& curve) {
  std::ostringstream out;
  out << "time,lid_height,lid_force,lid_stress,grain_area,solid_fraction,snapshot\n";
  for (const CompactionPoint& p : curve.points)
    out << cell(p.time) << ',' << cell(p.lid_height) << ',' << cell(p.lid_force) << ','
        << cell(p.lid_stress) << ',' << cell(p.grain_area) << ',' << cell(p.solid_fraction) << ','
        << (p.at_snapshot ? 1 : 0) << '\n';
  return out.str();
}

void write_compaction_csv(const std::string& path, const CompactionCurve& curve) {
  write_file_atomically(path, compaction_csv(curve));
}

std::vector<SummaryEntry> compaction_summary_entries(const CompactionCurve& c) {
  const CompactionPoint& first = c.first_point();
  const CompactionPoint& last = c.last_point();
  return {
      {"compaction_initial_solid_fraction", first.solid_fraction, "1",
       "phi = A / (W h) at the first series row: grain area over the box area below the lid "
       "(paper 000 §4; analysis/compaction.csv)"},
      {"compaction_final_solid_fraction", last.solid_fraction, "1",
       "phi = A / (W h) at the last series row"},
      {"compaction_final_lid_stress", last.lid_stress, "force/length",
       "sigma = lid_fy / W at the last series row: force the grains exert on the lid per unit "
       "box width (> 0 in compression)"},
      {"compaction_peak_lid_stress", c.peak_lid_stress(), "force/length",
       "largest sigma = lid_fy / W over the run"},
      {"compaction_final_lid_height", last.lid_height, "length",
       "h = lid_y - t_lid / 2 at the last series row: the lid's lower face above the floor"},
  };
}

std::string format_compaction_table(const CompactionCurve& curve) {
  return format_summary_rows(compaction_summary_entries(curve), 8);
}

}  // namespace sg
