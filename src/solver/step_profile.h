#pragma once
// Where the time of a run goes: wall seconds per phase of the step (Stepper::step), of the
// step controller (StepController::advance) and of the run loop around them
// (src/run/run_session.cpp), summed over the run. Timing only: nothing of the
// physics reads it, and it is never checkpointed (a resumed run's profile covers that session).
//
// The phases are those of the step as it reads (docs/architecture.md "The step"); each is
// stamped once per step, so the profile costs 8 clock reads per step (about 0.2 us), well under
// 1% of the smallest step we run. (The node forces and the velocities are done body by body in
// one loop, timed per body: three more reads per body, about 0.3% of the step.)
#include <array>
#include <chrono>
#include <cstddef>
#include <initializer_list>
#include <string_view>
#include <utility>

namespace sg {

enum class StepPhase : std::size_t {
  external_forces,  // rigid accumulators cleared
  contacts,         // broad phase refresh, narrow phase, contact laws; per body: gravity on
                    // the nodes and the spread of the contact forces
  internal_forces,  // elastic (and explicit viscous) forces of deformable bodies
  velocities,       // field-node velocities with drives and carriers (the integrator's phase)
  rigid_bodies,     // rigid degrees of freedom: velocities and positions
  positions,        // field-node displacements, periodic wrap, finite check
  ledger,           // the energy ledger
  step_control,     // held states, rollbacks and critical-step estimates (the controller)
  outputs,          // series rows, snapshots, checkpoints, progress (the run loop)
  count
};

inline constexpr std::size_t kStepPhaseCount = static_cast<std::size_t>(StepPhase::count);

constexpr std::string_view phase_name(StepPhase phase) {
  constexpr std::array<std::string_view, kStepPhaseCount> names = {
      "external forces", "contacts", "internal forces", "velocities", "rigid bodies",
      "positions",       "ledger",   "step control",    "outputs"};
  return names[static_cast<std::size_t>(phase)];
}

struct StepProfile {
  std::array<double, kStepPhaseCount> seconds{};  // wall seconds per phase
  long steps = 0;                                 // force evaluations timed

  double total() const {
    double sum = 0.0;
    for (double s : seconds)
      sum += s;
    return sum;
  }
  double operator[](StepPhase phase) const { return seconds[static_cast<std::size_t>(phase)]; }
};

// Books the time since the previous stamp to a phase: `stamp(p)` closes phase p.
class PhaseTimer {
 public:
  explicit PhaseTimer(StepProfile& profile) : profile_(profile), last_(clock::now()) {}
  void stamp(StepPhase phase) {
    const clock::time_point now = clock::now();
    profile_.seconds[static_cast<std::size_t>(phase)] +=
        std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }
  // Books the time since the previous stamp to phases done together, body by body, in
  // proportion to the threads' seconds measured in each.
  void stamp_split(std::initializer_list<std::pair<StepPhase, double>> shares) {
    const clock::time_point now = clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    double measured = 0.0;
    for (const auto& [phase, share] : shares)
      measured += share;
    for (const auto& [phase, share] : shares)
      profile_.seconds[static_cast<std::size_t>(phase)] +=
          measured > 0.0 ? seconds * share / measured
                         : seconds / static_cast<double>(shares.size());
    last_ = now;
  }
  // Books the time since the previous stamp to no phase: it was timed elsewhere (the step's
  // own phases, inside the step controller's).
  void skip() { last_ = clock::now(); }

 private:
  using clock = std::chrono::steady_clock;
  StepProfile& profile_;
  clock::time_point last_;
};

}  // namespace sg
