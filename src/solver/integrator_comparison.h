#pragma once
// The two integrators on one model (`softgrain info`): each one's stable step and its measured
// wall time per step, from the model's current state. The integrator is a parameter of the
// step (solver/integrator_params.h), so the comparison changes nothing of the model: each
// integrator steps a stepper of its own from a snapshot of the state, which is restored after.
#include <array>

#include "contact/contact_system.h"
#include "model/model.h"
#include "solver/integrator_params.h"
#include "solver/stable_time_step.h"

namespace sg {

struct IntegratorCost {
  IntegratorParams integrator;
  StableStep stable;              // its stable step on the model's current state
  double seconds_per_step = 0.0;  // wall time, measured (timing only)
  double matrix_bytes = 0.0;      // IMEX: its factors and operators (ViscousSolveStatistics)
};

// The explicit integrator, then the IMEX one with `imex`'s settings, each timed over `steps`
// steps at its stable step after one warm-up step (first contact detection, factorizations).
// `contacts` may be null. The model's and the contacts' state are as before on return.
std::array<IntegratorCost, 2> compare_integrators(Model& model, ContactSystem* contacts,
                                                  double safety, double contact_stiffness,
                                                  const IntegratorParams& imex, int steps = 10);

}  // namespace sg
