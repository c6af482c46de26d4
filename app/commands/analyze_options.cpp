#include "analyze_options.h"

#include <algorithm>

namespace sg::app {

void add_analyze_options(CLI::App& cmd, AnalyzeArguments& a) {
  cmd.add_option("run_dir", a.run_dir, "run folder (holds series.csv)")->required();
  cmd.add_option("--window", a.window,
                 "averaging window T0 T1 (default: MSER-5 steady state, or the whole run)")
      ->expected(2);
  cmd.add_option("--length", a.length, "L, period of the cell (default: scenario)");
  cmd.add_option("--gap", a.gap, "D, gap between the first bodies (default: scenario)");
  cmd.add_option("--velocity", a.velocity, "V, sliding velocity (default: scenario)");
  cmd.add_option("--young", a.young, "E of the grains (default: scenario)");
  cmd.add_option("--cohesion", a.cohesion, "c, cohesion (default: scenario)");
  cmd.add_option("--alpha", a.alpha, "alpha, Rayleigh damping (default: scenario)");
  cmd.add_option("--diameter", a.diameter, "mean grain diameter (default: from grains/*.csv)");
  cmd.add_option("--layer", a.layer,
                 "layer bounds Y0 Y1 for profiles and solid fraction (default: grains)")
      ->expected(2);
  cmd.add_option("--bins", a.bins, "profile bins (default: two per mean diameter)");
  cmd.add_flag("--no-agglomerates", a.no_agglomerates, "skip the coherence analysis");
  cmd.add_option("--coherence-threshold", a.threshold,
                 "|C| above which a grid node belongs to a structure (paper 002: 0.8)")
      ->check(CLI::Range(0.0, 1.0).description("in (0, 1)"))
      ->capture_default_str();
  cmd.add_option("--att-thresholds", a.att_thresholds,
                 "shares of the velocity jump LO HI bounding the activated third-body "
                 "thickness (paper 003: 0.2 0.8)")
      ->expected(2);
  cmd.add_option("--stress-imbalance", a.stress_imbalance,
                 "warn when the top and bottom mean normal stresses differ by more than "
                 "this fraction of their mean (docs/analysis.md, steadiness checks)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  CLI::Option* plots = cmd.add_flag(
      "--plots", a.plots,
      "draw mu(t), profiles, energy shares, agglomerate PDFs, the compaction curve and, "
      "for a shear cell, the composite figure (the last frame's velocity, strain rate "
      "and stress, drawn into RUN_DIR/render/, beside mu(t), the profiles and the run's "
      "place in (E~, c~, alpha~)) into RUN_DIR/analysis/*.png "
      "(default: on when /usr/bin/python3 imports matplotlib)");
  cmd.add_flag("--no-plots", a.no_plots, "no plots")->excludes(plots);
}

std::string analyze_options_error(const std::vector<std::string>& options) {
  CLI::App check("analyze");
  check.set_help_flag();  // "--help" is no analysis option either
  AnalyzeArguments ignored;
  add_analyze_options(check, ignored);
  std::vector<std::string> arguments = {"RUN_DIR"};
  arguments.insert(arguments.end(), options.begin(), options.end());
  std::reverse(arguments.begin(), arguments.end());  // CLI11 consumes the vector from its back
  try {
    check.parse(arguments);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace sg::app
