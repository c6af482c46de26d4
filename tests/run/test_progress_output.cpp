// The progress of a run written to a file or a pipe (run/progress_output.h): plain lines at a
// modest rate, their number bounded whatever the step count; the ETA from the recent rate.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include "run/progress_output.h"
#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

TEST(ProgressSchedule, ALineAtEachFivePercentOrAfterThirtySeconds) {
  ProgressSchedule schedule;  // 5%, 30 s
  schedule.start(0.0, 0.0);
  EXPECT_FALSE(schedule.due(0.01, 1.0));
  EXPECT_FALSE(schedule.due(0.049, 2.0));
  EXPECT_TRUE(schedule.due(0.05, 3.0));  // the 5% mark
  EXPECT_FALSE(schedule.due(0.07, 4.0));
  EXPECT_TRUE(schedule.due(0.07, 34.0));   // 30 s after the last line
  EXPECT_FALSE(schedule.due(0.09, 35.0));  // the next mark is still 10%
  EXPECT_TRUE(schedule.due(0.31, 36.0));   // one line for the marks 10% ... 30% passed at once
  EXPECT_FALSE(schedule.due(0.34, 37.0));
  EXPECT_TRUE(schedule.due(0.35, 38.0));
}

TEST(ProgressSchedule, AResumedRunStartsAtItsShare) {
  ProgressSchedule schedule;
  schedule.start(0.42, 0.0);
  EXPECT_FALSE(schedule.due(0.44, 1.0));
  EXPECT_TRUE(schedule.due(0.45, 2.0));
}

TEST(RecentRate, TheEtaFollowsTheRecentRateNotTheAverage) {
  // 100 s at 0.01 time units per second (a slow compaction), then 30 s at 0.1: the average
  // since the start (4 / 130 = 0.031 per s) would give 6 / 0.031 = 195 s for the 6 units left;
  // the last minute's rate, 60 s ago to now, covers 30 s at 0.01 and 30 s at 0.1.
  RecentRate rate(60.0);
  for (int s = 0; s <= 100; ++s)
    rate.add(s, 0.01 * s, 10L * s);
  for (int s = 101; s <= 130; ++s)
    rate.add(s, 1.0 + 0.1 * (s - 100), 10L * s);
  const double expected_rate = (4.0 - 0.7) / 60.0;  // t(130) = 4, t(70) = 0.7
  EXPECT_NEAR(rate.time_per_second(), expected_rate, 1e-12);
  EXPECT_NEAR(rate.seconds_left(10.0), 6.0 / expected_rate, 1e-9);
  EXPECT_NEAR(rate.steps_per_second(), 10.0, 1e-12);
  // Steady at the fast rate for another minute: the slow start no longer counts.
  for (int s = 131; s <= 200; ++s)
    rate.add(s, 4.0 + 0.1 * (s - 130), 10L * s);
  EXPECT_NEAR(rate.time_per_second(), 0.1, 1e-12);
  EXPECT_NEAR(rate.seconds_left(12.0), (12.0 - 11.0) / 0.1, 1e-9);
}

TEST(RecentRate, NoRateGivesAnUnknownEta) {
  RecentRate rate;
  EXPECT_EQ(format_duration(rate.seconds_left(1.0)), "unknown");
  rate.add(0.0, 0.0, 0);
  rate.add(1.0, 0.0, 0);  // no progress in a second
  EXPECT_EQ(format_duration(rate.seconds_left(1.0)), "unknown");
}

struct ProgressRun {
  std::string text;  // what the run wrote to its progress stream
  long steps = 0;
  double wall_seconds = 0.0;
};

ProgressRun run_with_plain_progress(const std::string& name, double duration) {
  const fs::path dir = scenes::process_temp_dir("progress");
  std::ostringstream scenario;
  scenario << "name = \"" << name << "\"\n[time]\nduration = " << duration
           << "\n[output]\nseries_period = " << duration / 4 << "\nfield_period = " << duration
           << "\n"
           << scenes::kTinyScenarioBody;
  scenes::write_text_file(dir / (name + ".toml"), scenario.str());
  std::ostringstream progress;
  RunOptions options;
  options.output_root_override = dir / "out";
  options.progress = &progress;
  options.progress_on_terminal = false;
  const RunSummary summary = run_scenario(load_scenario(dir / (name + ".toml")), options);
  return {progress.str(), summary.steps, summary.wall_seconds};
}

// Progress lines ("  t = ... ETA ...") in `text`, each whole on its own line.
int progress_lines(const std::string& text) {
  std::istringstream in(text);
  int count = 0;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("  t = ", 0) == 0) {
      EXPECT_NE(line.find("ETA"), std::string::npos) << line;
      ++count;
    }
  return count;
}

TEST(ProgressOutput, PlainLinesAreBoundedWhateverTheStepCount) {
  const ProgressRun short_run = run_with_plain_progress("short", 0.15);
  const ProgressRun long_run = run_with_plain_progress("long", 1.5);
  ASSERT_GT(long_run.steps, 10 * short_run.steps / 2) << "the long run takes many more steps";
  ASSERT_GT(short_run.steps, 40) << "more steps than 5% marks, or the bound checks nothing";
  for (const ProgressRun* r : {&short_run, &long_run}) {
    // No carriage return: every update is a line of its own.
    EXPECT_EQ(r->text.find('\r'), std::string::npos) << r->text;
    // One line per 5% of the duration (20), plus one per 30 s of wall time.
    const int lines = progress_lines(r->text);
    EXPECT_LE(lines, 20 + static_cast<int>(r->wall_seconds / 30.0)) << r->text;
    EXPECT_GE(lines, 19) << r->text;  // each mark passed gives its line (the last: 100%)
  }
  EXPECT_NE(long_run.text.find("(100.0%)"), std::string::npos) << long_run.text;
}

}  // namespace
}  // namespace sg
