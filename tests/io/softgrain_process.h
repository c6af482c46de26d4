#pragma once
// Runs the real softgrain executable as a child process, for the tests that judge it from the
// outside (test_hostile_cli.cpp: exit status and message; test_crash_resume.cpp: killed at
// chosen moments). Header-only: used by test files of one module.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE

namespace sg::testing {

struct SoftgrainLaunch {
  // Where the child's stdout and stderr go ("/dev/null" to drop one); the same path for both
  // interleaves them.
  std::string stdout_path = "/dev/null", stderr_path = "/dev/null";
  bool append = false;  // append to those files rather than truncate them
  // Environment variables set in the child (an empty value unsets the variable).
  std::vector<std::pair<std::string, std::string>> environment;
  // > 0: every file the child writes is capped at this size (RLIMIT_FSIZE, SIGXFSZ ignored:
  // the write passing it fails with EFBIG as on a full disk).
  long file_size_limit = 0;
  // > 0: the child is killed with SIGKILL once this has passed (a hang in a test of input
  // handling; a chosen moment in a crash test). 0: wait for it however long it takes.
  std::chrono::milliseconds kill_after{0};
};

struct SoftgrainEnd {
  int exit_code = -1;            // -1: ended by a signal
  int signal = 0;                // the signal that ended it, if any
  bool killed_at_limit = false;  // killed by us after `kill_after`
};

// Runs `softgrain args...` (SOFTGRAIN_EXECUTABLE) as `launch` says and waits for its end.
inline SoftgrainEnd run_softgrain_process(std::vector<std::string> args,
                                          const SoftgrainLaunch& launch) {
  std::cout << std::flush;  // or the child would repeat what is buffered
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    for (const auto& [name, value] : launch.environment)
      if (value.empty())
        unsetenv(name.c_str());
      else
        setenv(name.c_str(), value.c_str(), 1);
    if (launch.file_size_limit > 0) {
      signal(SIGXFSZ, SIG_IGN);
      const rlimit r{static_cast<rlim_t>(launch.file_size_limit),
                     static_cast<rlim_t>(launch.file_size_limit)};
      setrlimit(RLIMIT_FSIZE, &r);
    }
    const char* mode = launch.append ? "a" : "w";
    if (!freopen(launch.stdout_path.c_str(), mode, stdout)) _exit(126);
    if (launch.stderr_path == launch.stdout_path)
      dup2(STDOUT_FILENO, STDERR_FILENO);  // one file, one offset
    else if (!freopen(launch.stderr_path.c_str(), mode, stderr))
      _exit(126);
    args.insert(args.begin(), SOFTGRAIN_EXECUTABLE);
    std::vector<char*> argv;
    for (std::string& a : args)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  SoftgrainEnd end;
  int status = 0;
  if (launch.kill_after.count() > 0) {
    const auto deadline = std::chrono::steady_clock::now() + launch.kill_after;
    while (waitpid(pid, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() >= deadline) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        end.killed_at_limit = true;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  } else {
    waitpid(pid, &status, 0);
  }
  if (WIFEXITED(status)) end.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) end.signal = WTERMSIG(status);
  return end;
}

}  // namespace sg::testing
