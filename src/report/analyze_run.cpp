#include "report/analyze_run.h"

#include <algorithm>

#include "analysis/compaction_curve.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "report/analyze_steps.h"

namespace sg {

namespace fs = std::filesystem;

std::vector<std::string> non_grain_rows(const RunInfo& run,
                                        const std::vector<std::string>& driven_bodies) {
  std::vector<std::string> rows;
  if (!run.has_scenario) return rows;
  std::vector<std::string> not_grains(driven_bodies);
  not_grains.insert(not_grains.end(), run.walls.begin(), run.walls.end());
  if (run.shear_cell) {
    not_grains.push_back("top");
    not_grains.push_back("bottom");
  }
  // grains/*.csv number bodies in build order; the rows of the non-grains by index.
  for (std::size_t i = 0; i < run.body_names.size(); ++i)
    if (std::find(not_grains.begin(), not_grains.end(), run.body_names[i]) != not_grains.end())
      rows.push_back(std::to_string(i));
  return rows;
}

namespace {

Series read_run_series(const fs::path& run_dir) {
  const fs::path series_path = run_dir / "series.csv";
  if (!fs::exists(series_path) && fs::exists(run_dir / "series.csv.partial"))
    SG_THROW("'" << run_dir.string()
                 << "': only series.csv.partial: the run is still going or was interrupted");
  SG_VERIFY(fs::exists(series_path),
            "'" << run_dir.string() << "' has no series.csv: not a run folder");
  Series series = read_series(series_path.string());
  SG_VERIFY(series.size() >= 2, series_path.string() << ": fewer than 2 rows, nothing to average");
  return series;
}

// What the scenario tells (or why nothing), as notes.
void note_run_info(const RunInfo& run, std::vector<std::string>& notes) {
  if (run.has_scenario) {
    notes.insert(notes.end(), run.notes.begin(), run.notes.end());
  } else {
    notes.push_back(run.note +
                    ": run parameters only from options; walls cannot be told from "
                    "grains in grains/*.csv");
  }
}

// The grain snapshots of the window: profiles, solid fraction, agglomerates.
void analyze_window_snapshots(AnalyzeResult& r, const report::Snapshots& snaps, const RunInfo& run,
                              const AnalyzeOptions& options, const fs::path& run_dir) {
  const std::vector<GrainSnapshot> window_snaps = report::window_snapshots(snaps, r.summary.window);
  if (window_snaps.empty()) {
    if (!snaps.all.empty())
      r.notes.push_back(
          "no grain snapshot inside the window: no profile, solid fraction or "
          "agglomerates");
    return;
  }
  report::analyze_layer(r, window_snaps, run, options, run_dir);
  if (options.agglomerates)
    report::analyze_agglomerates(r, window_snaps, run, options, run_dir);
  else
    r.notes.push_back("agglomerates not computed (--no-agglomerates)");
}

}  // namespace

AnalyzeResult analyze_run(const fs::path& run_dir, const AnalyzeOptions& options) {
  AnalyzeResult r;
  const Series series = read_run_series(run_dir);

  // Run parameters: options, then the scenario, then measured.
  const RunInfo run = read_run_info(run_dir);
  note_run_info(run, r.notes);
  report::resolve_run_parameters(r, run, options);
  const report::Snapshots snaps =
      report::read_snapshots(run_dir, non_grain_rows(run, series.body_names), r.notes);
  report::resolve_mean_diameter(r, snaps, options);

  // Compaction box: the curve over the whole run.
  if (run.compaction_box) {
    report::analyze_compaction(r, series, *run.compaction_box, snaps.all, run_dir);
  } else if (series.has(std::string(kCompactionLid) + "_fy")) {
    r.notes.push_back(
        "series.csv has a driven 'lid' but the run's scenario is not known as a "
        "[compaction_box]: no compaction curve");
  }

  // Shear cell: window, friction, dimensionless parameters, energy budget.
  report::analyze_shear(r, series, run, options, run_dir);
  report::read_campaign_request(r, run_dir);
  r.summary.solid_fraction = report::kNan;
  analyze_window_snapshots(r, snaps, run, options, run_dir);

  r.summary_path = run_dir / "analysis" / "summary.json";
  write_file_atomically(r.summary_path.string(), report::summary_document(r, run_dir));
  return r;
}

}  // namespace sg
