// softgrain names the build that produced a result: `softgrain --version`, run.log and
// summary.json carry the version and the git commit compiled in (core/version.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>

#include "app/command_output.h"
#include "core/version.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;
using test::run_command;
using test::softgrain;

// The commit of the source tree now, as the build would name it ("" without git: then the
// build said "unknown").
std::string source_commit() {
  const auto head = run_command("git -C '" SOFTGRAIN_SOURCE_DIR "' rev-parse --short=12 HEAD");
  if (head.status != 0) return "";
  return head.text.substr(0, head.text.find('\n'));
}

TEST(Version, PrintsTheVersionAndTheCommitOfTheSources) {
  const auto out = run_command(softgrain() + " --version");
  ASSERT_EQ(out.status, 0) << out.text;
  EXPECT_EQ(out.text, softgrain_version_line() + "\n");
  std::smatch m;
  ASSERT_TRUE(
      std::regex_match(out.text, m, std::regex(R"(softgrain (\d+\.\d+\.\d+) \(commit (\S+)\)\n)")))
      << out.text;
  EXPECT_EQ(m[1].str(), "0.1.0");  // project(softgrain VERSION ...) of CMakeLists.txt
  const std::string commit = source_commit();
  if (commit.empty()) {
    EXPECT_EQ(m[2].str(), "unknown");
  } else {
    // The hash of HEAD, "-dirty" if tracked files were modified when it was built. (A commit
    // made after the build fails this until the next build, which regenerates version.cpp.)
    EXPECT_TRUE(m[2].str() == commit || m[2].str() == commit + "-dirty")
        << "softgrain was built from commit " << m[2] << ", the sources are at " << commit
        << " (rebuild before testing)";
  }
}

TEST(Version, RunLogAndSummaryNameTheBuild) {
  const fs::path dir = scenes::process_temp_dir("version");
  scenes::write_text_file(dir / "tiny.toml", scenes::tiny_scenario("0.02"));
  const auto run = run_command(softgrain() + " --threads 1 run '" + (dir / "tiny.toml").string() +
                               "' -o '" + (dir / "out").string() + "'");
  ASSERT_EQ(run.status, 0) << run.text;
  const fs::path run_dir = dir / "out" / "tiny";
  const std::string log = scenes::read_text_file(run_dir / "run.log");
  EXPECT_NE(log.find("\nsoftgrain = \"" + std::string(softgrain_version()) + "\"\n"),
            std::string::npos)
      << log.substr(0, 300);
  EXPECT_NE(log.find("\ncommit = \"" + std::string(softgrain_commit()) + "\"\n"), std::string::npos)
      << log.substr(0, 300);

  const auto analyze =
      run_command(softgrain() + " --threads 1 analyze '" + run_dir.string() + "' --no-plots");
  ASSERT_EQ(analyze.status, 0) << analyze.text;
  const auto summary =
      nlohmann::json::parse(scenes::read_text_file(run_dir / "analysis" / "summary.json"));
  EXPECT_EQ(summary.at("softgrain").at("version"), std::string(softgrain_version()));
  EXPECT_EQ(summary.at("softgrain").at("commit"), std::string(softgrain_commit()));
}

}  // namespace
}  // namespace sg
