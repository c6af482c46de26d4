#pragma once
// Adaptive explicit step (issue #4 "Step control"; docs/method.md §Step control and rejections).
//
// The step is bounded by stability, not by accuracy: for the papers' parameters the critical
// step (damping-aware, stable_time_step.h) is far below what the accuracy of the slow
// granular motion would allow. So the controller
//   1. takes safety x the critical step, re-estimated every `reestimate_interval` accepted
//      steps (finite strain stiffens the grains; the estimate is for the current state);
//   2. checks every step with an error estimate that costs no extra force evaluation: the
//      energy ledger's residual increment. The ledger (stepper.h) closes each
//      interval [t_n-1, t_n] with its own step: its residual changes by the interval's
//      integration error alone, round-off for a linear system under any sequence of steps,
//      a small oscillating amount otherwise (shear cell: median 1e-5, 99th percentile 4e-3
//      of the system's energy per step); a step that creates or destroys more than
//      `tolerance` x the largest energy held so far is an instability or an unresolved
//      event. The velocity update is the variable-step central difference
//      (v_n+1/2 = v_n-1/2 + (dt_- + dt_+)/2 a_n), so a retried smaller step is judged by an
//      error that shrinks with it. (With v_n+1/2 = v_n-1/2 + dt_+ a_n a change of the step
//      made the first-order error 1/2 (dt_+ - dt_-) v_n-1/2 . f_n, which no smaller retry
//      removed: after a violent event every retry showed the same residual jump.)
//      The check does not include the ledger's step_change, K_n^+ - K_n^- =
//      -1/8 (dt_+^2 - dt_-^2) f_n M^-1 f_n at a change of the step: (a) a smaller retry does
//      not reduce it (it tends to 1/8 dt_-^2 f M^-1 f, set by the accepted step before), so
//      rejecting on it would trap the controller again; (b) the true kinetic energy at t_n,
//      with the unique full-step velocity v_n, is continuous across the change: only the
//      modified energy the ledger follows, 1/2 v_n M v_n - 1/8 dt^2 f M^-1 f, changes its
//      definition; (c) it is no larger than that gap between the ledger's and the true
//      kinetic energy which every constant-step run has unchecked. It stays visible, summed,
//      in EnergyLedger::step_change. (Measured on the seam scene of
//      tests/run/test_checkpoint_restart.cpp: +1.6e-4 at the halving after the rejection,
//      -5.0e-4 at a growth by 1.25, against tolerance x scale = 1.5e-3 at 0.0006; at
//      0.0001 a growth's -2.9e-4 exceeds the 2.6e-4 allowed: a check including it would
//      reject the growths.)
//   3. rejects such a step, or one that fails outright (a non-finite value, an inverted
//      Gauss point), restores the state from before it, re-estimates the critical step
//      there and retries at half the step (at most the new stable step); after
//      `recovery_steps` accepted steps at a reduced step it grows back by `growth` up to the
//      stable step.
// The residual after a step describes the previous interval (the ledger is one step
// behind), so with the energy check the controller keeps the states before the last two
// steps, and a rejection rolls both back and retries the earlier one at half its size.
// Without it (the default) a state is held every `hold_interval` steps, and a failed step
// rolls back to the last state held before it (at most 2 hold_interval steps back).
// Accepted steps cost one force evaluation; a rejection costs the rolled-back ones. seal() forgets
// the held states (the run calls it at checkpoints, so that no rollback ever crosses one and a
// resumed run repeats the uninterrupted one bitwise); a step that fails with nothing held is an
// error. Outputs written between a step and its rollback (at most two steps) show the rejected
// trajectory; run.log lists every rejection with its time.
//
// Everything is deterministic (no timing, no thread-count dependence): a run with rejections
// repeats bitwise, and `state()` / `set_state()` carry the controller through a checkpoint.
//
// Why a class holding references to the solver and the contacts, and why exceptions: rejecting
// a step needs the whole state from before it, and the controller keeps the two held snapshots
// and its own counters together with what they were taken from. A step that fails outright
// raises sg::Error where the fault is known (body, Gauss point, step); advance() catches it,
// restores a held snapshot (the failed step may have left forces and velocities half updated)
// and retries, so failure is reported once, after max_halvings retries (core/error.h).
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "contact/contact_system.h"
#include "solver/stable_time_step.h"
#include "solver/state_snapshot.h"
#include "solver/stepper.h"

namespace sg {

// StepControlParams::on_step_collapse: an estimate below the first one / this factor.
inline constexpr double kStepCollapseFactor = 100.0;

struct StepControlParams {
  double safety = 0.8;              // fraction of the critical step, in (0, 1]
  double fixed_step = 0.0;          // > 0: this step always, no estimate, no check
  double initial_step = 0.0;        // > 0: start with this step instead of the estimate (tests)
  long reestimate_interval = 2000;  // accepted steps between critical-step estimates (0: never)
  // Allowed |residual increment| per step / largest energy so far; 0: no energy check (only
  // failed steps are rejected). Off by default: at the start of a run every energy is tiny,
  // and round-off-sized increments against a 1e-8 scale made the shear-cell demo reject 10
  // steps and crawl at dt = 1e-6 for a while; the check needs an absolute floor first.
  double tolerance = 0.0;
  int max_halvings = 8;      // consecutive rejections of one step before giving up
  long recovery_steps = 50;  // accepted steps at a reduced step before it grows
  double growth = 1.25;      // growth factor back towards the stable step
  long hold_interval = 25;   // without the energy check: steps between held states
  // Called once, at the first estimate below the first one / kStepCollapseFactor (a
  // collapsing step: an extreme state the user should hear of); unset: nothing.
  std::function<void(const StableStep& now, double first_dt)> on_step_collapse;
};

// Throws sg::Error naming the key if a value is out of range.
void validate(const StepControlParams& params);

// What the run log reports.
struct StepStatistics {
  long accepted = 0, rejected = 0, estimates = 0;
  double dt_min = std::numeric_limits<double>::infinity(), dt_max = 0.0;
  std::string last_rejection;  // why the last step was rejected (empty: none)
};

// The controller's own evolving state (checkpointed with the run).
struct StepControllerState {
  double dt = 0.0;            // the step the next advance() tries
  double stable_dt = 0.0;     // safety x critical step at the last estimate
  double energy_scale = 0.0;  // largest K + E_elastic + E_contact + |W_ext| seen
  long since_estimate = 0;    // accepted steps since the last estimate
  long since_reduction = 0;   // accepted steps since dt was last reduced or grown
  StepStatistics statistics;
};

class StepController {
 public:
  // Estimates the first step (unless fixed). `contacts` may be null.
  StepController(Stepper& solver, ContactSystem* contacts, const StepControlParams& params);

  // Takes one accepted step and returns its size: holds a state, tries the step, accepts it or
  // rolls back and retries. Throws sg::Error (with the stepper's diagnosis: body, node, step)
  // when a step still fails after max_halvings retries. Its own time (held states, judging,
  // rollbacks, estimates) goes to the step_control phase of the stepper's profile.
  double advance();

  double next_step() const { return state_.dt; }
  const StableStep& last_estimate() const { return estimate_; }
  const StepStatistics& statistics() const { return state_.statistics; }
  const StepControllerState& state() const { return state_; }
  // Continues from a checkpoint: the solver must hold the checkpointed state already.
  void set_state(const StepControllerState& state);
  // Forgets the held states: no later rejection rolls back beyond this point.
  void seal() { held_ = 0; }

 private:
  Stepper& solver_;
  ContactSystem* contacts_;
  StepControlParams params_;
  double contact_stiffness_ = 0.0;
  StableStep estimate_;
  StepControllerState state_;
  // States before the last two steps (ring of two; held_ of them valid) and the steps taken
  // from them; newest_ indexes the state before the last step.
  StateSnapshot held_state_[2];
  double held_dt_[2] = {0.0, 0.0};
  int held_ = 0, newest_ = 1;
  double first_stable_dt_ = 0.0;  // this session's first estimate (on_step_collapse)
  bool collapse_reported_ = false;

  // Why a try was rejected; `failed`: the step threw (else the energy check refused it).
  struct Rejection {
    std::string why;
    bool failed = false;
  };
  // The parts of advance(), in order.
  double take_fixed_step();
  // Holds the state before the step when due; true when it did.
  bool hold_state();
  // Takes the step and judges it; nothing when it is accepted.
  std::optional<Rejection> try_step(double dt, PhaseTimer& timer);
  void accept(double dt);
  // Restores a held state and sets the smaller step to retry; throws when there is nothing to
  // retry from or the retries are exhausted.
  void roll_back(const Rejection& rejection, bool held_now, int rejections);
  bool checks_energy() const { return params_.tolerance > 0.0; }
  void estimate();
};

}  // namespace sg
