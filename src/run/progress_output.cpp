#include "run/progress_output.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <vector>

namespace sg {

std::string format_duration(double seconds) {
  // An ETA can be infinite or absurdly long when the step collapses: those would overflow the
  // integer conversions below, so they are named instead.
  constexpr double kDay = 86400.0, kLongest = 10000.0 * kDay;
  if (!std::isfinite(seconds) || seconds < 0.0) return "unknown";
  if (seconds >= kLongest) return "over 10000 days";
  const auto whole = [](double v) { return static_cast<long long>(v); };
  std::ostringstream s;
  if (seconds < 60)
    s << std::fixed << std::setprecision(0) << seconds << "s";
  else if (seconds < 3600)
    s << whole(seconds / 60) << "m" << whole(std::fmod(seconds, 60)) << "s";
  else if (seconds < kDay)
    s << whole(seconds / 3600) << "h" << whole(std::fmod(seconds, 3600) / 60) << "m";
  else
    s << whole(seconds / kDay) << "d" << whole(std::fmod(seconds, kDay) / 3600) << "h";
  return s.str();
}

std::string describe_shares(const StepProfile& profile) {
  const double total = profile.total();
  if (total <= 0.0) return "no time measured";
  std::vector<std::size_t> order(kStepPhaseCount);
  for (std::size_t k = 0; k < kStepPhaseCount; ++k)
    order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return profile.seconds[a] > profile.seconds[b];
  });
  std::ostringstream s;
  s << std::fixed << std::setprecision(0);
  for (std::size_t k = 0; k < kStepPhaseCount; ++k) {
    const std::size_t p = order[k];
    s << (k ? ", " : "") << phase_name(static_cast<StepPhase>(p)) << ' '
      << 100.0 * profile.seconds[p] / total << '%';
  }
  return s.str();
}

void RecentRate::add(double wall_seconds, double time, long step) {
  samples_.push_back({wall_seconds, time, step});
  while (samples_.size() > 2 && samples_.back().wall - samples_[1].wall >= horizon_)
    samples_.pop_front();
}

double RecentRate::time_per_second() const {
  if (samples_.size() < 2) return 0.0;
  const double wall = samples_.back().wall - samples_.front().wall;
  return wall > 0.0 ? (samples_.back().time - samples_.front().time) / wall : 0.0;
}

double RecentRate::steps_per_second() const {
  if (samples_.size() < 2) return 0.0;
  const double wall = samples_.back().wall - samples_.front().wall;
  return wall > 0.0 ? static_cast<double>(samples_.back().step - samples_.front().step) / wall
                    : 0.0;
}

double RecentRate::seconds_left(double duration) const {
  const double rate = time_per_second();
  if (samples_.empty() || !(rate > 0.0)) return std::numeric_limits<double>::infinity();
  return std::max(0.0, duration - samples_.back().time) / rate;
}

void ProgressSchedule::start(double share, double wall) {
  // The first line at the first multiple of the step beyond where the run starts.
  next_share_ = (std::floor(share / share_step_ + 1e-9) + 1.0) * share_step_;
  last_wall_ = wall;
}

bool ProgressSchedule::due(double share, double wall) {
  // 1e-9: a share that reaches a mark up to round-off (t = 0.1 of 1 for 10%) counts as there.
  if (share + 1e-9 < next_share_ && wall - last_wall_ < period_) return false;
  while (next_share_ <= share + 1e-9)
    next_share_ += share_step_;
  last_wall_ = wall;
  return true;
}

ProgressOutput::ProgressOutput(RunContext& context, std::ostream* out, bool show_profile,
                               bool terminal)
    : context_(context), out_(out), show_profile_(show_profile), terminal_(terminal) {}

double ProgressOutput::wall_seconds() const {
  return std::chrono::duration<double>(clock::now() - start_).count();
}

void ProgressOutput::begin(bool) {
  start_ = clock::now();
  last_sample_ = 0.0;
  const SolverState& state = context_.simulation.solver.state();
  rate_.add(0.0, state.time, state.step);
  schedule_.start(state.time / context_.scenario.duration, 0.0);
}

std::string ProgressOutput::describe() const {
  const SolverState& state = context_.simulation.solver.state();
  const double duration = context_.scenario.duration;
  std::ostringstream line;
  line << "  t = " << std::setprecision(4) << state.time << " / " << duration << "  (" << std::fixed
       << std::setprecision(1) << 100.0 * state.time / duration << "%)  " << std::setprecision(0)
       << rate_.steps_per_second() << " steps/s  ETA "
       << format_duration(rate_.seconds_left(duration));
  return line.str();
}

void ProgressOutput::after_step(const StepTaken&) {
  if (!out_) return;
  const double wall = wall_seconds();
  const SolverState& state = context_.simulation.solver.state();
  if (terminal_) {
    if (wall - last_sample_ <= 1.0) return;
    last_sample_ = wall;
    rate_.add(wall, state.time, state.step);
    std::string line = "\r" + describe() + "   ";
    if (show_profile_)
      line += "\n  profile: " + describe_shares(context_.simulation.solver.profile()) + "\n";
    *out_ << line << std::flush;
    return;
  }
  // Plain lines: the rate is sampled once a second as on a terminal, lines as scheduled.
  if (wall - last_sample_ > 1.0) {
    last_sample_ = wall;
    rate_.add(wall, state.time, state.step);
  }
  if (!schedule_.due(state.time / context_.scenario.duration, wall)) return;
  rate_.add(wall, state.time, state.step);
  std::string line = describe() + "\n";
  if (show_profile_)
    line += "  profile: " + describe_shares(context_.simulation.solver.profile()) + "\n";
  *out_ << line << std::flush;
}

}  // namespace sg
