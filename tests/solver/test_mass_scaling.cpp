// Mass scaling (solver/mass_scaling.h): the closed-form factor, which bodies it scales, and
// that gravity keeps acting on the physical mass while the inertia is scaled.
#include <gtest/gtest.h>

#include <cmath>

#include "../scenes/contact_scenes.h"
#include "../scenes/free_grains.h"
#include "core/error.h"
#include "geometry/shapes.h"
#include "solver/mass_scaling.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"

namespace sg {
namespace {

TEST(MassScaling, FactorBringsTheCriticalStepExactlyToTheTarget) {
  // Damped (xi = alpha omega / 2 = 5: damping-limited) and undamped modes.
  for (const double alpha : {0.0, 0.01, 0.1}) {
    const double omega = 100.0;
    const double target = 3.0 * critical_time_step(omega, alpha);
    const double s = mass_scale_for_step(omega, alpha, target);
    EXPECT_GT(s, 1.0);
    EXPECT_NEAR(critical_time_step(omega / std::sqrt(s), alpha), target, 1e-12 * target)
        << "alpha " << alpha;
    // Undamped, the step is proportional to sqrt(m): three times the step, nine times the mass.
    if (alpha == 0.0) {
      EXPECT_NEAR(s, 9.0, 1e-12);
    }
    // Already at or above the target: nothing to do.
    EXPECT_EQ(mass_scale_for_step(omega, alpha, 0.5 * critical_time_step(omega, alpha)), 1.0);
  }
}

// Two free discs of the same material: a coarse large one and a finely resolved small one
// (the small spacing sets the critical step). A target between their critical steps scales
// the fine disc only, and the step estimated afterwards reaches the target.
TEST(MassScaling, ScalesOnlyTheBodiesBelowTheTargetAndTheStepReachesIt) {
  Model model;
  const MaterialId m = model.add_material(scenes::elastic_material(MaterialLaw::neo_hookean, 0.01));
  const BodyId coarse = scenes::add_disc(model, m, Vec2(0, 0), 0.5, 0.1, "coarse");
  const BodyId fine = scenes::add_disc(model, m, Vec2(3, 0), 0.3, 0.04, "fine");
  const double safety = 0.8;
  const std::vector<double> omega = estimate_body_frequencies(model, 0.0).omega;
  const double step_coarse = safety * critical_time_step(omega[0], 0.01);
  const double step_fine = safety * critical_time_step(omega[1], 0.01);
  ASSERT_LT(step_fine, 0.7 * step_coarse) << "the scene must have one limiting body";
  const double target = 0.5 * (step_fine + step_coarse);
  const std::vector<double> mass_before = model.nodes.mass;

  const MassScalingReport report = apply_mass_scaling(model, target, safety, 0.0);
  EXPECT_EQ(report.scaled_bodies, 1);
  EXPECT_EQ(report.max_factor_body, fine);
  const Body& c = model.body(coarse);
  const Body& f = model.body(fine);
  EXPECT_EQ(c.mass_scale, 1.0);
  for (int i = c.node_begin; i < c.node_end; ++i)
    EXPECT_EQ(model.nodes.mass[static_cast<std::size_t>(i)],
              mass_before[static_cast<std::size_t>(i)]);
  double fine_mass = 0.0;
  for (int i = f.node_begin; i < f.node_end; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_DOUBLE_EQ(model.nodes.mass[k], f.mass_scale * mass_before[k]);
    EXPECT_DOUBLE_EQ(model.nodes.inverse_mass[k], 1.0 / model.nodes.mass[k]);
    fine_mass += mass_before[k];
  }
  EXPECT_NEAR(report.added_mass, (f.mass_scale - 1.0) * fine_mass, 1e-12 * report.added_mass);
  // The estimate on the scaled model (fresh power iterations) lands on the target: the
  // fine disc now sits at the target, the coarse one stays above it.
  const StableStep after = estimate_stable_time_step(model, safety);
  EXPECT_NEAR(after.dt, target, 1e-4 * target);
  EXPECT_EQ(after.limiting_body, fine);
  // Scaling twice is refused (the factors are computed from the physical masses).
  EXPECT_THROW(apply_mass_scaling(model, target, safety, 0.0), Error);
}

// Free fall: gravity g on the physical mass m, inertia s m, so every scaled body accelerates
// at g / s, deformable or rigid; the energy ledger stays balanced (work of gravity = kinetic
// energy gained, with the scaled masses).
TEST(MassScaling, GravityActsOnThePhysicalMassAndTheLedgerBalances) {
  Model model;
  const MaterialId soft = model.add_material(scenes::elastic_material());
  const MaterialId hard = model.add_material(scenes::rigid_material("steel", 2.0));
  const BodyId grain = scenes::add_disc(model, soft, Vec2(0, 0), 0.5, 0.1, "grain");
  const BodyId stone = model.add_rigid_body("stone", make_disc(Vec2(3, 0), 0.4, 0.1), hard);
  model.gravity = Vec2(0.0, -1.0);
  const std::vector<double> omega = estimate_body_frequencies(model, 0.0).omega;
  const double physical_step = 0.8 * critical_time_step(omega[0], 0.0);
  // A contact stiffness so that the rigid disc has a frequency too and is scaled as well.
  const double k = 1000.0;
  const MassScalingReport report = apply_mass_scaling(model, 4.0 * physical_step, 0.8, k);
  ASSERT_EQ(report.scaled_bodies, 2);
  const double s_grain = model.body(grain).mass_scale;
  const double s_stone = model.body(stone).mass_scale;
  EXPECT_GT(s_grain, 10.0);  // four times the step: ~16 times the mass
  EXPECT_GT(s_stone, 1.0);
  // With contacts each body's estimate holds its partners' contact terms too: the passes
  // still bring the step of the scaled model to the target.
  EXPECT_GE(estimate_stable_time_step(model, 0.8, k).dt, (1.0 - 1e-4) * 4.0 * physical_step);

  Stepper solver(model);
  const double dt = 4.0 * physical_step;
  const int steps = 200;
  for (int i = 0; i < steps; ++i)
    solver.step(dt);
  const double t = steps * dt;
  const Body& g = model.body(grain);
  for (int i = g.node_begin; i < g.node_end; ++i)
    ASSERT_NEAR(model.nodes.vy[static_cast<std::size_t>(i)], -t / s_grain, 1e-12 * t);
  const auto r = static_cast<std::size_t>(model.body(stone).rigid_index);
  EXPECT_NEAR(model.rigid.vy[r], -t / s_stone, 1e-12 * t);
  const EnergyLedger& e = solver.state().energy;
  EXPECT_GT(e.external_work, 0.0);
  EXPECT_LT(std::abs(e.residual()), 1e-10 * e.external_work);
}

}  // namespace
}  // namespace sg
