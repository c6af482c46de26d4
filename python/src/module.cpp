// softgrain._softgrain: the compiled module (bindings.h lists its parts). The package
// softgrain/__init__.py imports it; users import `softgrain`.
#include "bindings.h"

PYBIND11_MODULE(_softgrain, m) {
  m.doc() = "softgrain's compiled core: scenarios and in-process runs (import softgrain).";
  // The command line's version: the project VERSION of CMakeLists.txt.
  m.attr("__version__") = SOFTGRAIN_VERSION;
  sg::python::bind_errors(m);
  sg::python::bind_scenario(m);
  sg::python::bind_simulation(m);
  sg::python::bind_campaign(m);
}
