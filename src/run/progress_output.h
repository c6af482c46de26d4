#pragma once
// The progress of a run: simulated time, share done, steps per second and the estimated time
// left, both from the recent rate (the last minute or so: the step changes as the layer
// compacts and shears, so the rate since the start misleads), and with RunOptions::profile the
// share of each phase of the step so far. Two styles:
//  - on a terminal, one line rewritten in place (carriage return) at most once a second;
//  - otherwise (a file, a pipe, a campaign's sweep.log) plain lines, one each time the run
//    passes another 5% of its duration or 30 s after the last one: at most 20 lines plus one
//    per 30 s whatever the step count, where the rewritten line would pile hundreds of
//    carriage-return updates into one line of the file.
// Writes nothing when there is no progress stream.
#include <chrono>
#include <deque>
#include <ostream>
#include <string>

#include "run/run_observer.h"

namespace sg {

// The rate of a run over its recent past: samples of (wall time, simulated time, step), the
// oldest dropped once the rest span `horizon` wall seconds.
class RecentRate {
 public:
  explicit RecentRate(double horizon_seconds = 60.0) : horizon_(horizon_seconds) {}
  void add(double wall_seconds, double time, long step);
  // Over the kept samples; 0 with fewer than two samples or no wall time between them.
  double time_per_second() const;
  double steps_per_second() const;
  // (duration - the last time) at time_per_second(): +inf when the rate is not positive
  // (format_duration says "unknown").
  double seconds_left(double duration) const;

 private:
  struct Sample {
    double wall, time;
    long step;
  };
  double horizon_;
  std::deque<Sample> samples_;
};

// When a plain (non-terminal) progress line is due: the run has passed the next multiple of
// `share_step` of its duration, or `period` wall seconds went by since the last line.
class ProgressSchedule {
 public:
  explicit ProgressSchedule(double share_step = 0.05, double period_seconds = 30.0)
      : share_step_(share_step), period_(period_seconds) {}
  // Starts counting from `share` done at wall time `wall` (a resumed run starts part-way).
  void start(double share, double wall);
  // True if a line is due now (and counts it as written).
  bool due(double share, double wall);

 private:
  double share_step_, period_;
  double next_share_ = 0.0, last_wall_ = 0.0;
};

class ProgressOutput : public RunObserver {
 public:
  // `terminal`: the stream is a terminal (lines rewritten in place), else plain lines.
  ProgressOutput(RunContext& context, std::ostream* out, bool show_profile, bool terminal);

  void begin(bool resumed) override;
  void after_step(const StepTaken& step) override;

 private:
  using clock = std::chrono::steady_clock;
  double wall_seconds() const;
  std::string describe() const;  // the line, without its line break or carriage return

  RunContext& context_;
  std::ostream* out_;
  bool show_profile_, terminal_;
  clock::time_point start_;
  double last_sample_ = 0.0;  // wall seconds of the last rate sample (terminal: of the last line)
  RecentRate rate_;
  ProgressSchedule schedule_;
};

// "12s", "3m4s", "2h5m", "19d2h"; "unknown" for a negative or non-finite duration, "over 10000
// days" beyond.
std::string format_duration(double seconds);

// One line: each phase's share of the profile's total, largest first ("internal forces 71%,
// contacts 18%, ...").
std::string describe_shares(const StepProfile& profile);

}  // namespace sg
