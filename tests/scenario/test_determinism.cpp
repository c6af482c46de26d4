// The shear cell (contacts, rigid first bodies, periodic seam, cohesion) gives bitwise the
// same trajectory on 1 and 2 threads: forces are accumulated in a fixed order and sums are
// reduced per body in body order.
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>

#include "scenario/scenario.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

struct Trajectory {
  NodeState nodes;
  RigidState rigid;
  EnergyLedger energy;
};

Trajectory run_shear_cell(int threads) {
  omp_set_num_threads(threads);
  const ScenarioDef s = load_scenario(std::filesystem::path(SOFTGRAIN_SOURCE_DIR) / "examples" /
                                      "shear-cell-small.toml");
  Model model = build_model(s);
  ContactSystem contacts(model, contact_law_table(s), contact_settings(s));
  const double dt =
      estimate_stable_time_step(model, s.time_step_safety, contacts.max_stiffness()).dt;
  Stepper solver(model, &contacts);
  // 600 steps: about one time unit, enough for grains to touch, bond and wrap the seam.
  for (int k = 0; k < 600; ++k)
    solver.step(dt);
  return {model.nodes, model.rigid, solver.state().energy};
}

TEST(Determinism, ShearCellIsBitwiseIdenticalOnOneAndTwoThreads) {
  const Trajectory one = run_shear_cell(1);
  const Trajectory two = run_shear_cell(2);
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_GT(one.energy.contact_elastic + one.energy.contact_dissipated, 0.0);  // contacts happened
  EXPECT_TRUE(one.nodes.ux == two.nodes.ux && one.nodes.uy == two.nodes.uy);
  EXPECT_TRUE(one.nodes.vx == two.nodes.vx && one.nodes.vy == two.nodes.vy);
  EXPECT_TRUE(one.rigid.fx == two.rigid.fx && one.rigid.fy == two.rigid.fy);
  EXPECT_EQ(one.energy.contact_dissipated, two.energy.contact_dissipated);
  EXPECT_EQ(one.energy.damping_dissipated, two.energy.damping_dissipated);
  EXPECT_EQ(one.energy.external_work, two.energy.external_work);
}

}  // namespace
}  // namespace sg
