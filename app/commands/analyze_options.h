// The options of `softgrain analyze`, declared once: for the subcommand itself and for
// `softgrain sweep`, which checks a campaign's analyze_options before it runs anything (a
// misspelt option would otherwise fail every run's analysis after its simulation).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "report/analyze_run.h"

namespace sg::app {

struct AnalyzeArguments {
  std::string run_dir;
  std::vector<double> window, layer;
  double length = RunParameters::kUnknown, gap = RunParameters::kUnknown,
         velocity = RunParameters::kUnknown, young = RunParameters::kUnknown,
         cohesion = RunParameters::kUnknown, alpha = RunParameters::kUnknown,
         diameter = RunParameters::kUnknown;
  int bins = 0;
  bool no_agglomerates = false;
  double threshold = 0.8;
  std::vector<double> att_thresholds;
  double stress_imbalance = SteadinessThresholds{}.stress_imbalance;
  bool plots = false, no_plots = false;
};

// Declares RUN_DIR and every option of `analyze` on `cmd`, stored into `a`.
void add_analyze_options(CLI::App& cmd, AnalyzeArguments& a);

// Empty if `analyze RUN_DIR <options>` parses; else what CLI11 says is wrong with them.
std::string analyze_options_error(const std::vector<std::string>& options);

}  // namespace sg::app
