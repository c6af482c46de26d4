#include "solver/integrator_comparison.h"

#include <chrono>

#include "solver/state_snapshot.h"
#include "solver/stepper.h"

namespace sg {

namespace {

IntegratorCost measure(Model& model, ContactSystem* contacts, double safety,
                       double contact_stiffness, const IntegratorParams& integrator, int steps) {
  IntegratorCost cost;
  cost.integrator = integrator;
  cost.stable = estimate_stable_time_step(model, safety, contact_stiffness, integrator);
  Stepper solver(model, contacts, integrator);
  StateSnapshot initial;
  capture_state(solver, contacts, initial);
  solver.step(cost.stable.dt);  // warm-up (first contact detection, factorizations)
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k)
    solver.step(cost.stable.dt);
  cost.seconds_per_step =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
  cost.matrix_bytes = solver.viscous_statistics().matrix_bytes;
  restore_state(initial, solver, contacts);
  return cost;
}

}  // namespace

std::array<IntegratorCost, 2> compare_integrators(Model& model, ContactSystem* contacts,
                                                  double safety, double contact_stiffness,
                                                  const IntegratorParams& imex, int steps) {
  IntegratorParams implicit = imex;
  implicit.implicit_viscosity = true;
  return {measure(model, contacts, safety, contact_stiffness,
                  IntegratorParams::explicit_integrator(), steps),
          measure(model, contacts, safety, contact_stiffness, implicit, steps)};
}

}  // namespace sg
