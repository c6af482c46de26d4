#pragma once
// The progress line of a run (at most once a second): simulated time, share done, steps per
// second, the estimated time left, and with RunOptions::profile the share of each phase of
// the step so far. Writes nothing when there is no progress stream.
#include <chrono>
#include <ostream>

#include "run/run_observer.h"

namespace sg {

class ProgressOutput : public RunObserver {
 public:
  ProgressOutput(RunContext& context, std::ostream* out, bool show_profile);

  void begin(bool resumed) override;
  void after_step(const StepTaken& step) override;

 private:
  using clock = std::chrono::steady_clock;
  RunContext& context_;
  std::ostream* out_;
  bool show_profile_;
  clock::time_point start_, last_line_;
  long first_step_ = 0;
  double first_time_ = 0.0;
};

// "12s", "3m4s", "2h5m", "19d2h"; "unknown" for a negative or non-finite duration, "over 10000
// days" beyond.
std::string format_duration(double seconds);

// One line: each phase's share of the profile's total, largest first ("internal forces 71%,
// contacts 18%, ...").
std::string describe_shares(const StepProfile& profile);

}  // namespace sg
