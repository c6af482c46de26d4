#pragma once
// The three time intervals around the force evaluation at t_n of a variable step
// (solver/stepper.h): the step that ended at t_n, the step about to be taken, and the interval
// between the two half-step velocities.
namespace sg {

struct StepSizes {
  double previous;           // dt_- = t_n - t_n-1 (dt_+ at the first step)
  double next;               // dt_+ = t_n+1 - t_n
  double velocity_interval;  // h_n = (dt_- + dt_+) / 2: from v_n-1/2 to v_n+1/2
};

// The intervals of a step `next` after a step `previous` (0: none yet, as at the run's first
// step: the initial velocities are v_-1/2, as for a constant step). h_n is `next` bitwise when
// the step does not change (0.5 * (dt + dt) is exact).
inline StepSizes step_sizes(double previous, double next) {
  const double dt_prev = previous > 0.0 ? previous : next;
  return StepSizes{dt_prev, next, 0.5 * (dt_prev + next)};
}

}  // namespace sg
