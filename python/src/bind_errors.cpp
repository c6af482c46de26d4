// Every sg::Error (src/core/error.h) leaving a call into the module becomes the exception
// softgrain/errors.py makes of its message: a ScenarioError carrying file, line, key and
// detail when the message names a scenario place, else a softgrain.Error. The message is
// parsed in Python (one regular expression, next to the classes) rather than carried as
// fields through the engine: every scenario error is already written in that one form by
// TomlReader::fail, and the command line prints the same text.
#include "bindings.h"

#include "core/error.h"

namespace sg::python {

void bind_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const sg::Error& e) {
      const py::object error =
          py::module_::import("softgrain.errors").attr("error_from_message")(e.what());
      PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
    }
  });
}

}  // namespace sg::python
