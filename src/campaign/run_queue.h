#pragma once
// Runs jobs as child processes, N at a time. A job is a short sequence of commands (for a
// campaign run: `softgrain run`, then `softgrain analyze`) executed one after the other
// while they succeed, in a working folder, with stdout and stderr going to one log file.
//
// Why processes and not threads: each run is a whole simulation with its own OpenMP team;
// a crash or an exit in one run must not take the others down; and a child is exactly
// what a cluster job runs (`softgrain run`), so local and cluster runs behave the same.
// The children stay in the caller's process group: killing the group (Ctrl-C in a
// terminal, a batch system's kill) stops them all. SIGINT or SIGTERM sent to the caller
// alone make it terminate its children and return without starting more; if the caller dies
// otherwise (SIGKILL), the kernel kills its children (PR_SET_PDEATHSIG), so that no orphaned
// run goes on writing a folder that a restarted sweep starts again (issue #26).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sg {

struct ProcessJob {
  std::vector<std::vector<std::string>> steps;  // argv of each command; argv[0] is a path
  std::filesystem::path working_directory;
  std::filesystem::path log;  // created (truncated) by the first step, appended to by the rest
};

struct JobOutcome {
  std::size_t job = 0;   // index in the job list
  bool success = false;  // every step exited with status 0
  std::size_t step = 0;  // the step that failed
  int exit_code = 0;     // its exit status, or -1 if a signal ended it
  int signal = 0;        // the signal, if any
  double seconds = 0.0;  // wall time of the whole job
};

struct QueueEvents {
  // After a job's first step started; `running` counts it.
  std::function<void(std::size_t job, std::size_t running)> started;
  // After a job ended (success or failure); `running` no longer counts it.
  std::function<void(const JobOutcome& outcome, std::size_t running)> finished;
};

// Runs `jobs` in order, at most `parallel` at a time. Returns false if interrupted by
// SIGINT or SIGTERM (running jobs were terminated and are not reported as finished).
bool run_process_queue(const std::vector<ProcessJob>& jobs, int parallel,
                       const QueueEvents& events);

}  // namespace sg
