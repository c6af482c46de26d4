#pragma once
// The Slurm client commands sweep uses, each run without a shell (argv as given, found on
// PATH; SLURM_CONF and the rest of the environment passed on) and its output parsed:
//   sbatch --parsable            submits a job array, prints "<job id>[;<cluster>]"
//   squeue -h -t all -r -j JOB   the tasks the controller still holds (pending, running, and
//                                ended ones for MinJobAge, 300 s by default)
//   sacct -n -P -X -j JOB        the tasks of a job the controller forgot, where the cluster
//                                keeps accounting (a test cluster need not)
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sg {

struct CommandResult {
  bool started = false;  // false: the program could not be executed (not installed?)
  int exit_code = -1;    // -1 when a signal ended it
  std::string out, err;
};

// Runs argv[0] (searched on PATH) with its arguments in `working_directory` (empty: here),
// stdin from /dev/null, and returns its exit status and what it printed.
CommandResult run_command(const std::vector<std::string>& argv,
                          const std::filesystem::path& working_directory = {});

// Submits `script` from `working_directory` with extra sbatch arguments (before the script);
// returns the job id. Throws with sbatch's message if it fails or prints no job id.
std::string sbatch_submit(const std::filesystem::path& working_directory,
                          const std::vector<std::string>& arguments,
                          const std::filesystem::path& script);

// One array task as the scheduler reports it.
struct SlurmTask {
  std::string state;   // Slurm's long name: PENDING, RUNNING, COMPLETED, CANCELLED, TIMEOUT, ...
  double elapsed = 0;  // seconds it has run (0 while pending)
  int cpus = 0;        // CPUs allocated (or requested while pending)
  std::string reason;  // why pending ("Priority", "JobArrayTaskLimit"), "None" otherwise
};

// The tasks of job array `job_id` by task index. nullopt if the scheduler knows no such job
// (squeue and sacct both say nothing, e.g. a purged job on a cluster without accounting).
// Throws if squeue cannot be run at all (no Slurm on this machine).
std::optional<std::map<std::size_t, SlurmTask>> query_array_tasks(const std::string& job_id);

// Parsers of the commands' outputs (exposed for tests).
std::optional<std::string> parse_sbatch_job_id(const std::string& sbatch_output);
// Lines "%F|%K|%T|%M|%C|%r" of squeue for job `job_id`; other jobs' lines are ignored.
std::map<std::size_t, SlurmTask> parse_squeue_tasks(const std::string& output,
                                                    const std::string& job_id);
// Lines "JobID|State|ElapsedRaw|AllocCPUS" of sacct -P; "State" may read "CANCELLED by 0".
std::map<std::size_t, SlurmTask> parse_sacct_tasks(const std::string& output,
                                                   const std::string& job_id);
// Seconds of squeue's %M ("M:SS", "H:MM:SS", "D-HH:MM:SS"); 0 if unreadable.
double parse_squeue_elapsed(const std::string& text);

}  // namespace sg
