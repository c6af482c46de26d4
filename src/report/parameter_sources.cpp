#include <cmath>

#include "analysis/coherence_frames.h"
#include "report/analyze_steps.h"

namespace sg::report {
namespace {

// One run parameter: the option if given, else the run's value, else unknown.
double pick(AnalyzeResult& r, const std::string& key, const std::string& unit, double option,
            double from_run, const std::string& run_source) {
  ParameterSource p{key, kNan, unit, "unknown"};
  if (std::isfinite(option)) {
    p.value = option;
    p.source = "option";
  } else if (std::isfinite(from_run)) {
    p.value = from_run;
    p.source = run_source;
  }
  r.parameter_sources.push_back(p);
  return p.value;
}

}  // namespace

void resolve_run_parameters(AnalyzeResult& r, const RunInfo& run, const AnalyzeOptions& options) {
  const std::string scenario_source = "scenario " + run.source.filename().string();
  const RunParameters& sv = run.parameters;
  const RunParameters& g = options.given;
  RunParameters& p = r.parameters;
  p.length = pick(r, "length", "length", g.length, sv.length, scenario_source);
  p.gap = pick(r, "gap", "length", g.gap, sv.gap, scenario_source);
  p.velocity = pick(r, "velocity", "length/time", g.velocity, sv.velocity, scenario_source);
  p.young_modulus =
      pick(r, "young_modulus", "stress", g.young_modulus, sv.young_modulus, scenario_source);
  p.cohesion = pick(r, "cohesion", "force/length", g.cohesion, sv.cohesion, scenario_source);
  p.damping_alpha =
      pick(r, "damping_alpha", "time", g.damping_alpha, sv.damping_alpha, scenario_source);
  p.pressure = pick(r, "pressure", "stress", g.pressure, sv.pressure, scenario_source);
}

void resolve_mean_diameter(AnalyzeResult& r, const Snapshots& snaps,
                           const AnalyzeOptions& options) {
  // Mean equivalent diameter 2 sqrt(A/pi) of the grains in the first snapshot.
  const double measured_diameter =
      snaps.all.empty() ? kNan : mean_equivalent_diameter(snaps.all.front());
  r.parameters.mean_diameter =
      pick(r, "mean_diameter", "length", options.given.mean_diameter, measured_diameter,
           "grains/*.csv (mean 2 sqrt(area/pi), first snapshot)");
}

}  // namespace sg::report
