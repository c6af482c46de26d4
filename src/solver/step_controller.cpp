#include "solver/step_controller.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/error.h"

namespace sg {

namespace {
// A run whose retried step falls below this fraction of the stable step stops with an error.
constexpr double kSmallestStepFraction = 1e-6;
}  // namespace

void validate(const StepControlParams& p) {
  SG_VERIFY(p.safety > 0.0 && p.safety <= 1.0,
            "step control: safety must be in (0, 1], got " << p.safety);
  SG_VERIFY(p.fixed_step >= 0.0 && std::isfinite(p.fixed_step),
            "step control: fixed_step must be >= 0, got " << p.fixed_step);
  SG_VERIFY(p.initial_step >= 0.0 && std::isfinite(p.initial_step),
            "step control: initial_step must be >= 0, got " << p.initial_step);
  SG_VERIFY(p.reestimate_interval >= 0,
            "step control: reestimate_interval must be >= 0, got " << p.reestimate_interval);
  SG_VERIFY(p.tolerance >= 0.0, "step control: tolerance must be >= 0, got " << p.tolerance);
  SG_VERIFY(p.max_halvings >= 1, "step control: max_halvings must be >= 1, got " << p.max_halvings);
  SG_VERIFY(p.recovery_steps >= 1,
            "step control: recovery_steps must be >= 1, got " << p.recovery_steps);
  SG_VERIFY(p.growth > 1.0, "step control: growth must be > 1, got " << p.growth);
  SG_VERIFY(p.hold_interval >= 1,
            "step control: hold_interval must be >= 1, got " << p.hold_interval);
}

StepController::StepController(Stepper& solver, ContactSystem* contacts,
                               const StepControlParams& params)
    : solver_(solver), contacts_(contacts), params_(params) {
  validate(params_);
  contact_stiffness_ = contacts_ ? contacts_->max_stiffness() : 0.0;
  if (params_.fixed_step > 0.0) {
    state_.dt = state_.stable_dt = params_.fixed_step;
    return;
  }
  estimate();
  state_.dt = params_.initial_step > 0.0 ? params_.initial_step : state_.stable_dt;
}

void StepController::estimate() {
  const bool reduced = state_.dt > 0.0 && state_.dt < state_.stable_dt;
  estimate_ = estimate_stable_time_step(solver_.model(), params_.safety, contact_stiffness_,
                                        solver_.integrator());
  state_.stable_dt = estimate_.dt;
  if (first_stable_dt_ == 0.0) first_stable_dt_ = estimate_.dt;
  if (params_.on_step_collapse && !collapse_reported_ &&
      estimate_.dt * kStepCollapseFactor < first_stable_dt_) {
    collapse_reported_ = true;
    params_.on_step_collapse(estimate_, first_stable_dt_);
  }
  state_.since_estimate = 0;
  ++state_.statistics.estimates;
  // A step reduced after a rejection keeps growing back on its own schedule; otherwise the
  // step follows the estimate, down or up.
  state_.dt = reduced ? std::min(state_.dt, state_.stable_dt) : state_.stable_dt;
}

void StepController::set_state(const StepControllerState& state) {
  state_ = state;
  seal();
}

// One accepted step: hold a state to roll back to, try the step, accept it or roll back and
// retry smaller. The controller's own work (held states, judging, rollbacks, estimates) is
// timed into the step_control phase of the stepper's profile; the step times its own phases.
double StepController::advance() {
  if (params_.fixed_step > 0.0) return take_fixed_step();
  PhaseTimer timer(solver_.profile());
  if (params_.reestimate_interval > 0 && state_.since_estimate >= params_.reestimate_interval)
    estimate();
  for (int rejections = 0;; ++rejections) {
    const bool held_now = hold_state();
    const double dt = state_.dt;
    const std::optional<Rejection> rejection = try_step(dt, timer);
    if (!rejection) {
      accept(dt);
      timer.stamp(StepPhase::step_control);
      return dt;
    }
    roll_back(*rejection, held_now, rejections);
    timer.stamp(StepPhase::step_control);
  }
}

double StepController::take_fixed_step() {
  StepStatistics& stats = state_.statistics;
  solver_.step(params_.fixed_step);
  ++stats.accepted;
  stats.dt_min = stats.dt_max = params_.fixed_step;
  return params_.fixed_step;
}

bool StepController::hold_state() {
  // The energy check judges the previous interval, so it needs the state before every step;
  // a failed step only needs some earlier state, and copying every node array each step
  // would cost a few percent of the step for a rare event: then a state is held every
  // hold_interval steps (and whenever none is held).
  const bool hold_now =
      checks_energy() || held_ == 0 || solver_.state().step % params_.hold_interval == 0;
  if (hold_now) {  // the older held state is overwritten
    newest_ = 1 - newest_;
    capture_state(solver_, contacts_, held_state_[newest_]);
    held_dt_[newest_] = state_.dt;
    held_ = std::min(held_ + 1, 2);
  }
  return hold_now;
}

std::optional<StepController::Rejection> StepController::try_step(double dt, PhaseTimer& timer) {
  const double residual_before = solver_.state().energy.residual();
  timer.stamp(StepPhase::step_control);
  try {
    solver_.step(dt);
  } catch (const Error& e) {
    timer.skip();  // the step's phases, booked by the step itself
    return Rejection{e.what(), true};
  }
  timer.skip();
  // The residual increment of this call is the error of the previous interval.
  const EnergyLedger& e = solver_.state().energy;
  state_.energy_scale =
      std::max(state_.energy_scale,
               std::abs(e.kinetic) + e.elastic + e.contact_elastic + std::abs(e.external_work));
  const double increment = e.residual() - residual_before;
  if (params_.tolerance == 0.0 || std::abs(increment) <= params_.tolerance * state_.energy_scale)
    return std::nullopt;
  std::ostringstream s;
  s << "energy residual changed by " << increment << " in one step (tolerance " << params_.tolerance
    << " x energy scale " << state_.energy_scale << ")";
  return Rejection{s.str(), false};
}

void StepController::accept(double dt) {
  StepStatistics& stats = state_.statistics;
  ++stats.accepted;
  stats.dt_min = std::min(stats.dt_min, dt);
  stats.dt_max = std::max(stats.dt_max, dt);
  ++state_.since_estimate;
  if (state_.dt < state_.stable_dt && ++state_.since_reduction >= params_.recovery_steps) {
    state_.dt = std::min(state_.stable_dt, state_.dt * params_.growth);
    state_.since_reduction = 0;
  }
}

void StepController::roll_back(const Rejection& rejection, bool held_now, int rejections) {
  // Back to a state from before the interval that went wrong: the older held state when one
  // was taken at the start of this try, else the newest.
  const int target = held_now ? (held_ == 2 ? 1 - newest_ : -1) : newest_;
  const bool nothing_to_retry = target < 0 && (rejection.failed || !checks_energy());
  const int shown = target < 0 ? newest_ : target;
  std::ostringstream note;
  note << "t = " << solver_.state().time << ", step " << solver_.state().step
       << ", dt = " << held_dt_[shown] << ": " << rejection.why;
  if (rejections >= params_.max_halvings || nothing_to_retry)
    SG_THROW(
        "step rejected " << rejections + 1 << " times; last: " << note.str()
                         << (nothing_to_retry ? " (no earlier state held to retry from)" : ""));
  const int from = target < 0 ? newest_ : target;  // energy check right after a seal
  restore_state(held_state_[from], solver_, contacts_);
  // Half the rejected step, and never more than the stable step of the restored state (an
  // estimate older than the event, or a user-given first step, may have been too large).
  const double rejected_dt = held_dt_[from];
  estimate();
  state_.dt = std::min(0.5 * rejected_dt, state_.stable_dt);
  // Retries separated by a few accepted steps each never reach max_halvings: without this
  // bound such a run halves its step forever (the fuzzer's gravity = 1e300, issue #15).
  if (state_.dt < kSmallestStepFraction * state_.stable_dt)
    SG_THROW("step rejected again and again: the step fell to "
             << state_.dt << ", below " << kSmallestStepFraction << " of the stable step "
             << state_.stable_dt << "; last: " << note.str());
  state_.since_reduction = 0;
  held_ = 0;
  ++state_.statistics.rejected;
  state_.statistics.last_rejection = note.str();
}

}  // namespace sg
