// The rollback rule of the run loop (run/run_observer.h), checked once against the observer
// interface: a recording observer sees the loop of a run whose step control rejects a step
// and rolls back, and the run's own outputs (series.csv, fields.pvd, grains/, checkpoint) must
// describe exactly the instants the loop committed, each once, in increasing time.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run/run.h"
#include "run/run_observer.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

struct RecordingObserver : RunObserver {
  std::vector<RunInstant> prepared, committed;
  int rolled_back = 0;  // accepted steps that did not start where the loop stood
  bool finished = false;
  void prepare(const RunInstant& now) override { prepared.push_back(now); }
  void commit(const StepTaken& step) override { committed.push_back(step.start); }
  void after_step(const StepTaken& step) override { rolled_back += step.from_start ? 0 : 1; }
  void finish() override { finished = true; }
};

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::string formatted(double t) {  // as series.csv writes its time column
  std::ostringstream s;
  s.precision(12);
  s << t;
  return s.str();
}

TEST(RunObservers, ARollbackLeavesEveryOutputAtTheCommittedInstants) {
  // The seam scene of the checkpoint tests: at step tolerance 0.0006 the collision at
  // t = 0.1058 is rejected and retried at half the step (test_checkpoint_restart.cpp). A row
  // every 0.002 (about dt).
  const std::string text = std::string(R"(
name = "observed"
[time]
duration = 0.2
step_tolerance = 0.0006
[output]
series_period = 0.002
field_period = 0.05
checkpoint_period = 0.05
)") + scenes::kTinyScenarioBody +
                           scenes::kSeamGrains;
  const fs::path dir = scenes::process_temp_dir("observers");
  const ScenarioDef scenario = load_scenario(scenes::write_text_file(dir / "observed.toml", text));
  RecordingObserver recorder;
  RunOptions options;
  options.output_root_override = dir / "out";
  options.observers = {&recorder};
  const RunSummary summary = run_scenario(scenario, options);
  ASSERT_TRUE(summary.completed);
  EXPECT_TRUE(recorder.finished);
  EXPECT_GE(recorder.rolled_back, 1) << "the scene must roll back";
  // Every rolled-back instant was prepared again: more preparations than commits.
  EXPECT_EQ(recorder.prepared.size(), recorder.committed.size() + recorder.rolled_back);
  for (std::size_t k = 1; k < recorder.committed.size(); ++k) {
    EXPECT_GT(recorder.committed[k].time, recorder.committed[k - 1].time) << k;
    EXPECT_EQ(recorder.committed[k].step, recorder.committed[k - 1].step + 1) << k;
  }
  // series.csv: a row at the first committed instant at or after each multiple of the period
  // (the rejected trajectory's instants never appear), with its time and step.
  std::vector<RunInstant> due;
  double next_row = 0.0;
  for (const RunInstant& c : recorder.committed)
    if (c.time >= next_row - 1e-12 * scenario.duration) {
      due.push_back(c);
      next_row += scenario.series_period;
    }
  const std::vector<std::string> rows = lines_of(summary.directory / "series.csv");
  ASSERT_EQ(rows.size(), due.size() + 1);
  for (std::size_t k = 0; k < due.size(); ++k) {
    const std::string& row = rows[k + 1];
    const std::size_t comma = row.find(',');
    EXPECT_EQ(row.substr(0, comma), formatted(due[k].time)) << k;
    EXPECT_EQ(std::stol(row.substr(comma + 1)), due[k].step) << k;
  }
  // fields.pvd: the snapshots at committed instants (and the final state), increasing, each
  // with its fields and grains files.
  const std::vector<std::string> pvd = lines_of(summary.directory / "fields.pvd");
  std::vector<double> snapshot_times;
  for (const std::string& line : pvd) {
    const auto at = line.find("timestep=\"");
    if (at == std::string::npos) continue;
    snapshot_times.push_back(std::stod(line.substr(at + 10)));
  }
  ASSERT_EQ(snapshot_times.size(), 5u);  // t = 0, 0.05, 0.1, 0.15 (committed) and the end
  for (std::size_t k = 0; k + 1 < snapshot_times.size(); ++k) {
    bool committed = false;
    for (const RunInstant& c : recorder.committed)
      committed = committed || std::abs(c.time - snapshot_times[k]) < 1e-9;
    EXPECT_TRUE(committed) << snapshot_times[k];
    if (k > 0) {
      EXPECT_GT(snapshot_times[k], snapshot_times[k - 1]);
    }
    char name[32];
    std::snprintf(name, sizeof name, "%06zu", k);
    EXPECT_TRUE(fs::exists(summary.directory / "fields" / (std::string(name) + ".vtu")));
    EXPECT_TRUE(fs::exists(summary.directory / "grains" / (std::string(name) + ".csv")));
  }
  EXPECT_FALSE(fs::exists(summary.directory / "fields" / "000005.vtu"));
  // The checkpoint of this run resumes to the same folder (the loop state it saved is that of
  // the committed outputs): see test_checkpoint_restart.cpp RunWithRejectedStepsResumesExactly.
  EXPECT_EQ(summary.checkpoints_written, 3);
}

}  // namespace
}  // namespace sg
