#pragma once
// Runs a shell command and returns its exit status and what it wrote (stdout and stderr).
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg::test {

struct CommandOutput {
  int status = -1;  // exit status; -1 if it did not exit normally
  std::string text;
};

inline CommandOutput run_command(const std::string& command) {
  CommandOutput out;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return out;
  std::array<char, 4096> buffer{};
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
    out.text.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  if (WIFEXITED(status)) out.status = WEXITSTATUS(status);
  return out;
}

// The softgrain executable under test, quoted for the shell.
inline std::string softgrain() {
  return std::string("'") + SOFTGRAIN_EXECUTABLE + "'";
}

}  // namespace sg::test
