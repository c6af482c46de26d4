#include <cmath>

#include "core/error.h"
#include "report/analyze_steps.h"

namespace sg::report {

namespace fs = std::filesystem;

// The compaction curve of a [compaction_box] run over every series.csv row; A(t) from the
// snapshots' grains (walls removed), else the generated grains' areas. A failure is a note.
void analyze_compaction(AnalyzeResult& r, const Series& series, const CompactionBoxGeometry& box,
                        std::span<const GrainSnapshot> snapshots, const fs::path& run_dir) {
  std::vector<GrainAreaSample> areas;
  for (const GrainSnapshot& snap : snapshots) {
    if (snap.size() == 0) continue;
    double area = 0.0;
    for (const double a : snap.area)
      area += a;
    areas.push_back({snap.time, area});
  }
  const std::string source =
      areas.empty()
          ? "the generated grains' contour areas, constant (no grains/*.csv: a deformable "
            "grain's change of area is not seen)"
          : "grains/*.csv: sum of the grains' current contour areas, linear in time between "
            "the " +
                std::to_string(areas.size()) + " snapshots";
  // The snapshots must hold the grains and only them: at t = 0 their area is the generated one.
  if (!areas.empty() && areas.front().time == 0.0 && std::isfinite(box.generated_grain_area) &&
      !(std::abs(areas.front().area - box.generated_grain_area) <= 1e-9 * box.generated_grain_area))
    r.notes.push_back("compaction: grains/*.csv at t = 0 hold grain area " +
                      number(areas.front().area) + ", the scenario's grains " +
                      number(box.generated_grain_area) + " (walls not told apart?)");
  try {
    CompactionCurve curve =
        compute_compaction_curve(series, box, areas, box.generated_grain_area, source);
    r.compaction_path = run_dir / "analysis" / "compaction.csv";
    write_compaction_csv(r.compaction_path.string(), curve);
    r.compaction = std::move(curve);
  } catch (const Error& e) {
    r.compaction.reset();
    r.compaction_path.clear();
    r.notes.push_back(std::string("compaction curve not computed: ") + e.what());
    r.unmeasured.push_back({"compaction curve", e.what()});
  }
}

}  // namespace sg::report
