#pragma once
// The integrator a scenario gets when its [time] table does not name one (issue #30, item 5):
// `imex` where it is faster than `explicit`, `explicit` otherwise, decided on the built model
// before the first step (docs/scenario.md "Integrators").
//
// IMEX is faster when its step gain outweighs its cost per step:
//     dt_imex / dt_explicit  >  cost of an imex step / cost of an explicit step,
// both steps estimated on the initial state from one estimate of the body frequencies (the
// explicit one damping-aware, the imex one without the damping of the bodies it treats
// implicitly), the cost ratio that of the costliest damping model among those bodies
// (imex_step_cost). The decision uses no clock, so a run repeats bitwise whatever the machine.
//
// When imex is chosen this way, the step controller's energy check is on by default
// (kDefaultImexStepTolerance): at a violent event the undamped step the implicit viscosity
// allows is too coarse for the contacts, and the ledger residual grows to several percent of
// the external work; the check halves the step there and lets it grow back.
#include <string>

#include "material/material.h"
#include "model/model.h"
#include "solver/integrator_params.h"

namespace sg {

// The [time] step_tolerance of a run whose integrator was chosen imex by default and that sets
// none. Measured on a cell compacted in 0.2 time units (20 cohesive grains, L = 10,
// alpha = 0.3, h = 0.25, seeds 1, 3, 4, 5): the ledger residual, in percent of the external
// work, is 9.9 / 26 / 1.7 / 3.6 with imex unchecked, 0.30 / 0.60 / 0.32 / 0.44 at 0.01 (8, 6,
// 4, 5 rejected steps), 0.37 / 0.45 / 0.23 / 0.42 explicit (docs/scenario.md "Integrators").
inline constexpr double kDefaultImexStepTolerance = 0.01;

// Wall time of an imex step over that of an explicit step with the same damping model: the
// largest ratio measured on bench/scenes/imex-cell.toml (whole runs, alpha = 0.02 and 0.3,
// 1 and 2 threads, bench/results/debian12-2core/imex.csv): objective 3.3 to 5.5 (its
// conjugate gradients), corotational 1.35 to 1.6, reference_stiffness 1.4 to 1.9 (one stored
// factor each). The largest, so that imex is chosen only where it is faster on either count
// of threads.
double imex_step_cost(DampingModel model);

struct IntegratorChoice {
  IntegratorParams params;      // the integrator the run steps with
  double step_tolerance = 0.0;  // the step controller's energy check (0: off)
  bool by_default = false;      // [time] integrator absent: chosen here
  // By default: why (the steps compared, or why none was needed); empty otherwise.
  std::string reason;
};

// The default for `model` (built, masses not yet scaled). `imex`: the settings imex would run
// with; `fixed_step` > 0: a fixed step, which the integrator does not change (explicit).
// `step_tolerance` < 0: none written (kDefaultImexStepTolerance if imex is chosen, else 0).
IntegratorChoice choose_default_integrator(const Model& model, double safety,
                                           double contact_stiffness, const IntegratorParams& imex,
                                           double fixed_step, double step_tolerance);

// "imex (default: ...; step_tolerance 0.01)", "explicit (default: ...)", or the name alone
// when written.
std::string describe(const IntegratorChoice& choice);

}  // namespace sg
