// The campaign's process queue (campaign/run_queue.h) for Python: softgrain.run_scenarios
// (softgrain/campaign.py) builds the jobs, one child process per scenario, and runs them N at
// a time through the same queue `softgrain sweep` uses (children in the caller's process
// group, SIGINT and SIGTERM terminating them). The queue waits with the GIL released; its
// events call back into Python with the GIL held.
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "campaign/run_queue.h"

namespace sg::python {

namespace {

using Steps = std::vector<std::vector<std::string>>;
using JobTuple = std::tuple<Steps, std::filesystem::path, std::filesystem::path>;

py::dict outcome_dict(const JobOutcome& o) {
  py::dict d;
  d["job"] = o.job;
  d["success"] = o.success;
  d["step"] = o.step;
  d["exit_code"] = o.exit_code;
  d["signal"] = o.signal;
  d["seconds"] = o.seconds;
  return d;
}

// (completed, outcomes): completed is false if SIGINT or SIGTERM stopped the queue.
py::tuple run_queue(const std::vector<JobTuple>& job_tuples, int parallel,
                    const std::function<void(py::dict)>& on_finished) {
  std::vector<ProcessJob> jobs;
  for (const auto& [steps, folder, log] : job_tuples)
    jobs.push_back(ProcessJob{steps, folder, log});
  std::vector<JobOutcome> outcomes;
  QueueEvents events;
  events.finished = [&](const JobOutcome& outcome, std::size_t) {
    outcomes.push_back(outcome);
    if (on_finished) {
      py::gil_scoped_acquire acquire;
      on_finished(outcome_dict(outcome));
    }
  };
  bool completed = false;
  {
    py::gil_scoped_release release;
    completed = run_process_queue(jobs, parallel, events);
  }
  py::list list;
  for (const JobOutcome& o : outcomes)
    list.append(outcome_dict(o));
  return py::make_tuple(completed, list);
}

}  // namespace

void bind_campaign(py::module_& m) {
  m.def("_run_process_queue", &run_queue, py::arg("jobs"), py::arg("parallel"),
        py::arg("on_finished") = nullptr,
        "Runs jobs (steps: list of argv, working folder, log file) as child processes, "
        "`parallel` at a time (campaign/run_queue.h); returns (completed, outcomes).");
}

}  // namespace sg::python
