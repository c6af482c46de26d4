// `softgrain sweep` end to end, with the real executable: a 2 x 2 campaign of tiny runs
// gives a table of 4 rows whose parameters match the runs; a sweep killed (with its runs)
// after its first run finished and started again does not redo that run and completes.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/exit_status.h"
#include "core/version.h"
#include "io/run_lock.h"
#include "scenes/scenario_files.h"
#include "scenes/shear_cell_scenario.h"
#include "scenes/tiny_scenario.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = scenes::process_temp_dir("sweep") / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The tiny scene (no shear cell: mu is null in the summaries, which is fine here), short.
void write_campaign(const fs::path& dir, int parallel) {
  std::ofstream(dir / "tiny.toml") << std::string(R"(name = "tiny"
[time]
duration = 0.05
[output]
series_period = 0.005
field_period = 0.025
)") + scenes::kTinyScenarioBody;
  std::ofstream(dir / "campaign.toml") << "name = \"c\"\nscenario = \"tiny.toml\"\n"
                                       << "output = \"out\"\nparallel = " << parallel << R"(
threads = 1
analyze_options = ["--no-agglomerates"]
[grid]
"materials.0.young" = [10.0, 20.0]
"contact_laws.0.friction" = [0.1, 0.4]
)";
}

// Starts `softgrain sweep <campaign>` in its own process group, output to `log`.
pid_t start_sweep(const fs::path& campaign, const fs::path& log) {
  const std::string exe = SOFTGRAIN_EXECUTABLE, file = campaign.string(), out = log.string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::execl(exe.c_str(), exe.c_str(), "sweep", file.c_str(), "--no-plot",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also from here: no race with the kill below
  return pid;
}

int wait_exit_code(pid_t pid);

// `softgrain sweep <campaign> --gather --no-plot`, output to `log`; its exit status.
int run_gather(const fs::path& campaign, const fs::path& log) {
  const std::string command = std::string("'") + SOFTGRAIN_EXECUTABLE + "' sweep '" +
                              campaign.string() + "' --gather --no-plot > '" + log.string() +
                              "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int wait_exit_code(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::vector<std::string>> read_csv(const fs::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read(p));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells(1);  // no quoted cells in this campaign's table
    for (char c : line)
      if (c == ',')
        cells.emplace_back();
      else
        cells.back() += c;
    rows.push_back(cells);
  }
  return rows;
}

// The runs of the 2 x 2 grid, in order: (young, friction) as written in the table.
const std::vector<std::pair<std::string, std::string>> kExpected = {
    {"10.0", "0.1"}, {"10.0", "0.4"}, {"20.0", "0.1"}, {"20.0", "0.4"}};

void expect_complete_table(const fs::path& campaign_folder) {
  const auto rows = read_csv(campaign_folder / "campaign.csv");
  ASSERT_EQ(rows.size(), 5u) << "a header and 4 runs";
  ASSERT_GE(rows[0].size(), 5u);
  EXPECT_EQ(rows[0][0], "id");
  EXPECT_EQ(rows[0][1], "materials.0.young");
  EXPECT_EQ(rows[0][2], "contact_laws.0.friction");
  EXPECT_EQ(rows[0][3], "status");
  EXPECT_EQ(rows[0][4], "softgrain");
  EXPECT_EQ(rows[0][5], "unmeasured");
  EXPECT_EQ(rows[0][6], "warnings");
  for (std::size_t r = 0; r < 4; ++r) {
    const auto& row = rows[r + 1];
    ASSERT_EQ(row.size(), rows[0].size()) << r;
    EXPECT_EQ(row[1], kExpected[r].first) << r;
    EXPECT_EQ(row[2], kExpected[r].second) << r;
    EXPECT_EQ(row[3], "done") << r;
    // The build that analysed it; nothing unmeasured (not a shear cell: no mu asked for).
    EXPECT_EQ(row[4], std::string(softgrain_version()) + " " + std::string(softgrain_commit()));
    EXPECT_EQ(row[5], "") << r;
    // The row is the run's: its folder holds the scenario with these values.
    const std::string scenario = read(campaign_folder / "runs" / row[0] / "scenario.toml");
    EXPECT_NE(scenario.find("young = " + kExpected[r].first), std::string::npos) << row[0];
    EXPECT_NE(scenario.find("friction = " + kExpected[r].second), std::string::npos) << row[0];
    EXPECT_TRUE(fs::exists(campaign_folder / "runs" / row[0] / "series.csv")) << row[0];
  }
}

TEST(Sweep, TwoByTwoCampaignGivesOneRowPerRun) {
  const fs::path dir = fresh_dir("grid");
  write_campaign(dir, 2);
  const int code = wait_exit_code(start_sweep(dir / "campaign.toml", dir / "sweep.out"));
  ASSERT_EQ(code, 0) << read(dir / "sweep.out");
  expect_complete_table(dir / "out" / "c");
  EXPECT_NE(read(dir / "sweep.out").find("[4/4 done, 0 running]"), std::string::npos)
      << read(dir / "sweep.out");
}

TEST(Sweep, KilledSweepResumesWithoutRedoingFinishedRuns) {
  const fs::path dir = fresh_dir("resume");
  write_campaign(dir, 1);
  const fs::path folder = dir / "out" / "c";
  const fs::path first = folder / "runs" / "run-000_young=10_friction=0.1";
  const fs::path summary = first / "analysis" / "summary.json";

  const pid_t pid = start_sweep(dir / "campaign.toml", dir / "first.out");
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  const auto second_started = [&] {
    return read(dir / "first.out").find("run-001_young=10_friction=0.4 started") !=
           std::string::npos;
  };
  while (!(fs::exists(summary) && second_started()) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(10ms);
  ASSERT_TRUE(fs::exists(summary) && second_started()) << read(dir / "first.out");
  // The sweep and the run it started next, within ~10 ms of its start: long before that run
  // and its analysis (~1 s) can finish.
  ::kill(-pid, SIGKILL);
  wait_exit_code(pid);
  const auto summary_time = fs::last_write_time(summary);
  const std::string first_log = read(first / "sweep.log");

  const int code = wait_exit_code(start_sweep(dir / "campaign.toml", dir / "second.out"));
  const std::string second = read(dir / "second.out");
  ASSERT_EQ(code, 0) << second;
  EXPECT_EQ(fs::last_write_time(summary), summary_time) << "the finished run was redone";
  EXPECT_EQ(read(first / "sweep.log"), first_log);
  EXPECT_EQ(second.find("run-000_young=10_friction=0.1 started"), std::string::npos) << second;
  EXPECT_NE(second.find("run-001_young=10_friction=0.4 finished"), std::string::npos) << second;
  EXPECT_NE(second.find("run-003_young=20_friction=0.4 finished"), std::string::npos) << second;
  expect_complete_table(folder);
}

// The cells of a line of campaign.csv, RFC 4180 quotes undone.
std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

// A campaign of two tiny pressure-loaded shear cells (the cell of test_paper_campaign.cpp):
// under p = 1 the layer carries the load and mu is measured; under p = 0.01 the light top,
// held back by its servo damping (terminal speed p L / c = 0.12), never reaches the layer in
// 4 time units: the normal force is 0 over the window, mu cannot be measured, and the sweep
// must say so (issue #29: such runs were reported "finished (mu = -)" and counted as done).
TEST(Sweep, ARunWithoutMuIsReportedAndGatheredAsSuch) {
  const fs::path dir = fresh_dir("without_mu");
  scenes::CohesiveShearCell c;
  c.duration = 4.0;
  c.compaction_time = 0.4;
  c.grains = 16;
  c.extra_time = "integrator = \"imex\"";
  std::string cell = scenes::shear_cell_scenario(c);
  const std::string rigid = "name = \"first_body\"\nyoung = 1000.0\n";
  cell.replace(cell.find(rigid), rigid.size(), rigid + "density = 0.1\n");
  std::ofstream(dir / "cell.toml") << cell
                                   << "normal_load = \"pressure\"\npressure = 1.0\n"
                                      "servo_damping = 0.5\n";
  std::ofstream(dir / "campaign.toml") << R"(name = "c"
scenario = "cell.toml"
output = "out"
parallel = 2
threads = 1
analyze_options = ["--window", "2.5", "4", "--no-agglomerates", "--no-plots"]
[grid]
"shear_cell.pressure" = [1.0, 0.01]
)";
  const int code = wait_exit_code(start_sweep(dir / "campaign.toml", dir / "sweep.out"));
  const std::string out = read(dir / "sweep.out");
  EXPECT_EQ(code, kExitUnmeasured) << out;
  const std::string loaded = "run-000_pressure=1", unloaded = "run-001_pressure=0.01";
  EXPECT_NE(out.find(loaded + " finished in"), std::string::npos) << out;
  EXPECT_NE(out.find(unloaded + " finished WITHOUT mu"), std::string::npos) << out;
  EXPECT_NE(out.find("mean normal force 0 over the window is not positive"), std::string::npos)
      << out;
  EXPECT_NE(out.find("[2/2 done (1 without mu), 0 running]"), std::string::npos) << out;
  EXPECT_NE(out.find("1 of 2 runs done, 1 done without mu"), std::string::npos) << out;
  EXPECT_NE(out.find("  done without mu: " + unloaded + ": mu: "), std::string::npos) << out;

  // The table marks it, and a --gather (as after cluster jobs) gives the same marks.
  for (const char* pass : {"sweep", "gather"}) {
    SCOPED_TRACE(pass);
    if (std::string(pass) == "gather") {
      const auto gather = run_gather(dir / "campaign.toml", dir / "gather.out");
      EXPECT_EQ(gather, kExitUnmeasured) << read(dir / "gather.out");
      EXPECT_NE(read(dir / "gather.out").find("1 of 2 runs done, 1 done without mu"),
                std::string::npos)
          << read(dir / "gather.out");
    }
    std::istringstream table(read(dir / "out" / "c" / "campaign.csv"));
    std::string line;
    std::getline(table, line);
    const auto header = csv_cells(line);
    const auto column = [&](const std::string& key) {
      return static_cast<std::size_t>(std::find(header.begin(), header.end(), key) -
                                      header.begin());
    };
    ASSERT_LT(column("unmeasured"), header.size()) << line;
    ASSERT_LT(column("mu"), header.size()) << line;
    std::map<std::string, std::vector<std::string>> rows;
    while (std::getline(table, line)) {
      const auto cells = csv_cells(line);
      rows[cells[0]] = cells;
    }
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[loaded][column("status")], "done");
    EXPECT_EQ(rows[loaded][column("unmeasured")], "");
    EXPECT_GT(std::stod(rows[loaded][column("mu")]), 0.0);
    EXPECT_EQ(rows[unloaded][column("status")], "done");
    EXPECT_EQ(rows[unloaded][column("mu")], "");
    EXPECT_EQ(rows[unloaded][column("unmeasured")].rfind("mu: ", 0), 0u)
        << rows[unloaded][column("unmeasured")];
    EXPECT_NE(rows[unloaded][column("unmeasured")].find("mean normal force 0"), std::string::npos);
  }
}

// Issue #26: a resume that fails (here a damaged checkpoint) moves checkpoint.bin and
// series.csv* aside as *.damaged, so that the next sweep starts the run from scratch as the
// message says, and it completes.
TEST(Sweep, AFailedResumeMovesTheDamagedFilesAsideAndTheNextSweepStartsOver) {
  const fs::path dir = fresh_dir("damaged");
  write_campaign(dir, 1);
  const fs::path run = dir / "out" / "c" / "runs" / "run-000_young=10_friction=0.1";
  fs::create_directories(run);
  std::ofstream(run / "checkpoint.bin") << "not a checkpoint";
  std::ofstream(run / "series.csv.partial") << "time,step\n0,0\n";
  wait_exit_code(start_sweep(dir / "campaign.toml", dir / "first.out"));
  const std::string first = read(dir / "first.out");
  EXPECT_NE(first.find("run-000_young=10_friction=0.1 resumed from its checkpoint"),
            std::string::npos)
      << first;
  EXPECT_NE(first.find("(resuming failed: checkpoint.bin and series.csv* moved aside as "
                       "*.damaged; the next sweep starts it from scratch)"),
            std::string::npos)
      << first;
  EXPECT_EQ(read(run / "checkpoint.bin.damaged"), "not a checkpoint");
  EXPECT_TRUE(fs::exists(run / "series.csv.partial.damaged"));
  EXPECT_FALSE(fs::exists(run / "checkpoint.bin"));
  const int code = wait_exit_code(start_sweep(dir / "campaign.toml", dir / "second.out"));
  const std::string second = read(dir / "second.out");
  ASSERT_EQ(code, 0) << second;
  EXPECT_NE(second.find("run-000_young=10_friction=0.1 started"), std::string::npos) << second;
  EXPECT_FALSE(fs::exists(run / "checkpoint.bin.damaged"));  // the from-scratch clean-up
  expect_complete_table(dir / "out" / "c");
}

// Issue #26: a second sweep of a campaign that a sweep is running is refused, naming the
// process, before it touches the run folders (it would clean up and restart the runs the first
// one is writing).
TEST(Sweep, ASecondSweepOfTheSameCampaignIsRefusedNamingTheProcess) {
  const fs::path dir = fresh_dir("second-sweep");
  write_campaign(dir, 1);
  const fs::path folder = dir / "out" / "c";
  fs::create_directories(folder);
  RunFolderLock lock;  // this process plays the first sweep
  lock.acquire(folder, 3000ms, kSweepLockFile, "campaign folder");
  const int code = wait_exit_code(start_sweep(dir / "campaign.toml", dir / "second.out"));
  const std::string out = read(dir / "second.out");
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("softgrain: error: campaign folder '" + folder.string() +
                     "' is in use: process " + std::to_string(::getpid())),
            std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(folder / "runs")) << "the refused sweep wrote run folders";
}

// Issue #26: `softgrain sweep` killed alone (SIGKILL to the sweep, not its process group)
// while a run is mid-way and past a checkpoint, restarted at once: the orphaned run used to go
// on writing its folder beside the restarted sweep's resume of the same run (a corrupt
// series.csv, a run failed for good). Now the run dies with its sweep (PR_SET_PDEATHSIG) and a
// run folder is locked while a run writes it; the campaign completes with every run's files
// byte-identical to those of an uninterrupted campaign (but run.log, which notes the resume,
// sweep.log, and the run folder's path in analysis/summary.json).
void write_long_campaign(const fs::path& dir) {
  std::ofstream(dir / "tiny.toml") << std::string(R"(name = "tiny"
[time]
duration = 0.4
[output]
series_period = 0.005
field_period = 0.05
checkpoint_period = 0.02
)") + scenes::kTinyScenarioBody;
  std::ofstream(dir / "campaign.toml") << R"(name = "c"
scenario = "tiny.toml"
output = "out"
parallel = 1
threads = 1
analyze_options = ["--no-agglomerates"]
[grid]
"contact_laws.0.friction" = [0.1, 0.4]
)";
}

std::string bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Sweep, SweepKilledAloneMidRunAndRestartedAtOnceGivesIdenticalRuns) {
  const fs::path reference = fresh_dir("reference");
  write_long_campaign(reference);
  ASSERT_EQ(wait_exit_code(start_sweep(reference / "campaign.toml", reference / "sweep.out")), 0)
      << read(reference / "sweep.out");

  const fs::path dir = fresh_dir("killed-alone");
  write_long_campaign(dir);
  const fs::path run = dir / "out" / "c" / "runs" / "run-000_friction=0.1";
  const pid_t pid = start_sweep(dir / "campaign.toml", dir / "first.out");
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (!fs::exists(run / "checkpoint.bin") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(2ms);
  ASSERT_TRUE(fs::exists(run / "checkpoint.bin")) << read(dir / "first.out");
  ::kill(pid, SIGKILL);  // the sweep alone: its run is not signalled by us
  wait_exit_code(pid);
  const int code = wait_exit_code(start_sweep(dir / "campaign.toml", dir / "second.out"));
  const std::string second = read(dir / "second.out");
  ASSERT_EQ(code, 0) << second << read(run / "sweep.log");
  EXPECT_EQ(second.find("FAILED"), std::string::npos) << second;
  // The kill came mid-run, past a checkpoint: the restarted sweep resumed the run.
  EXPECT_NE(second.find("run-000_friction=0.1 resumed from its checkpoint"), std::string::npos)
      << second;

  int compared = 0;
  const fs::path reference_runs = reference / "out" / "c" / "runs";
  for (const auto& entry : fs::recursive_directory_iterator(reference_runs)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), reference_runs);
    const std::string name = relative.filename().string();
    if (name == "run.log" || name == "sweep.log") continue;
    const fs::path other = dir / "out" / "c" / "runs" / relative;
    EXPECT_TRUE(fs::exists(other)) << relative << " is missing";
    // analysis/summary.json names its run folder: the same once the roots are swapped.
    std::string expected = bytes(entry.path());
    for (auto at = expected.find(reference.string()); at != std::string::npos;
         at = expected.find(reference.string(), at + dir.string().size()))
      expected.replace(at, reference.string().size(), dir.string());
    EXPECT_TRUE(expected == bytes(other)) << relative << " differs";
    ++compared;
  }
  EXPECT_GT(compared, 20);
  const fs::path runs = dir / "out" / "c" / "runs";
  for (const auto& entry : fs::recursive_directory_iterator(runs)) {
    if (!entry.is_regular_file()) continue;
    EXPECT_TRUE(fs::exists(reference_runs / fs::relative(entry.path(), runs)))
        << entry.path() << " is extra";
  }
}

}  // namespace
}  // namespace sg
