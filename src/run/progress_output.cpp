#include "run/progress_output.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
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

ProgressOutput::ProgressOutput(RunContext& context, std::ostream* out, bool show_profile)
    : context_(context), out_(out), show_profile_(show_profile) {}

void ProgressOutput::begin(bool) {
  start_ = last_line_ = clock::now();
  first_step_ = context_.simulation.solver.state().step;
  first_time_ = context_.simulation.solver.state().time;
}

void ProgressOutput::after_step(const StepTaken& step) {
  if (!out_ || clock::now() - last_line_ <= std::chrono::seconds(1)) return;
  last_line_ = clock::now();
  const SolverState& state = context_.simulation.solver.state();
  const double duration = context_.scenario.duration;
  const double elapsed = std::chrono::duration<double>(last_line_ - start_).count();
  const double rate = static_cast<double>(step.start.step + 1 - first_step_) / elapsed;
  const double time_rate = (state.time - first_time_) / elapsed;
  std::ostringstream line;
  line << "\r  t = " << std::setprecision(4) << state.time << " / " << duration << "  ("
       << std::fixed << std::setprecision(1) << 100.0 * state.time / duration << "%)  "
       << std::setprecision(0) << rate << " steps/s  ETA "
       << format_duration((duration - state.time) / time_rate) << "   ";
  if (show_profile_)
    line << "\n  profile: " << describe_shares(context_.simulation.solver.profile()) << "\n";
  *out_ << line.str() << std::flush;
}

}  // namespace sg
