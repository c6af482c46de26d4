#pragma once
// Scenario files for tests: a temp folder per test process, text written to files, and the
// error a scenario gives (ctest runs a binary's tests as parallel processes, so every
// process needs a folder of its own).
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scenario/scenario.h"

namespace sg::scenes {

// The folders process_temp_dir made, removed when the test process exits if every test passed
// (a failed test's files stay for a look; so do all of them with SOFTGRAIN_KEEP_TEST_FILES set).
// Without this, every test process left its folder in the temp directory for good.
class ProcessTempDirs {
 public:
  ProcessTempDirs() = default;
  ProcessTempDirs(const ProcessTempDirs&) = delete;
  ProcessTempDirs& operator=(const ProcessTempDirs&) = delete;
  ~ProcessTempDirs() {
    const auto* unit_test = ::testing::UnitTest::GetInstance();
    if (unit_test->Failed() || std::getenv("SOFTGRAIN_KEEP_TEST_FILES") != nullptr) return;
    for (const auto& dir : dirs_) {
      std::error_code ignored;  // a folder already gone, or busy, is left as it is
      std::filesystem::remove_all(dir, ignored);
    }
  }
  // True the first time `dir` is seen.
  bool add(const std::filesystem::path& dir) { return dirs_.insert(dir).second; }

 private:
  std::set<std::filesystem::path> dirs_;
};

// <temp>/softgrain_test_<tag>_<pid>, emptied the first time this process asks for it and
// removed at the process's exit (ProcessTempDirs).
inline std::filesystem::path process_temp_dir(const std::string& tag) {
  static ProcessTempDirs made;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("softgrain_test_" + tag + "_" + std::to_string(::getpid()));
  if (made.add(dir)) std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path write_text_file(const std::filesystem::path& path,
                                             const std::string& text) {
  std::ofstream(path, std::ios::trunc) << text;
  return path;
}

// The whole content of a text file ("" if it cannot be read).
inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// `text` with the first occurrence of `from` replaced (a test failure if there is none).
inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The message load_scenario gives for `text` written to <dir>/bad.toml; empty if it loads.
inline std::string scenario_error(const std::filesystem::path& dir, const std::string& text) {
  try {
    load_scenario(write_text_file(dir / "bad.toml", text));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace sg::scenes
