// [time], [output], [discretization], [physics], [contact] and [periodic] of a scenario file
// (scenario_readers.h).
#include <algorithm>
#include <string>

#include "scenario/scenario_readers.h"

namespace sg {

void read_time(const TomlReader& root, ScenarioDef& s) {
  if (auto t = root.table("time")) {
    t->reject_unknown_keys({"duration", "safety", "fixed_step", "reestimate_interval",
                            "step_tolerance", "mass_scaling_step", "integrator", "imex_tolerance",
                            "imex_refactor_threshold", "imex_dense_factors", "imex_objective",
                            "allow_long_run"});
    s.duration = t->positive("duration");
    s.time_step_safety = t->positive("safety", 0.8);
    if (s.time_step_safety > 1.0) t->fail("safety", "expected a number in (0, 1]");
    s.fixed_time_step = t->non_negative("fixed_step", 0.0);
    s.reestimate_interval = t->integer("reestimate_interval", s.reestimate_interval);
    if (s.reestimate_interval < 0)
      t->fail("reestimate_interval", "expected a number of steps >= 0 (0: never)");
    if (t->has("step_tolerance")) s.step_tolerance = t->non_negative("step_tolerance", 0.0);
    s.mass_scaling_step = t->non_negative("mass_scaling_step", 0.0);
    if (t->has("integrator"))
      s.integrator = t->one_of("integrator", {"explicit", "imex"}, "explicit") == "imex"
                         ? ScenarioIntegrator::imex
                         : ScenarioIntegrator::explicit_integrator;
    s.imex_tolerance = t->positive("imex_tolerance", s.imex_tolerance);
    if (s.imex_tolerance >= 1.0) t->fail("imex_tolerance", "expected a number in (0, 1)");
    s.imex_refactor_threshold =
        t->non_negative("imex_refactor_threshold", s.imex_refactor_threshold);
    s.imex_dense_factors = t->boolean("imex_dense_factors", s.imex_dense_factors);
    if (t->has("imex_objective"))
      s.imex_objective_split = t->one_of("imex_objective", {"split", "exact"}, "split") == "split";
    s.allow_long_run = t->boolean("allow_long_run", false);
  } else {
    root.fail("time", "required table [time] with 'duration' is missing");
  }
}

void read_output(const TomlReader& root, ScenarioDef& s) {
  if (auto t = root.table("output")) {
    t->reject_unknown_keys(
        {"directory", "series_period", "field_period", "checkpoint_period", "field_format"});
    s.output_root = t->string("directory", "out");
    s.series_period = t->non_negative("series_period", 0.0);
    s.field_period = t->non_negative("field_period", 0.0);
    if (t->one_of("field_format", {"binary", "ascii"}, "binary") == "ascii")
      s.field_format = FieldFormat::ascii;
    if (t->has("checkpoint_period"))
      s.checkpoint_period = t->non_negative("checkpoint_period", 0.0);
  }
  if (s.series_period == 0.0) s.series_period = s.duration / 200.0;
  if (s.field_period == 0.0) s.field_period = s.duration / 20.0;
  if (s.checkpoint_period < 0.0) s.checkpoint_period = s.duration / 10.0;  // key absent
}

void read_discretization(const TomlReader& root, ScenarioDef& s) {
  if (auto t = root.table("discretization")) {
    t->reject_unknown_keys({"node_spacing", "interior_spacing", "mls_neighbours",
                            "mls_support_factor", "gauss_points", "smoothing_iterations"});
    s.discretization.mesh.spacing = t->positive("node_spacing", 0.1);
    if (t->has("interior_spacing"))
      s.discretization.mesh.interior_spacing =
          read_node_spacing(*t, NodeSpacing{s.discretization.mesh.spacing, 0.0}).interior;
    s.discretization.mesh.smoothing_iterations =
        static_cast<int>(t->integer("smoothing_iterations", 10));
    s.discretization.mls.neighbours = static_cast<int>(t->integer("mls_neighbours", 8));
    if (s.discretization.mls.neighbours < 3) t->fail("mls_neighbours", "expected an integer >= 3");
    s.discretization.mls.support_factor = t->number("mls_support_factor", 1.0);
    if (s.discretization.mls.support_factor < 1.0)
      t->fail("mls_support_factor", "expected a number >= 1");
    s.discretization.gauss_points = static_cast<int>(t->integer("gauss_points", 3));
    const int gp = s.discretization.gauss_points;
    if (gp != 1 && gp != 3 && gp != 6 && gp != 7) t->fail("gauss_points", "expected 1, 3, 6 or 7");
  }
}

void read_physics(const TomlReader& root, ScenarioDef& s) {
  if (auto t = root.table("physics")) {
    t->reject_unknown_keys({"gravity"});
    s.gravity = t->vec2("gravity", Vec2::Zero());
  }
}

void read_contact_settings(const TomlReader& root, ScenarioDef& s, double cohesive_reach) {
  if (auto t = root.table("contact")) {
    t->reject_unknown_keys({"cutoff", "skin"});
    s.contact_cutoff = t->non_negative("cutoff", 0.0);
    s.contact_skin = t->non_negative("skin", 0.0);
    if (s.contact_cutoff > 0.0 && s.contact_cutoff < cohesive_reach)
      t->fail(
          "cutoff",
          "must be at least the reach of the tensile laws (sigma_c / (2 k_n), g_lim, bond_gap) = " +
              std::to_string(cohesive_reach));
  }
  if (s.contact_cutoff == 0.0)
    s.contact_cutoff = std::max(0.25 * finest_contour_spacing(s), 1.5 * cohesive_reach);
}

void read_periodic(const TomlReader& root, ScenarioDef& s) {
  if (auto t = root.table("periodic")) {
    t->reject_unknown_keys({"x_min", "x_max"});
    s.periodic_x = true;
    s.x_min = t->number("x_min");
    s.x_max = t->number("x_max");
    if (!(s.x_max > s.x_min)) t->fail("x_max", "expected x_max > x_min");
  }
}

}  // namespace sg
