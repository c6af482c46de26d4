#pragma once
// Every scalar of the analysis in one struct, and its two renderings: analysis/summary.json
// (each value with its unit and definition, so the file explains itself) and a terminal
// table. Quantities that could not be computed (unknown run parameter, no snapshot) are
// NaN in the struct and null in the JSON.
//
// summary.json layout (version 1):
//   { "format": "softgrain-analysis-summary", "version": 1,
//     "softgrain": { "version": "0.1.0", "commit": "<git hash>[-dirty]" | "unknown" },
//     "quantities": { "<key>": { "value": <number|null>, "unit": "...",
//                                "definition": "..." }, ... },
//     "warnings": [ { "check": "mu_trend", "message": "..." }, ... ] }
// Keys are stable; readers should refuse a version they do not know.
#include <optional>
#include <string>
#include <vector>

#include "analysis/agglomerate_statistics.h"
#include "analysis/energy_budget.h"
#include "analysis/friction.h"
#include "analysis/steadiness.h"
#include "analysis/steady_state.h"

namespace sg {

struct AnalysisSummary {
  TimeWindow window;
  FrictionResult friction;
  DimensionlessParameters dimensionless;
  // p imposed on the loaded first body under pressure loading, the sigma_n of E~ and c~
  // (analysis/pressure_loading.h); NaN under gap loading.
  double imposed_pressure = RunParameters::kUnknown;
  std::optional<EnergyBudget> energy;  // absent if the budget is undefined
  double solid_fraction = RunParameters::kUnknown;
  // Activated third-body thickness, mean over the window's snapshots (activated_thickness.h).
  double att_map = RunParameters::kUnknown, att_profile = RunParameters::kUnknown;
  std::optional<AgglomerateStatistics> agglomerates;  // absent without snapshots
  // The steadiness checks the window failed (analysis/steadiness.h); empty: none failed, or
  // not checked (no friction).
  std::vector<SteadinessWarning> warnings;
};

struct SummaryEntry {
  std::string key;
  double value = 0.0;
  std::string unit;        // "1" for dimensionless; otherwise in the run's units
  std::string definition;  // formula and paper reference
};

// The flat list of quantities, in a fixed order: the single source of keys, units and
// definitions for both the JSON and the table.
std::vector<SummaryEntry> summary_entries(const AnalysisSummary& summary);

// The JSON document as text (tests parse it back); `extra` entries (e.g.
// compaction_summary_entries) follow the summary's own quantities.
std::string summary_json(const AnalysisSummary& summary,
                         const std::vector<SummaryEntry>& extra = {});

// Writes <path> atomically (write "<path>.tmp", then rename).
void write_summary_json(const std::string& path, const AnalysisSummary& summary);

// A human-readable table: key, value, unit, one line each; absent values shown as "-".
std::string format_summary_table(const AnalysisSummary& summary);

// The rows of that table for `entries` (no header), keys padded to at least `key_width`:
// for other lists of entries in the same layout (e.g. compaction_summary_entries).
std::string format_summary_rows(const std::vector<SummaryEntry>& entries, std::size_t key_width);

}  // namespace sg
