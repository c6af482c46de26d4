// `softgrain info`'s comparison of the integrators (solver/integrator_comparison.h): the
// integrator is passed to the stepper and to the stable step, never stored in the model, so
// comparing them leaves the model as it was, bit for bit, and each integrator gets its own
// stable step.
#include <gtest/gtest.h>

#include <vector>

#include "model/kinematics.h"
#include "scenes/free_grains.h"
#include "solver/integrator_comparison.h"
#include "solver/stable_time_step.h"

namespace sg {
namespace {

// The node arrays that are state or fixed data, concatenated (the force arrays are each step's
// scratch, recomputed before they are read: docs/architecture.md "Data layout").
std::vector<double> state_of(const Model& model) {
  std::vector<double> all;
  const NodeState& n = model.nodes;
  for (const std::vector<double>* a :
       {&n.ref_x, &n.ref_y, &n.ux, &n.uy, &n.vx, &n.vy, &n.mass, &n.inverse_mass})
    all.insert(all.end(), a->begin(), a->end());
  return all;
}

TEST(IntegratorComparison, LeavesTheModelUnchangedAndGivesEachIntegratorItsStep) {
  // A stiffly damped disc (alpha 0.1, nu 0.45): the explicit step is damping-limited, the
  // IMEX step is not.
  Model model = scenes::single_disc(
      scenes::elastic_material(MaterialLaw::neo_hookean, 0.1, 0.45, 10.0), 1.0, 0.2);
  Mat2 stretch;
  stretch << 1.01, 0.0, 0.0, 0.99;
  set_affine_deformation(model, 0, stretch);
  set_rigid_velocity(model, 0, Vec2(0.1, -0.2), 0.3);
  const std::vector<double> before = state_of(model);
  const StableStep explicit_before = estimate_stable_time_step(model, 0.8);

  const std::array<IntegratorCost, 2> costs =
      compare_integrators(model, nullptr, 0.8, 0.0, IntegratorParams::imex(1e-6, 0.2), 3);

  EXPECT_EQ(state_of(model), before) << "the comparison changed the model's state";
  EXPECT_FALSE(costs[0].integrator.implicit_viscosity);
  EXPECT_TRUE(costs[1].integrator.implicit_viscosity);
  EXPECT_EQ(costs[1].integrator.imex_tolerance, 1e-6);  // the settings given, passed on
  EXPECT_EQ(costs[1].integrator.imex_refactor_threshold, 0.2);
  EXPECT_EQ(costs[0].stable.dt, explicit_before.dt);
  EXPECT_TRUE(costs[0].stable.damping_limited);
  EXPECT_FALSE(costs[1].stable.damping_limited);
  EXPECT_GT(costs[1].stable.dt, 2.0 * costs[0].stable.dt);
  EXPECT_GT(costs[0].seconds_per_step, 0.0);
  EXPECT_GT(costs[1].seconds_per_step, 0.0);
  // And after it, the model's own estimate is still the explicit one: nothing was stored.
  EXPECT_EQ(estimate_stable_time_step(model, 0.8).dt, explicit_before.dt);
}

}  // namespace
}  // namespace sg
