// softgrain.Scenario: a checked scenario, read from a TOML file, built from a Python dict with
// the file's keys, or from TOML text. The checks are the command line's own (load_scenario,
// scenario/scenario.h): a dict is turned into a TOML table, written as TOML text and read as
// a file would be, so that every rule and every message is the same, and an error's line is
// a line of to_toml()'s text.
//
// The dict is kept as a toml++ table: to_dict() and to_toml() give it back (key order aside:
// toml++ sorts keys), and from_dict(s.to_dict()) builds the same model (the tests compare
// the checkpoint fingerprints of both, which hash every fixed datum of the model).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <toml++/toml.h>
#include <sstream>
#include <variant>

#include "bindings.h"
#include "model/force_kernel.h"
#include "run/simulation.h"

namespace sg::python {

namespace {

// A TOML value made from a Python value (one type, so that the conversion is one recursive
// function rather than a template instantiated per nesting level).
using TomlValue = std::variant<bool, std::int64_t, double, std::string, toml::array, toml::table>;

TomlValue toml_value(py::handle v, const std::string& key);

template <class Container, class... Key>
void put(Container& container, TomlValue value, const Key&... key) {
  std::visit(
      [&](auto&& x) {
        if constexpr (sizeof...(Key) == 0)
          container.push_back(std::move(x));
        else
          container.insert_or_assign(key..., std::move(x));
      },
      std::move(value));
}

toml::table table_from_dict(const py::dict& dict, const std::string& where) {
  toml::table table;
  for (auto [k, v] : dict) {
    if (!py::isinstance<py::str>(k))
      throw py::type_error("scenario keys are strings; got " + py::repr(k).cast<std::string>() +
                           (where.empty() ? "" : " in '" + where + "'"));
    const std::string key = k.cast<std::string>();
    put(table, toml_value(v, where.empty() ? key : where + "." + key), key);
  }
  return table;
}

// The TOML value of the Python value `v` (at key `key`, for messages).
TomlValue toml_value(py::handle v, const std::string& key) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
  if (py::isinstance<py::int_>(v)) return v.cast<std::int64_t>();
  if (py::isinstance<py::float_>(v)) return v.cast<double>();
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::dict>(v)) return table_from_dict(v.cast<py::dict>(), key);
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    toml::array array;
    std::size_t i = 0;
    for (py::handle item : v)
      put(array, toml_value(item, key + "[" + std::to_string(i++) + "]"));
    return array;
  }
  if (py::hasattr(v, "__fspath__"))  // pathlib.Path for file keys
    return py::module_::import("os").attr("fspath")(v).cast<std::string>();
  if (py::hasattr(v, "tolist")) return toml_value(v.attr("tolist")(), key);  // NumPy values
  throw py::type_error("scenario key '" + key + "': a " +
                       py::str(py::type::of(v).attr("__name__")).cast<std::string>() +
                       " cannot be written in TOML (numbers, strings, booleans, lists and "
                       "dicts can)");
}

py::object to_python(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: {
      py::dict dict;
      for (auto&& [key, value] : *node.as_table())
        dict[py::str(std::string(key.str()))] = to_python(value);
      return dict;
    }
    case toml::node_type::array: {
      py::list list;
      for (const toml::node& item : *node.as_array())
        list.append(to_python(item));
      return list;
    }
    case toml::node_type::string:
      return py::str(*node.value<std::string>());
    case toml::node_type::integer:
      return py::int_(*node.value<std::int64_t>());
    case toml::node_type::floating_point:
      return py::float_(*node.value<double>());
    case toml::node_type::boolean:
      return py::bool_(*node.value<bool>());
    default: {  // dates and times: no scenario key takes one; kept as their text
      std::ostringstream text;
      node.visit([&](const auto& value) { text << value; });
      return py::str(text.str());
    }
  }
}

std::string toml_text(const toml::table& table) {
  std::ostringstream text;
  text << toml::toml_formatter{table} << "\n";
  return text.str();
}

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
  s.toml = toml_text(toml::parse_file(file.string()));
  return s;
}

Scenario from_dict(const py::dict& dict, const std::optional<std::filesystem::path>& base_dir) {
  toml::table table = table_from_dict(dict, "");
  if (!table.contains("name")) table.insert("name", "scenario");
  return from_toml_text(toml_text(table), base_dir);
}

// What `softgrain info` prints (app/commands/info_command.cpp), as a dict; the model is built
// as `run` builds it (run/simulation.h: contacts, mass scaling, the first step estimate),
// without the integrators' timing.
py::dict info(const Scenario& s) {
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
    d["limiting_body"] = model.bodies[static_cast<std::size_t>(stable.limiting_body)].name;
    d["steps"] = static_cast<long>(s.def.duration / stable.dt);
  }
  d["first_step"] = sim->first_dt;
  d["integrator"] = model.implicit_viscosity ? "imex" : "explicit";
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
  return d;
}

}  // namespace

void bind_scenario(py::module_& m) {
  py::class_<Scenario>(m, "Scenario", R"(A checked scenario (docs/scenario.md lists every key).

Build one with Scenario.from_file(path), Scenario.from_dict(d) (the keys of the TOML file,
nested dicts for tables, lists of dicts for arrays of tables) or Scenario.from_toml(text).
Errors raise softgrain.ScenarioError with file, line, key and detail.)")
      .def_static("from_file", &from_file, py::arg("path"),
                  "Reads and checks a scenario file, as `softgrain run` does.")
      .def_static("from_dict", &from_dict, py::arg("d"), py::arg("base_dir") = py::none(),
                  "A scenario from a dict with the keys of the TOML file. `name` defaults to "
                  "'scenario'; relative file keys resolve against base_dir (default: the working "
                  "folder). An error's line is a line of to_toml()'s text; its file is '<dict>'.")
      .def_static("from_toml", &from_toml_text, py::arg("text"), py::arg("base_dir") = py::none(),
                  "A scenario from TOML text (as from_dict for names and relative files).")
      .def(
          "to_dict", [](const Scenario& s) { return to_python(toml::parse(s.toml)); },
          "The scenario's keys as a dict (a new one each call: change it and pass it to "
          "from_dict).")
      .def(
          "to_toml", [](const Scenario& s) { return s.toml; },
          "The scenario as TOML text (keys sorted, comments dropped); from_toml of it builds "
          "the same model.")
      .def("info", &info,
           "What `softgrain info` prints, as a dict: bodies, field nodes, Gauss points, stable "
           "and first step, steps, memory, force kernel, and the checkpoint fingerprint's "
           "model_hash and settings_hash. Builds the model (seconds for large scenarios).")
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
