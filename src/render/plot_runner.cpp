#include "render/plot_runner.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cerrno>

#include <cstdio>
#include <iostream>
#include <string>

namespace sg {
namespace {

namespace fs = std::filesystem;

// fork + execv (no shell: paths need no quoting); silent = output to /dev/null.
int run_program(const std::vector<std::string>& argv, bool silent) {
  std::vector<char*> args;
  for (const std::string& a : argv)
    args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // The child writes to our stdout: what we printed must come first.
  std::cout.flush();
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    if (silent) {
      const int null = open("/dev/null", O_WRONLY);
      if (null >= 0) {
        dup2(null, 1);
        dup2(null, 2);
      }
    }
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 127;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 127;
}

}  // namespace

fs::path current_executable() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

std::optional<fs::path> find_plot_script(const fs::path& executable, std::vector<fs::path>* tried) {
  std::vector<fs::path> candidates;
  if (!executable.empty())
    candidates.push_back((executable.parent_path() / ".." / "share" / "softgrain" / "plot_run.py")
                             .lexically_normal());
#ifdef SOFTGRAIN_SOURCE_SCRIPTS_DIR
  candidates.push_back(fs::path(SOFTGRAIN_SOURCE_SCRIPTS_DIR) / "plot_run.py");
#endif
  for (const fs::path& c : candidates) {
    if (tried) tried->push_back(c);
    std::error_code ec;
    if (fs::is_regular_file(c, ec)) return c;
  }
  return std::nullopt;
}

bool python_has_matplotlib(const fs::path& python) {
  std::error_code ec;
  if (!fs::is_regular_file(python, ec)) return false;
  return run_program({python.string(), "-c", "import matplotlib, numpy"}, true) == 0;
}

int run_plot_script(const fs::path& script, const fs::path& run_dir,
                    const std::vector<std::string>& arguments, const fs::path& python) {
  std::vector<std::string> argv = {python.string(), script.string(), run_dir.string()};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_program(argv, false);
}

}  // namespace sg
