#pragma once
// The compiled part of the Python module (softgrain._softgrain), one file per role, gathered
// by module.cpp:
//   bind_errors.cpp      sg::Error -> softgrain.Error / softgrain.ScenarioError
//   bind_scenario.cpp    Scenario: from a file or TOML text; to_toml, info (the dict side,
//                        from_dict and to_dict, is softgrain/scenario_dict.py)
//   bind_simulation.cpp  Simulation: a run stepped from Python (run/run_session.h), with
//                        read-only zero-copy NumPy views of its state
//   bind_campaign.cpp    the campaign's process queue (softgrain.run_scenarios)
// The pure-Python part (softgrain/*.py) reads run folders, writes dicts as TOML, defines the
// exceptions and runs scenario lists through the queue.
#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>

#include "scenario/scenario.h"

namespace sg::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_scenario(py::module_& m);
void bind_simulation(py::module_& m);
void bind_campaign(py::module_& m);

// A scenario as the module holds it: the checked definition, and the same scenario as TOML
// text (what to_toml() returns, and what a checkpoint written from Python keeps beside it).
struct Scenario {
  ScenarioDef def;
  std::string toml;
};

}  // namespace sg::python
