// `softgrain sweep --slurm` against a real Slurm (run inside tests/slurm/with_slurm.sh, which
// starts a one-node cluster and sets SLURM_CONF): a submission to an unknown partition fails
// with Slurm's reason; a 2 x 2 campaign of tiny runs is submitted as one job array (2 tasks at
// a time); once its first two runs have a checkpoint, one task is cancelled with scancel and
// the other re-queued (scontrol requeue, as after a node failure: it resumes its run in the
// same job); --status reports the first cancelled and --gather names it missing; the campaign is
// submitted again: only that run is, it resumes from its checkpoint, and the runs finished
// before are not touched (files' bytes and modification times); a third submission submits
// nothing. The gathered table and every run's series.csv are then bitwise those of a local
// `softgrain sweep` of the same campaign file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "campaign/slurm_commands.h"
#include "scenes/tiny_scenario.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The tiny scene, finer (271 nodes) and longer: a run takes several seconds on one thread and
// writes a checkpoint every 2 of its 40 time units, so that a task can be cancelled mid-run.
void write_campaign(const fs::path& dir) {
  const std::string body =
      replaced(scenes::kTinyScenarioBody, "node_spacing = 0.15", "node_spacing = 0.06");
  std::ofstream(dir / "tiny.toml") << "name = \"tiny\"\n[time]\nduration = 40.0\n[output]\n"
                                   << "series_period = 0.05\nfield_period = 10.0\n"
                                   << "checkpoint_period = 2.0\n"
                                   << body;
  std::ofstream(dir / "campaign.toml") << R"(name = "c"
scenario = "tiny.toml"
output = "out"
parallel = 2
threads = 1
analyze_options = ["--no-agglomerates"]
[grid]
"materials.0.young" = [10.0, 20.0]
"contact_laws.0.friction" = [0.1, 0.4]
[slurm]
max_running = 2
)";
}

const std::vector<std::string> kRuns = {
    "run-000_young=10_friction=0.1", "run-001_young=10_friction=0.4",
    "run-002_young=20_friction=0.1", "run-003_young=20_friction=0.4"};

struct Output {
  int code = -1;
  std::string text;  // stdout then stderr
};

Output softgrain(const fs::path& dir, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {SOFTGRAIN_EXECUTABLE};
  argv.insert(argv.end(), args.begin(), args.end());
  const CommandResult r = run_command(argv, dir);
  return {r.exit_code, r.out + r.err};
}

// Polls `done` every 0.5 s for at most `limit`; true if it became true.
bool wait_for(const std::function<bool()>& done, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(500ms);
  }
  return done();
}

// The line of `text` that contains `what`, or "".
std::string line_with(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.find(what) != std::string::npos) return line;
  return "";
}

// Every file under the finished runs' folders: its bytes and modification time.
using Snapshot = std::map<fs::path, std::pair<std::string, fs::file_time_type>>;
Snapshot snapshot(const fs::path& runs, const std::vector<std::string>& ids) {
  Snapshot s;
  for (const std::string& id : ids)
    for (const auto& e : fs::recursive_directory_iterator(runs / id))
      if (e.is_regular_file()) s[e.path()] = {read(e.path()), e.last_write_time()};
  return s;
}

// The files added, removed or changed (bytes or modification time) between two snapshots.
std::vector<std::string> changed_files(const Snapshot& before, const Snapshot& after) {
  std::vector<std::string> changed;
  for (const auto& [path, file] : before) {
    const auto it = after.find(path);
    if (it == after.end())
      changed.push_back(path.string() + " (removed)");
    else if (it->second.first != file.first)
      changed.push_back(path.string() + " (bytes)");
    else if (it->second.second != file.second)
      changed.push_back(path.string() + " (modification time)");
  }
  for (const auto& [path, file] : after)
    if (!before.count(path)) changed.push_back(path.string() + " (added)");
  return changed;
}

std::vector<std::string> job_records(const fs::path& folder) {
  std::vector<std::string> records;  // "<job> <array>"
  std::istringstream in(read(folder / "slurm-jobs.txt"));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    std::string job, array;
    f >> job >> array;
    records.push_back(job + " " + array);
  }
  return records;
}

std::string submitted_job(const std::string& sweep_output) {
  const std::string marker = "submitted job array ";
  const auto at = sweep_output.find(marker);
  if (at == std::string::npos) return "";
  std::istringstream in(sweep_output.substr(at + marker.size()));
  std::string id;
  in >> id;
  return id;
}

// Prints the seconds since the test began before each phase: where a slow run spent its time.
class PhaseClock {
 public:
  void operator()(const std::string& phase) const {
    std::cout << "[" << std::fixed << std::setprecision(1)
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()
              << " s] " << phase << std::endl;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

class SlurmCampaign : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NE(std::getenv("SLURM_CONF"), nullptr)
        << "this test needs a Slurm cluster: run it through tests/slurm/with_slurm.sh";
    dir_ = fs::temp_directory_path() / ("softgrain_test_slurm_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (HasFailure())
      for (const std::string& id : kRuns)
        std::cerr << "----- " << id << "/sweep.log -----\n"
                  << read(dir_ / "out/c/runs" / id / "sweep.log") << "\n";
    fs::remove_all(dir_);
  }
  fs::path dir_;
};

TEST_F(SlurmCampaign, CancelledTaskResumesOnResubmissionAndResultsMatchALocalSweep) {
  write_campaign(dir_);
  const fs::path folder = dir_ / "out" / "c", runs = folder / "runs";
  const auto finished = [&](const std::string& id) {
    return fs::exists(runs / id / "analysis" / "summary.json");
  };

  const PhaseClock phase;
  phase("refused submission");
  // A submission Slurm refuses is an error with Slurm's reason, and records nothing.
  const Output refused = softgrain(
      dir_, {"sweep", "campaign.toml", "--slurm", "--partition", "nosuch", "--time", "5"});
  EXPECT_EQ(refused.code, 1) << refused.text;
  EXPECT_NE(refused.text.find("sbatch failed"), std::string::npos) << refused.text;
  EXPECT_NE(refused.text.find("partition"), std::string::npos) << refused.text;
  EXPECT_FALSE(fs::exists(folder / "slurm-jobs.txt"));

  phase("submission");
  // Submission: one array of the 4 runs, 2 at a time.
  const Output first = softgrain(dir_, {"sweep", "campaign.toml", "--slurm"});
  ASSERT_EQ(first.code, 0) << first.text;
  const std::string job = submitted_job(first.text);
  ASSERT_FALSE(job.empty()) << first.text;
  ASSERT_EQ(job_records(folder), std::vector<std::string>{job + " 0-3%2"});

  phase("waiting for two runs with a checkpoint");
  // The two tasks that run first start together: once both runs have a checkpoint, cancel one
  // (scancel) and re-queue the other as Slurm does after a node failure or a preemption
  // (scontrol requeue, then no wait for the re-queued task's begin time).
  std::vector<std::size_t> mid_run;
  ASSERT_TRUE(wait_for(
      [&] {
        mid_run.clear();
        for (std::size_t i = 0; i < kRuns.size(); ++i)
          if (fs::exists(runs / kRuns[i] / "checkpoint.bin") &&
              !fs::exists(runs / kRuns[i] / "series.csv"))
            mid_run.push_back(i);
        return mid_run.size() == 2;
      },
      180s))
      << softgrain(dir_, {"sweep", "campaign.toml", "--status"}).text;
  const std::size_t victim = mid_run[0], requeued = mid_run[1];
  const std::string task = job + "_" + std::to_string(victim);
  const CommandResult cancel = run_command({"scancel", task});
  ASSERT_EQ(cancel.exit_code, 0) << cancel.err;
  const std::string requeued_task = job + "_" + std::to_string(requeued);
  const CommandResult requeue = run_command({"scontrol", "requeue", requeued_task});
  ASSERT_EQ(requeue.exit_code, 0) << requeue.err;
  // Once its processes are gone the task is pending again, held until its begin time (now + 2
  // min in Slurm 22.05): moved to now (done earlier, the requeue would set it again).
  ASSERT_TRUE(wait_for(
      [&] {
        const auto tasks = query_array_tasks(job);
        return tasks && tasks->count(requeued) && tasks->at(requeued).state == "PENDING" &&
               tasks->at(requeued).reason == "BeginTime";
      },
      60s));
  const CommandResult now =
      run_command({"scontrol", "update", "JobId=" + requeued_task, "StartTime=now"});
  ASSERT_EQ(now.exit_code, 0) << now.err;

  phase("cancelled and re-queued; waiting for --status");
  // --status reports it cancelled; --gather names it missing.
  Output status;
  ASSERT_TRUE(wait_for(
      [&] {
        status = softgrain(dir_, {"sweep", "campaign.toml", "--status"});
        return line_with(status.text, kRuns[victim]).find("cancelled") != std::string::npos;
      },
      60s))
      << status.text;
  EXPECT_EQ(status.code, 0) << status.text;
  EXPECT_NE(line_with(status.text, kRuns[victim]).find("[" + task + "]"), std::string::npos)
      << status.text;
  EXPECT_NE(line_with(status.text, "4 runs:").find("1 cancelled"), std::string::npos)
      << status.text;
  EXPECT_FALSE(finished(kRuns[victim]));
  const Output partial = softgrain(dir_, {"sweep", "campaign.toml", "--gather", "--no-plot"});
  EXPECT_EQ(partial.code, 0) << partial.text;
  EXPECT_NE(partial.text.find("missing: " + kRuns[victim]), std::string::npos) << partial.text;

  phase("waiting for a finished run, then resubmission");
  // Resubmission once another run has finished (its task completed: `analyze` draws its
  // pictures after writing summary.json): only the cancelled run is submitted (the others are
  // done, or still pending or running in the first array).
  std::vector<std::string> done_before;
  ASSERT_TRUE(wait_for(
      [&] {
        const auto tasks = query_array_tasks(job);
        for (std::size_t i = 0; i < kRuns.size(); ++i)
          if (i != victim && finished(kRuns[i]) && tasks && tasks->count(i) &&
              tasks->at(i).state == "COMPLETED")
            done_before.push_back(kRuns[i]);
        return !done_before.empty();
      },
      180s));
  const Snapshot before = snapshot(runs, done_before);
  const Output second = softgrain(dir_, {"sweep", "campaign.toml", "--slurm"});
  ASSERT_EQ(second.code, 0) << second.text;
  const std::string job2 = submitted_job(second.text);
  ASSERT_FALSE(job2.empty()) << second.text;
  EXPECT_EQ(job_records(folder),
            (std::vector<std::string>{job + " 0-3%2", job2 + " " + std::to_string(victim) + "%2"}))
      << second.text;

  phase("waiting for every run");
  // Every run finishes; the cancelled one resumed from its checkpoint.
  ASSERT_TRUE(wait_for(
      [&] {
        status = softgrain(dir_, {"sweep", "campaign.toml", "--status"});
        return status.text.find("4 runs: 4 done;") != std::string::npos;
      },
      300s))
      << status.text;
  const std::string log = read(runs / kRuns[victim] / "sweep.log");
  EXPECT_NE(log.find("Slurm task " + job2 + "_" + std::to_string(victim)), std::string::npos)
      << log;
  EXPECT_NE(log.find("from its checkpoint"), std::string::npos) << log;
  EXPECT_NE(log.find("(resumed at step "), std::string::npos) << log;
  // The re-queued task ran again (restart 1) and resumed its run in the same job.
  const std::string requeued_log = read(runs / kRuns[requeued] / "sweep.log");
  EXPECT_NE(requeued_log.find("Slurm task " + requeued_task + " on "), std::string::npos)
      << requeued_log;
  EXPECT_NE(requeued_log.find("(restart 1): resumes"), std::string::npos) << requeued_log;
  EXPECT_EQ(changed_files(before, snapshot(runs, done_before)), std::vector<std::string>{})
      << "a finished run was touched";

  phase("third submission");
  // Submitting a finished campaign submits nothing and touches nothing.
  const Output third = softgrain(dir_, {"sweep", "campaign.toml", "--slurm"});
  EXPECT_EQ(third.code, 0) << third.text;
  EXPECT_NE(third.text.find("nothing to submit"), std::string::npos) << third.text;
  EXPECT_EQ(job_records(folder).size(), 2u);
  EXPECT_EQ(changed_files(before, snapshot(runs, done_before)), std::vector<std::string>{})
      << "a finished run was touched";

  phase("gather and local sweep");
  // Gathered, and bitwise the local sweep's results.
  const Output gathered = softgrain(dir_, {"sweep", "campaign.toml", "--gather", "--no-plot"});
  ASSERT_EQ(gathered.code, 0) << gathered.text;
  EXPECT_NE(gathered.text.find("4 of 4 runs done"), std::string::npos) << gathered.text;
  const Output local =
      softgrain(dir_, {"sweep", "campaign.toml", "-o", "local", "--parallel", "2", "--no-plot"});
  ASSERT_EQ(local.code, 0) << local.text;
  const fs::path local_folder = dir_ / "local" / "c";
  EXPECT_EQ(read(folder / "campaign.csv"), read(local_folder / "campaign.csv"));
  for (const std::string& id : kRuns) {
    const std::string series = read(runs / id / "series.csv");
    EXPECT_FALSE(series.empty()) << id;
    EXPECT_TRUE(series == read(local_folder / "runs" / id / "series.csv"))
        << id << ": series.csv differs between Slurm and the local sweep";
  }
  phase("done");
}

}  // namespace
}  // namespace sg
