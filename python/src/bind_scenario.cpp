// softgrain.Scenario: a checked scenario, read from a TOML file or TOML text with the command
// line's own checks and messages (load_scenario, scenario/scenario.h), and the text it was
// read from (to_toml()). The dict side (Scenario.from_dict, to_dict) is Python's
// (softgrain/scenario_dict.py): a dict is written as TOML text and read here, so that every
// rule and message is the same, and an error's line is a line of to_toml()'s text.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fstream>
#include <sstream>

#include "bindings.h"
#include "model/force_kernel.h"
#include "run/simulation.h"
#include "solver/integrator_comparison.h"

namespace sg::python {

namespace {

// The file name a scenario built in memory carries in messages; relative file keys resolve
// against its folder.
std::filesystem::path memory_source(const std::optional<std::filesystem::path>& base_dir) {
  return base_dir ? *base_dir / "<dict>" : std::filesystem::path("<dict>");
}

Scenario from_toml_text(const std::string& text,
                        const std::optional<std::filesystem::path>& base_dir) {
  return Scenario{load_scenario_text(text, memory_source(base_dir)), text};
}

Scenario from_file(const std::filesystem::path& file) {
  Scenario s;
  s.def = load_scenario(file);  // every check and message of the command line
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  s.toml = text.str();
  return s;
}

// What `softgrain info` prints (app/commands/info_command.cpp), as a dict; the model is built
// as `run` builds it (run/simulation.h: contacts, mass scaling, the first step estimate).
// With `timing` and a damped body, both integrators' step and measured cost, as the command
// line prints them (solver/integrator_comparison.h; the model is left as it was).
py::list integrator_costs(Simulation& sim, const ScenarioDef& def) {
  const IntegratorParams& configured = sim.integrator.params;
  const double contact_stiffness = sim.contacts ? sim.contacts->max_stiffness() : 0.0;
  std::array<IntegratorCost, 2> costs;
  {
    py::gil_scoped_release release;
    costs = compare_integrators(sim.model, sim.contacts.get(), def.time_step_safety,
                                contact_stiffness, imex_integrator(def), 10);
  }
  py::list out;
  for (const IntegratorCost& c : costs) {
    py::dict d;
    d["integrator"] = c.integrator.name();
    d["stable_step"] = c.stable.dt;
    d["step_limit"] = c.stable.damping_limited ? "damping-limited" : "wave-speed-limited";
    d["seconds_per_step"] = c.seconds_per_step;
    d["seconds_per_time_unit"] = c.seconds_per_step / c.stable.dt;
    d["hours_for_duration"] = c.seconds_per_step / c.stable.dt * def.duration / 3600.0;
    d["configured"] = c.integrator.implicit_viscosity == configured.implicit_viscosity;
    if (c.integrator.implicit_viscosity) d["factors_mib"] = c.matrix_bytes / 1048576.0;
    out.append(d);
  }
  return out;
}

bool has_damped_body(const Model& model) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.is_damped(static_cast<BodyId>(b))) return true;
  return false;
}

py::dict info(const Scenario& s, bool timing) {
  std::unique_ptr<Simulation> sim;
  {
    py::gil_scoped_release release;
    sim = std::make_unique<Simulation>(s.def);
  }
  const Model& model = sim->model;
  const StableStep& stable = sim->first_estimate;
  py::dict d;
  d["name"] = s.def.name;
  d["source"] = s.def.source.string();
  d["bodies"] = model.bodies.size();
  d["materials"] = model.materials.size();
  d["field_nodes"] = model.node_count();
  d["gauss_points"] = model.gauss_point_count();
  d["neighbours_per_gauss_point"] =
      static_cast<double>(model.gauss_rows.entries()) /
      static_cast<double>(std::max<std::size_t>(1, model.gauss_point_count()));
  if (stable.limiting_body >= 0) {
    d["stable_step"] = stable.dt;
    d["step_limit"] = stable.damping_limited ? "damping-limited" : "wave-speed-limited";
    d["limiting_body"] = model.body(stable.limiting_body).name;
    d["contact_share"] = stable.contact_share;  // of the limiting body's omega^2
    d["steps"] = static_cast<long>(s.def.duration / stable.dt);
  }
  d["first_step"] = sim->first_dt;
  d["integrator"] = sim->solver.integrator().name();
  d["integrator_choice"] = describe(sim->integrator);  // why, when chosen by default
  d["duration"] = s.def.duration;
  if (!sim->mass_scaling_note.empty()) d["mass_scaling"] = sim->mass_scaling_note.substr(2);
  const double bytes = static_cast<double>(model.node_count()) * 12 * sizeof(double) +
                       static_cast<double>(model.gauss_rows.entries()) * (4 * sizeof(double) + 4) +
                       static_cast<double>(model.node_rows.entries()) * (4 * sizeof(double) + 4);
  d["memory_mib"] = bytes / 1048576.0;
  d["force_kernel"] = force_kernel().isa;
  // The checkpoint fingerprint: equal hashes, same model and run settings.
  d["model_hash"] = sim->fingerprint.model_hash;
  d["settings_hash"] = sim->fingerprint.settings_hash;
  if (timing && stable.limiting_body >= 0 && has_damped_body(model))
    d["integrators"] = integrator_costs(*sim, s.def);
  return d;
}

}  // namespace

void bind_scenario(py::module_& m) {
  py::class_<Scenario>(m, "Scenario", R"(A checked scenario (docs/scenario.md lists every key).

Build one with Scenario.from_file(path), Scenario.from_dict(d) (the keys of the TOML file,
nested dicts for tables, lists of dicts for arrays of tables) or Scenario.from_toml(text);
to_dict() and to_toml() give it back.
Errors raise softgrain.ScenarioError with file, line, key and detail.)")
      .def_static("from_file", &from_file, py::arg("path"),
                  "Reads and checks a scenario file, as `softgrain run` does.")
      .def_static("from_toml", &from_toml_text, py::arg("text"), py::arg("base_dir") = py::none(),
                  "A scenario from TOML text; relative file keys resolve against base_dir "
                  "(default: the working folder); its file in messages is '<dict>'.")
      .def(
          "to_toml", [](const Scenario& s) { return s.toml; },
          "The TOML text the scenario was read from: the file as written (comments kept), or "
          "the text from_dict wrote; from_toml of it (with base_dir) builds the same model.")
      .def("info", &info, py::arg("timing") = true,
           "What `softgrain info` prints, as a dict: bodies, field nodes, Gauss points, stable "
           "and first step, steps, memory, force kernel, and the checkpoint fingerprint's "
           "model_hash and settings_hash. Builds the model (seconds for large scenarios). "
           "With timing and a damped body, 'integrators': for the explicit and the IMEX "
           "integrator, the stable step, its limit, the measured seconds per step (10 steps) "
           "and per time unit, the hours for the duration, and which one [time] configures.")
      .def_property_readonly(
          "name", [](const Scenario& s) { return s.def.name; },
          "The run name (the run folder is <output root>/<name>).")
      .def_property_readonly(
          "duration", [](const Scenario& s) { return s.def.duration; }, "Simulated time.")
      .def_property_readonly(
          "source", [](const Scenario& s) { return s.def.source.string(); },
          "The scenario file ('<dict>' under base_dir for one built in memory).")
      .def_property_readonly(
          "base_dir", [](const Scenario& s) { return s.def.source.parent_path().string(); },
          "The folder relative file keys resolve against ('' : the working folder).")
      .def("__repr__", [](const Scenario& s) {
        return "softgrain.Scenario(name=" + py::repr(py::str(s.def.name)).cast<std::string>() +
               ", source=" + py::repr(py::str(s.def.source.string())).cast<std::string>() + ")";
      });
}

}  // namespace sg::python
