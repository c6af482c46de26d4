#pragma once
// `softgrain analyze RUN_DIR`: the analysis library (src/analysis/) applied to a run
// folder, with every input it needs gathered and every gap reported, never guessed.
//
//   series.csv        -> steady window, friction (when the shear-cell bodies "top" and
//                        "bottom" have columns), energy budget
//   grains/NNNNNN.csv -> velocity profiles, solid fraction, agglomerates (paper 002),
//                        times from fields.pvd (same snapshot numbers)
//   run.log           -> the scenario -> L, V, D, E, c, alpha; body names (walls and
//                        driven bodies are removed from the grain snapshots)
//   [compaction_box]  -> the compaction curve (analysis/compaction_curve.h): lid height,
//                        lid stress and solid fraction per series.csv row, from the lid's
//                        columns, the box width and the snapshots' grain areas
//   options           -> override any of these
//
// Writes RUN_DIR/analysis/summary.json (analysis/summary.h layout, plus "parameters": each
// run parameter with its value and where it came from, "campaign": for a run of a campaign in
// the papers' coordinates, its name, the run id and each coordinate requested beside the
// realized one, "agglomerates": how they were
// detected, "unmeasured": what the run asks for and could not be measured, with the reason,
// and "notes": what could not be computed and why), RUN_DIR/analysis/profiles.csv,
// agglomerates.csv (one row per structure) and agglomerate_pdfs.csv, and for a compaction
// box analysis/compaction.csv (its scalars compaction_* join summary.json's quantities, and
// "compaction" says where A(t) came from), all atomically.
//
// agglomerates.csv columns: id (the space-time label), sign (+1 counter-clockwise, -1
// clockwise = with the shear), first_frame, last_frame (indices into the window's
// snapshots), first_time, last_time, frames, lifetime, mean_area, diameter, grain_samples
// (its (grain, snapshot) samples: its weight in "equivalent grains"), omega (eq. 6),
// omega_tilde (omega / (-V/D), eq. 7; empty if unknown).
// agglomerate_pdfs.csv columns: quantity (omega_tilde, diameter, lifetime), bin_lo,
// bin_hi, density (grain-weighted, integrates to 1 over the bins of a quantity).
// agglomerate_space_time.csv, agglomerate_cylinders.csv: analysis/structure_cylinders.h.
// att.csv: the activated thickness per window snapshot (analysis/activated_thickness.h).
// Under pressure loading (D not in the scenario) D is measured (report/gap_report.cpp).
//
// The steps, one file each: report/analyze_steps.h. This stage sits above render (it reads
// the run folder with render's .vtu/.pvd and run.log readers) and below the commands.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/activated_thickness.h"
#include "analysis/agglomerates.h"
#include "analysis/compaction_curve.h"
#include "analysis/profiles.h"
#include "analysis/run_parameters.h"
#include "analysis/summary.h"

namespace sg {

struct AnalyzeOptions {
  std::optional<std::pair<double, double>> window;  // [t0, t1]; unset: MSER or whole run
  RunParameters given;                              // NaN = not given, take from the run
  std::optional<std::pair<double, double>> layer;   // [y_min, y_max] of the layer
  int profile_bins = 0;                             // 0: two per mean grain diameter
  bool agglomerates = true;
  double coherence_threshold = 0.8;  // |C| > threshold marks a structure (paper 002: 0.8)
  AttThresholds att;                 // shares of the velocity jump (paper 003: 0.2, 0.8)
  SteadinessThresholds steadiness;   // when the window's checks warn (analysis/steadiness.h)
};

struct ParameterSource {
  std::string key;     // "length", "gap", ...
  double value = 0.0;  // NaN if unknown
  std::string unit;
  std::string source;  // "option", "scenario ...", "grains/*.csv", "unknown"
};

// A quantity the run's kind asks for that could not be measured: mu of a shear cell (the
// driven bodies "top" and "bottom"), the compaction curve of a compaction box.
struct Unmeasured {
  std::string quantity;  // "mu", "compaction curve"
  std::string reason;
};

// The papers' coordinates (stiffness_tilde, cohesion_tilde, viscosity_tilde) a campaign that
// varies them requested for this run (campaign/paper_coordinates.h).
struct CampaignRequest {
  std::string campaign;  // the campaign folder's name
  std::string run;       // the run id
  std::vector<std::pair<std::string, double>> requested;
};

struct AnalyzeResult {
  AnalysisSummary summary;
  // Not empty: `analyze` exits with kExitUnmeasured (core/exit_status.h), summary.json lists
  // them under "unmeasured", `sweep` reports the run as done without them.
  std::vector<Unmeasured> unmeasured;
  RunParameters parameters;
  std::vector<ParameterSource> parameter_sources;
  std::vector<std::string> notes;  // what was not computed and why; choices made
  std::optional<VelocityProfile> profile;
  std::optional<AgglomerateResult> agglomerates;     // absent if not computed
  std::string agglomerate_grid;                      // how the coherence grid was chosen
  double agglomerate_threshold = 0.8;                // the |C| threshold used
  std::filesystem::path summary_path, profile_path;  // profile_path empty if none
  std::filesystem::path agglomerates_path, agglomerate_pdfs_path;  // empty if none
  std::optional<CompactionCurve> compaction;                       // compaction-box runs only
  std::filesystem::path compaction_path;                           // empty if none
  std::optional<AttSeries> att;    // activated thickness per snapshot; absent if unknown
  std::string att_layer_source;    // where H came from
  std::filesystem::path att_path;  // empty if none
  std::filesystem::path space_time_path, cylinders_path;  // empty without agglomerates
  std::optional<CampaignRequest> campaign;  // a campaign's run in the papers' coordinates
};

struct RunInfo;

// The rows of grains/NNNNNN.csv (bodies numbered in build order) that are not grains: the
// driven bodies of series.csv, walls and the shear cell's first bodies. Empty without the
// scenario (nothing can be told apart).
std::vector<std::string> non_grain_rows(const RunInfo& run,
                                        const std::vector<std::string>& driven_bodies);

// Throws sg::Error only when the run folder itself is unusable (no or malformed
// series.csv); anything that merely cannot be computed becomes null plus a note.
AnalyzeResult analyze_run(const std::filesystem::path& run_dir, const AnalyzeOptions& options);

}  // namespace sg
