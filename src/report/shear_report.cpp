#include <algorithm>
#include <cmath>

#include "analysis/driven_body.h"
#include "analysis/energy_budget.h"
#include "analysis/friction.h"
#include "analysis/pressure_loading.h"
#include "analysis/steadiness.h"
#include "analysis/steady_state.h"
#include "core/error.h"
#include "report/analyze_steps.h"

namespace sg::report {
namespace {

FrictionStats unknown_friction(const std::string& body) {
  FrictionStats s;
  s.body = body;
  s.normal_force = s.tangential_force = s.mu = s.mu_std = kNan;
  s.normal_stress = s.shear_stress = kNan;
  return s;
}

// The shear cell's driven bodies that have columns in series.csv: both or none.
std::vector<DrivenBody> shear_cell_columns(const Series& series, std::vector<std::string>& notes) {
  std::vector<DrivenBody> bodies;
  for (const DrivenBody& b : shear_cell_bodies())
    if (std::find(series.body_names.begin(), series.body_names.end(), b.name) !=
        series.body_names.end())
      bodies.push_back(b);
  if (bodies.size() != 2) {
    notes.push_back(
        "series.csv has no 'top' and 'bottom' columns (not a shear cell): no "
        "friction, stresses, E~ or c~");
    bodies.clear();
  }
  return bodies;
}

TimeWindow whole_run(const Series& series) {
  TimeWindow window;
  window.first = 0;
  window.last = series.size() - 1;
  window.t_begin = series.column("time")[0];
  window.t_end = series.column("time")[series.size() - 1];
  window.detected = false;
  return window;
}

// The given window, else MSER on the driven bodies' forces after the compaction or load ramp,
// else the whole run. A steady state that cannot be detected (too few rows after the ramp)
// leaves the whole run as window, for what needs none, and its reason in `no_steady_state`.
TimeWindow choose_window(const Series& series, std::span<const DrivenBody> bodies,
                         const AnalyzeOptions& options, double loading_end,
                         std::vector<std::string>& notes, std::string& no_steady_state) {
  TimeWindow window;
  if (options.window) {
    window = window_from_times(series, options.window->first, options.window->second);
    if (window.t_begin < loading_end)
      notes.push_back("window: the given window starts at " + number(window.t_begin) +
                      ", inside the compaction or load ramp (which ends at " + number(loading_end) +
                      ")");
  } else if (!bodies.empty()) {
    try {
      window = detect_steady_window(series, bodies, 5, loading_end);
      if (std::isfinite(loading_end))
        notes.push_back("window: detected after the compaction or load ramp (t >= " +
                        number(loading_end) + ")");
    } catch (const Error& e) {
      no_steady_state = std::string("no steady-state window: ") + e.what();
      notes.push_back(no_steady_state + "; the whole run is the window of what needs none");
      window = whole_run(series);
    }
  } else {
    window = whole_run(series);
    notes.push_back(
        "window: the whole run (no driven shear-cell body to detect a steady state "
        "on; pass --window T0 T1)");
  }
  if (window.truncation_at_limit)
    notes.push_back(
        "window: MSER's truncation hit half the series; the transient may not be "
        "over, the averages are suspect");
  return window;
}

// Notes for the dimensionless parameters that stayed unknown, naming the missing input.
void note_dimensionless_gaps(const AnalyzeResult& r, std::vector<std::string>& notes) {
  const RunParameters& p = r.parameters;
  const AnalysisSummary& s = r.summary;
  if (std::isfinite(coordinate_normal_stress(s.imposed_pressure, s.friction.mean.normal_stress))) {
    if (!std::isfinite(p.young_modulus)) notes.push_back("E~ null: E unknown (pass --young)");
    if (!(p.cohesion > 0.0)) notes.push_back("c~ null: cohesion unknown or 0");
  }
  if (!std::isfinite(s.dimensionless.viscosity)) {
    std::string missing;
    if (!std::isfinite(p.velocity)) missing += "V unknown; ";
    if (!std::isfinite(p.gap)) missing += "D unknown; ";
    notes.push_back("alpha~ null: needs alpha > 0, V and D (" + missing +
                    "alpha = " + number(p.damping_alpha) + ")");
  }
}

}  // namespace

void analyze_shear(AnalyzeResult& r, const Series& series, const RunInfo& run,
                   const AnalyzeOptions& options, const std::filesystem::path& run_dir) {
  std::vector<std::string>& notes = r.notes;
  const std::vector<DrivenBody> bodies = shear_cell_columns(series, notes);
  AnalysisSummary& s = r.summary;
  std::string no_steady_state;
  s.window = choose_window(series, bodies, options, run.loading_end, notes, no_steady_state);
  measure_gap(r, series, run, run_dir);
  s.friction.mean = unknown_friction("mean");
  std::string why_no_mu = "series.csv has no 'top' and 'bottom' columns";
  if (!no_steady_state.empty()) {
    why_no_mu = no_steady_state;  // a friction coefficient is a steady state's
  } else if (!bodies.empty()) {
    try {
      s.friction = compute_friction(series, bodies, s.window, r.parameters.length);
      why_no_mu = "mu is not finite";
    } catch (const Error& e) {
      notes.push_back(std::string("friction not computed: ") + e.what());
      why_no_mu = e.what();
      s.friction.bodies.clear();
      s.friction.mean = unknown_friction("mean");
    }
  }
  // A shear cell is run to measure its friction: failing to is not a success.
  if ((run.shear_cell || !bodies.empty()) && !std::isfinite(s.friction.mean.mu))
    r.unmeasured.push_back({"mu", why_no_mu});
  // Under pressure loading E~ and c~ are the imposed coordinates: sigma_n = p
  // (analysis/pressure_loading.h); each body's measured sigma_n stays in the summary.
  s.imposed_pressure = r.parameters.pressure > 0.0 ? r.parameters.pressure : kNan;
  s.dimensionless = compute_dimensionless(
      r.parameters, coordinate_normal_stress(s.imposed_pressure, s.friction.mean.normal_stress));
  note_dimensionless_gaps(r, notes);
  try {
    s.energy = compute_energy_budget(series, s.window, s.friction.mean.mu,
                                     s.friction.mean.normal_force, r.parameters.velocity);
  } catch (const Error& e) {
    notes.push_back(std::string("energy budget not computed: ") + e.what());
  }
  if (!bodies.empty() && std::isfinite(s.friction.mean.mu)) {
    s.warnings = check_steadiness(series, s.window, bodies, s.friction, s.energy,
                                  r.parameters.velocity, options.steadiness);
    if (auto w = check_imposed_pressure(s.friction, s.imposed_pressure,
                                        options.steadiness.pressure_mismatch))
      s.warnings.push_back(std::move(*w));
  }
}

}  // namespace sg::report
