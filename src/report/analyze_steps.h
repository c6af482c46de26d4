#pragma once
// The steps of `analyze_run` (report/analyze_run.h), one file each, in the order the driver
// calls them. Each step fills its part of the AnalyzeResult; what it cannot compute becomes
// a note (and null in summary.json), never an exception, except for an unusable run folder.
#include <filesystem>
#include <iomanip>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/grain_snapshot.h"
#include "analysis/series.h"
#include "render/run_folder.h"
#include "report/analyze_run.h"

namespace sg::report {

inline constexpr double kNan = RunParameters::kUnknown;

// A number for a note: the stream's default format.
inline std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// A number for a CSV cell: full precision; empty for an unknown value.
inline std::string cell(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s << std::setprecision(12) << v;
  return s.str();
}

// --- report/run_snapshots.cpp
struct Snapshots {
  std::vector<GrainSnapshot> all;  // grains only, time order
  std::size_t files = 0;
};
// grains/NNNNNN.csv with their times from fields.pvd, without the `exclude` rows.
Snapshots read_snapshots(const std::filesystem::path& run_dir,
                         const std::vector<std::string>& exclude, std::vector<std::string>& notes);
// The non-empty snapshots whose time lies in the window.
std::vector<GrainSnapshot> window_snapshots(const Snapshots& snaps, const TimeWindow& window);

// --- report/parameter_sources.cpp
// L, D, V, E, c, alpha: each from the options, else the scenario, else unknown.
void resolve_run_parameters(AnalyzeResult& r, const RunInfo& run, const AnalyzeOptions& options);
// The mean grain diameter: the option, else measured on the first snapshot.
void resolve_mean_diameter(AnalyzeResult& r, const Snapshots& snaps, const AnalyzeOptions& options);

// --- report/shear_report.cpp
// The steady window, friction, E~ c~ alpha~ and the energy budget of the shear cell's
// driven bodies "top" and "bottom" (the whole run as window without them); D measured
// (measure_gap) when the scenario does not give it.
void analyze_shear(AnalyzeResult& r, const Series& series, const RunInfo& run,
                   const AnalyzeOptions& options, const std::filesystem::path& run_dir);

// --- report/gap_report.cpp
// Under pressure loading D is an output: the mean over the window of the distance between
// the rough surfaces' mean lines, from the first bodies' positions in series.csv and their
// surfaces in the first field snapshot. Sets parameters.gap and its source; a note if not.
void measure_gap(AnalyzeResult& r, const Series& series, const RunInfo& run,
                 const std::filesystem::path& run_dir);

// --- report/layer_report.cpp
// Velocity profile, solid fraction and activated thickness of the window's snapshots.
void analyze_layer(AnalyzeResult& r, std::span<const GrainSnapshot> window_snaps,
                   const RunInfo& run, const AnalyzeOptions& options,
                   const std::filesystem::path& run_dir);

// --- report/agglomerate_report.cpp
// Paper 002's rotating structures in the window's snapshots.
void analyze_agglomerates(AnalyzeResult& r, std::span<const GrainSnapshot> frames,
                          const RunInfo& run, const AnalyzeOptions& options,
                          const std::filesystem::path& run_dir);

// --- report/compaction_report.cpp
// The compaction curve of a [compaction_box] run over every series.csv row.
void analyze_compaction(AnalyzeResult& r, const Series& series, const CompactionBoxGeometry& box,
                        std::span<const GrainSnapshot> snapshots,
                        const std::filesystem::path& run_dir);

// --- report/campaign_request.cpp
// The papers' coordinates a campaign requested for this run (<campaign folder>/
// paper_coordinates.csv, campaign/paper_coordinates.h), when run_dir is <campaign>/runs/<id>/.
void read_campaign_request(AnalyzeResult& r, const std::filesystem::path& run_dir);

// --- report/summary_document.cpp
// summary.json: the quantities, then "run", "parameters", "profile", "agglomerates",
// "compaction" and "notes".
std::string summary_document(const AnalyzeResult& r, const std::filesystem::path& run_dir);
// Largest |C| over the defined nodes of every frame (0 if none): tells a reader how far
// from the threshold a run without structures is.
double largest_coherence(const AgglomerateResult& a);

}  // namespace sg::report
