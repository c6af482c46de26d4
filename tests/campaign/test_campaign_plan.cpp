// The planner of `softgrain sweep --dry-run`: the wall time it projects for a run (model build
// + duration x the wall time per time unit it measured over about a second of steps) is within
// a factor 2 of the wall time the run then reports in its run.log. Both numbers come from the
// program; the test does not time anything itself.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "campaign/slurm_commands.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Seconds of "5.77 s", "12.5 min" or "1.2 h" at the end of `line`; -1 if none.
double trailing_wall_time(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;)
    words.push_back(w);
  if (words.size() < 2) return -1;
  const double value = std::stod(words[words.size() - 2]);
  const std::string& unit = words.back();
  return unit == "s" ? value : unit == "min" ? 60 * value : unit == "h" ? 3600 * value : -1;
}

TEST(CampaignPlan, ProjectedWallTimeIsWithinAFactorTwoOfTheRunsOwn) {
  const fs::path dir = scenes::process_temp_dir("plan");
  struct Remove {
    fs::path dir;
    ~Remove() { fs::remove_all(dir); }
  } remove{dir};
  // The tiny scene, finer and longer: a few seconds on one thread.
  std::ofstream(dir / "tiny.toml")
      << "name = \"tiny\"\n[time]\nduration = 40.0\n[output]\n"
      << "series_period = 0.05\nfield_period = 10.0\n"
      << scenes::replace_once(scenes::kTinyScenarioBody, "node_spacing = 0.15",
                              "node_spacing = 0.06");
  std::ofstream(dir / "plan.toml") << R"(name = "plan"
scenario = "tiny.toml"
output = "out"
threads = 1
analyze_options = ["--no-agglomerates"]
[grid]
"materials.0.young" = [10.0]
)";
  const std::string id = "run-000_young=10";
  const CommandResult plan =
      run_command({SOFTGRAIN_EXECUTABLE, "sweep", "plan.toml", "--dry-run"}, dir);
  ASSERT_EQ(plan.exit_code, 0) << plan.out << plan.err;
  std::string row;
  std::istringstream lines(plan.out);
  for (std::string line; std::getline(lines, line);)
    if (line.find("  " + id + " ") == 0) row = line;
  ASSERT_FALSE(row.empty()) << plan.out;
  const double projected = trailing_wall_time(row);
  EXPECT_NE(plan.out.find("core-hours projected"), std::string::npos) << plan.out;

  const CommandResult run =
      run_command({SOFTGRAIN_EXECUTABLE, "sweep", "plan.toml", "--no-plot"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  // "# profile (wall seconds of this session, 1 threads): 4.725 s in all, ..."
  const std::string log = read(dir / "out/plan/runs" / id / "run.log");
  const std::string marker = "threads): ";
  const auto at = log.find(marker, log.find("# profile (wall seconds"));
  ASSERT_NE(at, std::string::npos) << log;
  const double measured = std::stod(log.substr(at + marker.size()));
  EXPECT_GT(projected, measured / 2) << row << "\nrun.log: " << measured << " s";
  EXPECT_LT(projected, measured * 2) << row << "\nrun.log: " << measured << " s";
  std::cout << "projected " << projected << " s, the run took " << measured << " s\n";
}

}  // namespace
}  // namespace sg
