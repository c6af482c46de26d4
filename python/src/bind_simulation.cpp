// softgrain.Simulation: a run stepped from Python. It is the command line's run loop itself
// (run/run_session.h), not a copy of it: with an output folder, stepping to the end writes the
// files `softgrain run` writes, bitwise (python/tests/test_simulation.py compares them), and
// without one the same steps run with no file written.
//
// The state is shown through read-only NumPy arrays over the engine's own arrays (zero-copy:
// they follow the state step after step without a new call, and cost nothing to take): the
// node arrays (structure of arrays, model/model.h), the rigid bodies' state and the energy
// ledger. They stay valid as long as the Simulation; the engine never reallocates them while
// stepping (the node and body counts are fixed at build). Quantities the engine does not store
// (physical node positions through the MLS rows, deformable bodies' centres) are computed into
// new arrays by methods.
//
// Stepping releases the GIL; the OpenMP thread count asked for is set around each call into the
// engine and the caller's restored after, so two Simulations with different counts coexist.
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "bindings.h"
#include "core/error.h"
#include "model/body_motion.h"
#include "model/kinematics.h"
#include "run/run_session.h"

namespace sg::python {

namespace {

// Sets the OpenMP thread count for the scope (0: leave it), restores the caller's after.
class ThreadCount {
 public:
  explicit ThreadCount(int threads) : previous_(omp_get_max_threads()), set_(threads > 0) {
    if (set_) omp_set_num_threads(threads);
  }
  ~ThreadCount() {
    if (set_) omp_set_num_threads(previous_);
  }
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

 private:
  int previous_;
  bool set_;
};

// A read-only one-dimensional NumPy view of `v`, keeping `owner` alive.
template <class T>
py::array view(const std::vector<T>& v, py::handle owner) {
  py::array a(py::dtype::of<T>(), {v.size()}, {sizeof(T)}, v.data(), owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

// The ledger's fields: a structured NumPy dtype over the struct itself.
struct LedgerField {
  const char* name;
  std::size_t offset;
};
#define SG_LEDGER_FIELD(f)        \
  LedgerField {                   \
#f, offsetof(EnergyLedger, f) \
  }
constexpr LedgerField kLedgerFields[] = {SG_LEDGER_FIELD(kinetic),
                                         SG_LEDGER_FIELD(elastic),
                                         SG_LEDGER_FIELD(external_work),
                                         SG_LEDGER_FIELD(damping_dissipated),
                                         SG_LEDGER_FIELD(contact_dissipated),
                                         SG_LEDGER_FIELD(servo_dissipated),
                                         SG_LEDGER_FIELD(contact_elastic),
                                         SG_LEDGER_FIELD(step_change),
                                         SG_LEDGER_FIELD(initial_kinetic),
                                         SG_LEDGER_FIELD(initial_elastic)};
#undef SG_LEDGER_FIELD
static_assert(sizeof(EnergyLedger) == std::size(kLedgerFields) * sizeof(double),
              "EnergyLedger changed: update kLedgerFields (and the stubs, softgrain/*.pyi)");

class PySimulation {
 public:
  PySimulation(const Scenario& scenario, int threads,
               const std::optional<std::filesystem::path>& output, bool progress,
               const std::optional<std::filesystem::path>& resume)
      : scenario_(scenario), threads_(threads) {
    SG_VERIFY(threads >= 0,
              "Simulation: threads must be 0 (OpenMP's count) or more, got " << threads);
    RunOptions options;
    options.progress = progress ? &std::cerr : nullptr;
    options.write_outputs = output.has_value();
    if (output) options.output_root_override = *output;
    if (resume) {
      options.resume = true;
      options.resume_checkpoint = *resume;
    }
    {
      py::gil_scoped_release release;
      const ThreadCount count(threads_);
      session_ = std::make_unique<RunSession>(scenario_.def, options);
    }
    const Model& model = session_->simulation().model;
    node_body_.resize(model.node_count());
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      const Body& body = model.bodies[b];
      for (int i = body.node_begin; i < body.node_end; ++i)
        node_body_[static_cast<std::size_t>(i)] = static_cast<int>(b);
      if (body.kind == BodyKind::rigid) {
        const auto r = static_cast<std::size_t>(body.rigid_index);
        if (rigid_body_.size() <= r) rigid_body_.resize(r + 1);
        rigid_body_[r] = static_cast<int>(b);
      }
    }
  }

  ~PySimulation() {
    if (session_ && !session_->closed()) {
      try {
        session_->close();
      } catch (const std::exception&) {
        // A destructor must not throw; close() explicitly to see such an error.
      }
    }
  }

  bool reached_end() const { return session_->reached_end(); }

  // Steps until `until` (the duration if none), calling `callback(self)` every `every` steps;
  // false from the callback stops the run. Closes the run when it reaches its duration.
  // Returns false if the callback stopped it, true otherwise.
  bool run(py::object self, std::optional<double> until, long every, py::object callback) {
    SG_VERIFY(every >= 1, "run(): every must be at least 1, got " << every);
    const double target = until ? std::min(*until, scenario_.def.duration) : scenario_.def.duration;
    const double tolerance = 1e-12 * scenario_.def.duration;  // the run loop's own
    auto target_reached = [&] {
      return session_->reached_end() ||
             session_->simulation().solver.state().time >= target - tolerance;
    };
    while (!target_reached()) {
      check_open();
      {
        py::gil_scoped_release release;
        const ThreadCount count(threads_);
        for (long k = 0; k < every && !target_reached(); ++k)
          session_->step();
      }
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C between batches
      if (!callback.is_none()) {
        const py::object answer = callback(self);
        if (!answer.is_none() && !answer.cast<bool>()) {
          close_if_ended();  // stopped on the last step: the run is complete all the same
          return false;
        }
      }
    }
    close_if_ended();
    return true;
  }

  void step() {
    check_open();
    SG_VERIFY(!session_->reached_end(), "run '" << scenario_.def.name
                                                << "': the run has reached its duration "
                                                << scenario_.def.duration);
    {
      py::gil_scoped_release release;
      const ThreadCount count(threads_);
      session_->step();
    }
    close_if_ended();
  }

  void close() {
    if (!session_->closed()) session_->close();
  }

  void checkpoint(const std::filesystem::path& path) {
    check_open();
    {
      const ThreadCount count(threads_);
      session_->write_checkpoint(path);
    }
    // The scenario beside it, so that Simulation.resume(path) needs nothing else.
    const std::filesystem::path side_path = path.string() + ".toml";
    std::ofstream side(side_path);
    side << scenario_.toml;
    SG_VERIFY(side.good(), "cannot write '" << side_path.string() << "'");
  }

  const Simulation& sim() const { return session_->simulation(); }
  const Scenario& scenario() const { return scenario_; }
  const RunSession& session() const { return *session_; }
  const std::vector<int>& node_body() const { return node_body_; }
  const std::vector<int>& rigid_body() const { return rigid_body_; }
  int threads() const { return threads_; }

 private:
  Scenario scenario_;
  int threads_;
  std::unique_ptr<RunSession> session_;
  std::vector<int> node_body_;   // body of each node (fixed)
  std::vector<int> rigid_body_;  // body of each rigid-state entry (fixed)

  void check_open() const {
    SG_VERIFY(!session_->closed(), "run '" << scenario_.def.name << "': the run is closed");
  }
  void close_if_ended() {
    if (session_->reached_end() && !session_->closed()) session_->close();
  }
};

py::dict node_views(py::object self) {
  const PySimulation& s = self.cast<const PySimulation&>();
  const NodeState& n = s.sim().model.nodes;
  py::dict d;
  d["ref_x"] = view(n.ref_x, self);
  d["ref_y"] = view(n.ref_y, self);
  d["ux"] = view(n.ux, self);
  d["uy"] = view(n.uy, self);
  d["vx"] = view(n.vx, self);
  d["vy"] = view(n.vy, self);
  d["fx"] = view(n.fx, self);
  d["fy"] = view(n.fy, self);
  d["mass"] = view(n.mass, self);
  d["body"] = view(s.node_body(), self);
  return d;
}

py::dict rigid_views(py::object self) {
  const PySimulation& s = self.cast<const PySimulation&>();
  const RigidState& r = s.sim().model.rigid;
  py::dict d;
  d["body"] = view(s.rigid_body(), self);
  d["x"] = view(r.x, self);
  d["y"] = view(r.y, self);
  d["theta"] = view(r.theta, self);
  d["vx"] = view(r.vx, self);
  d["vy"] = view(r.vy, self);
  d["omega"] = view(r.omega, self);
  d["fx"] = view(r.fx, self);
  d["fy"] = view(r.fy, self);
  d["torque"] = view(r.torque, self);
  return d;
}

py::array energy_view(py::object self) {
  const PySimulation& s = self.cast<const PySimulation&>();
  py::list names, formats, offsets;
  for (const LedgerField& field : kLedgerFields) {
    names.append(field.name);
    formats.append(py::dtype::of<double>());
    offsets.append(field.offset);
  }
  const py::dtype ledger(names, formats, offsets, sizeof(EnergyLedger));
  py::array a(ledger, std::vector<py::ssize_t>{}, std::vector<py::ssize_t>{},
              &s.sim().solver.state().energy, self);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

// Physical node positions or velocities (n, 2), through the rows (model/kinematics.h).
py::array_t<double> node_vectors(const PySimulation& s, bool velocities) {
  const Model& model = s.sim().model;
  const auto n = static_cast<py::ssize_t>(model.node_count());
  py::array_t<double> out({n, py::ssize_t{2}});
  auto o = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const Vec2 p = velocities ? node_velocity(model, static_cast<int>(i))
                              : node_position(model, static_cast<int>(i));
    o(i, 0) = p.x();
    o(i, 1) = p.y();
  }
  return out;
}

// Per body: centre of mass, its velocity (as grains/NNNNNN.csv: the lumped nodes of a
// deformable body, the rigid state of a rigid one), rotation angle, kind and name.
py::dict bodies(const PySimulation& s) {
  const Model& model = s.sim().model;
  const auto count = static_cast<py::ssize_t>(model.bodies.size());
  py::array_t<double> x(count), y(count), vx(count), vy(count), theta(count);
  py::array_t<bool> rigid(count);
  py::list names;
  for (py::ssize_t b = 0; b < count; ++b) {
    const Body& body = model.body(static_cast<BodyId>(b));
    const BodyMotion motion = body_motion(model, body);
    const Vec2 c = motion.centre, v = motion.velocity;
    double angle = 0.0;
    if (body.kind == BodyKind::rigid) {
      angle = model.rigid.theta[static_cast<std::size_t>(body.rigid_index)];
    } else {
      const BodyRotation q = body_rotation(model, static_cast<BodyId>(b));
      angle = std::atan2(q.b, q.a);
    }
    x.mutable_at(b) = c.x();
    y.mutable_at(b) = c.y();
    vx.mutable_at(b) = v.x();
    vy.mutable_at(b) = v.y();
    theta.mutable_at(b) = angle;
    rigid.mutable_at(b) = body.kind == BodyKind::rigid;
    names.append(body.name);
  }
  py::dict d;
  d["name"] = names;
  d["rigid"] = rigid;
  d["x"] = x;
  d["y"] = y;
  d["vx"] = vx;
  d["vy"] = vy;
  d["theta"] = theta;
  return d;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<PySimulation>(m, "Simulation", R"(A run of a scenario, stepped from Python.

Simulation(scenario, threads=0, output=None): output=None runs in memory (no file written);
output=ROOT writes the run folder ROOT/<name>/ exactly as `softgrain run SCENARIO -o ROOT`
does, bitwise. threads=0 keeps OpenMP's count. step() takes one accepted step, run() many;
the run is closed (final snapshot written, series.csv.partial renamed series.csv) when it
reaches its duration; close() before that leaves the folder as a killed run leaves it.)")
      .def(py::init([](const Scenario& scenario, int threads,
                       std::optional<std::filesystem::path> output, bool progress) {
             return std::make_unique<PySimulation>(scenario, threads, output, progress,
                                                   std::nullopt);
           }),
           py::arg("scenario"), py::arg("threads") = 0, py::arg("output") = py::none(),
           py::arg("progress") = false,
           "Builds the model (and with an output root, the run folder and run.log). "
           "progress=True prints the command line's progress line to stderr.")
      .def_static(
          "_resume",
          [](const std::filesystem::path& checkpoint, const Scenario& scenario, int threads,
             std::optional<std::filesystem::path> output, bool progress) {
            return std::make_unique<PySimulation>(scenario, threads, output, progress, checkpoint);
          },
          py::arg("checkpoint"), py::arg("scenario"), py::arg("threads") = 0,
          py::arg("output") = py::none(), py::arg("progress") = false)
      .def("step", &PySimulation::step, "One accepted step (the GIL released).")
      .def(
          "run",
          [](py::object self, std::optional<double> until, long every, py::object callback) {
            return self.cast<PySimulation&>().run(self, until, every, callback);
          },
          py::arg("until") = py::none(), py::arg("every") = 1, py::arg("callback") = py::none(),
          "Steps until time `until` (default and at most: the duration), calling "
          "callback(sim) every `every` steps; a callback returning False stops the run. "
          "Returns False if a callback stopped it, True otherwise.")
      .def(
          "__enter__", [](py::object self) { return self; }, "The Simulation itself.")
      .def(
          "__exit__", [](PySimulation& s, py::args) { s.close(); }, "close().")
      .def("close", &PySimulation::close,
           "Ends the run: the final outputs if it reached its duration, else the folder stays "
           "resumable (series.csv.partial); run.log rewritten. Idempotent.")
      .def("checkpoint", &PySimulation::checkpoint, py::arg("path"),
           "Writes the state to `path` (the checkpoint.bin format) and the scenario to "
           "`path`.toml. As the run's own checkpoints, it seals the step controller: no later "
           "rollback crosses it, and Simulation.resume(path) repeats the rest bitwise.")
      .def_property_readonly(
          "time", [](const PySimulation& s) { return s.sim().solver.state().time; },
          "Simulated time of the present state.")
      .def_property_readonly(
          "step_count", [](const PySimulation& s) { return s.sim().solver.state().step; },
          "Steps taken since t = 0.")
      .def_property_readonly(
          "dt", [](const PySimulation& s) { return s.sim().controller.next_step(); },
          "The step the next step() takes.")
      .def_property_readonly(
          "last_dt", [](const PySimulation& s) { return s.sim().solver.state().previous_dt; },
          "The last step taken (0 before the first).")
      .def_property_readonly(
          "duration", [](const PySimulation& s) { return s.scenario().def.duration; },
          "The scenario's duration.")
      .def_property_readonly("reached_end", &PySimulation::reached_end,
                             "True once the run has reached its duration.")
      .def_property_readonly(
          "closed", [](const PySimulation& s) { return s.session().closed(); },
          "True once the run is closed (no more steps).")
      .def_property_readonly(
          "directory",
          [](const PySimulation& s) -> std::optional<std::string> {
            if (s.session().directory().empty()) return std::nullopt;
            return s.session().directory().string();
          },
          "The run folder, None without outputs.")
      .def_property_readonly(
          "scenario", [](const PySimulation& s) { return s.scenario(); }, "The scenario run.")
      .def_property_readonly(
          "threads", [](const PySimulation& s) { return s.threads(); },
          "OpenMP threads asked for (0: OpenMP's count).")
      .def_property_readonly("nodes", &node_views,
                             "Read-only zero-copy views of the node arrays (one entry per field "
                             "node, all bodies): ref_x, ref_y (reference position), ux, uy, vx, "
                             "vy (the MLS displacement and velocity PARAMETERS), fx, fy (force "
                             "on each parameter), mass, body (node -> body index).")
      .def_property_readonly("rigid", &rigid_views,
                             "Read-only zero-copy views of the rigid bodies' state (one entry "
                             "per rigid body): body (its body index), x, y, theta, vx, vy, "
                             "omega, and fx, fy, torque received at the last force evaluation "
                             "(the first bodies' forces, as series.csv's B_fx, B_fy).")
      .def_property_readonly("energy", &energy_view,
                             "Read-only zero-copy view of the energy ledger: a 0-d structured "
                             "array, energy['kinetic'], energy['external_work'], ...")
      .def_property_readonly(
          "energy_residual",
          [](const PySimulation& s) { return s.sim().solver.state().energy.residual(); },
          "The ledger's balance residual.")
      .def(
          "node_positions", [](const PySimulation& s) { return node_vectors(s, false); },
          "Physical node positions (n, 2), through the MLS rows: a new array.")
      .def(
          "node_velocities", [](const PySimulation& s) { return node_vectors(s, true); },
          "Physical node velocities (n, 2), through the MLS rows: a new array.")
      .def("__repr__",
           [](const PySimulation& s) {
             std::ostringstream text;
             text << "softgrain.Simulation('" << s.scenario().def.name
                  << "', time=" << s.sim().solver.state().time
                  << ", step_count=" << s.sim().solver.state().step << ", "
                  << (s.session().directory().empty() ? std::string("in memory")
                                                      : s.session().directory().string())
                  << (s.session().closed() ? ", closed" : "") << ")";
             return text.str();
           })
      .def("bodies", &bodies,
           "Per body (new arrays): name, rigid, centre of mass x, y, its velocity vx, vy (as "
           "grains/NNNNNN.csv) and rotation theta.");
  std::vector<std::string> ledger_fields;
  for (const LedgerField& field : kLedgerFields)
    ledger_fields.push_back(field.name);
  m.attr("ENERGY_FIELDS") = ledger_fields;
}

}  // namespace sg::python
