// Dynamics of free deformable grains under the explicit solver: energy conservation,
// dissipation bookkeeping, momentum conservation, objective damping, the stable step, and
// independence of the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "model/kinematics.h"
#include "scenes/free_grains.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"

namespace sg {
namespace {

double shear_wave_speed(const MaterialParams& m) {
  return std::sqrt(m.mu / m.density);
}

// The lowest non-rigid mode of a free disc (ovalling, n = 2) has omega a / c_s ~ 2.5 for
// nu = 0.3 (see test_vibration.cpp for the exact value); periods are counted with it.
double ovalling_period(const MaterialParams& m, double radius) {
  return 2.0 * std::numbers::pi * radius / (2.5 * shear_wave_speed(m));
}

// Largest relative deviation of K + E from its initial value over 50 periods of the lowest
// mode, for a grain released from a 5% uniaxial stretch, stepping at `fraction` of the
// estimated stable step.
double undamped_energy_drift(double fraction) {
  const double radius = 0.5, h = 0.07;
  Model model = scenes::single_disc(scenes::elastic_material(), radius, h);
  Mat2 stretch = Mat2::Identity();
  stretch(0, 0) = 1.05;  // 5% uniaxial stretch
  set_affine_deformation(model, 0, stretch);
  const StableStep stable = estimate_stable_time_step(model, fraction);
  Stepper solver(model);
  const double duration = 50.0 * ovalling_period(model.materials[0], radius);
  const long steps = std::lround(duration / stable.dt);
  double initial = 0.0, worst = 0.0;
  for (long s = 0; s < steps; ++s) {
    solver.step(stable.dt);
    const EnergyLedger& e = solver.state().energy;
    const double total = e.kinetic + e.elastic;
    if (s == 0) initial = total;
    worst = std::max(worst, std::abs(total - initial) / initial);
  }
  std::printf("undamped at %.2f of the stable step: %ld steps of %.4g, max energy error %.3e\n",
              fraction, steps, stable.dt, worst);
  EXPECT_GT(initial, 0.0);
  return worst;
}

TEST(Energy, UndampedGrainReleasedFromStretchConservesEnergy) {
  // Symplectic Euler keeps the energy error bounded (no drift), of order (omega dt)^2 in the
  // excited modes: measured 1.8e-2 at 0.8 of the stable step (the release from a homogeneous
  // stretch excites the highest modes), 4.5e-3 at 0.5, 2.5e-3 at 0.4, 6.8e-4 at 0.2. The issue's
  // 0.5% is met with margin at 0.4 of the stable step, and halving the step must divide the
  // error by about 4.
  const double coarse = undamped_energy_drift(0.4);
  const double fine = undamped_energy_drift(0.2);
  EXPECT_LT(coarse, 5e-3);
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_LT(coarse / fine, 5.5);
}

TEST(Energy, DampedGrainLosesEnergyMonotonicallyAndTheLedgerAccountsForIt) {
  const double radius = 0.5, h = 0.07;
  Model model =
      scenes::single_disc(scenes::elastic_material(MaterialLaw::neo_hookean, 0.01), radius, h);
  Mat2 stretch = Mat2::Identity();
  stretch(0, 0) = 1.05;
  set_affine_deformation(model, 0, stretch);
  const StableStep stable = estimate_stable_time_step(model, 0.8);
  Stepper solver(model);
  const long steps = std::lround(10.0 * ovalling_period(model.materials[0], radius) / stable.dt);
  double initial = 0.0, previous = 0.0;
  int increases = 0;
  for (long s = 0; s < steps; ++s) {
    solver.step(stable.dt);
    const EnergyLedger& e = solver.state().energy;
    const double total = e.kinetic + e.elastic;
    if (s == 0) initial = total;
    // Monotone up to 1e-6 of the initial energy: the time-centred ledger is exact for a linear
    // system; the neo-Hookean non-linearity leaves increases of ~2e-9 of it (measured).
    if (s > 1 && total > previous + 1e-6 * initial) {
      ++increases;
      std::printf("energy increased at step %ld: %.17g -> %.17g\n", s, previous, total);
    }
    previous = total;
  }
  const EnergyLedger& e = solver.state().energy;
  const double lost = initial - (e.kinetic + e.elastic);
  std::printf("damped: lost %.4g of %.4g, dissipated %.4g, residual %.3e\n", lost, initial,
              e.damping_dissipated, e.residual());
  EXPECT_GT(lost, 0.5 * initial);  // the oscillation is mostly damped out over 10 periods
  EXPECT_EQ(increases, 0);
  EXPECT_NEAR(e.damping_dissipated, lost, 0.01 * lost);  // issue requirement: 1%
}

TEST(Momentum, FreeSpinningDeformedGrainConservesLinearAndAngularMomentum) {
  Model model =
      scenes::single_disc(scenes::elastic_material(MaterialLaw::neo_hookean, 0.02), 0.5, 0.08);
  Mat2 f;
  f << 1.03, 0.02, 0.0, 0.98;
  set_affine_deformation(model, 0, f);
  set_rigid_velocity(model, 0, Vec2(1.0, -0.5), 2.0);
  const Vec2 p0 = linear_momentum(model);
  const double l0 = angular_momentum(model);
  const StableStep stable = estimate_stable_time_step(model, 0.8);
  Stepper solver(model);
  for (int s = 0; s < 2000; ++s)
    solver.step(stable.dt);
  // Round-off: ~1e-16 per operation, accumulated over 2000 steps and ~300 nodes.
  EXPECT_NEAR((linear_momentum(model) - p0).norm(), 0.0, 1e-12 * p0.norm());
  EXPECT_NEAR(angular_momentum(model), l0, 1e-11 * std::abs(l0));
  EXPECT_GT(solver.state().energy.damping_dissipated, 0.0);  // the grain did deform
}

TEST(ObjectiveDamping, SpinningUndeformedGrainKeepsItsKineticEnergy) {
  // Slow spin (centrifugal strain rho omega^2 a^2 / E ~ 2e-4) over two full turns with
  // strong damping: the kinetic energy stays; alpha K0 v would dissipate most of it.
  const double omega = 0.2;
  Model model =
      scenes::single_disc(scenes::elastic_material(MaterialLaw::neo_hookean, 0.05), 0.5, 0.08);
  set_rigid_velocity(model, 0, Vec2(0, 0), omega);
  const double k0 = kinetic_energy(model);
  const StableStep stable = estimate_stable_time_step(model, 0.8);
  Stepper solver(model);
  const long steps = std::lround(2.0 * 2.0 * std::numbers::pi / omega / stable.dt);
  for (long s = 0; s < steps; ++s)
    solver.step(stable.dt);
  const double k1 = kinetic_energy(model);
  std::printf("spin: K1/K0 - 1 = %.3e, dissipated/K0 = %.3e\n", k1 / k0 - 1,
              solver.state().energy.damping_dissipated / k0);
  EXPECT_NEAR(k1 / k0, 1.0, 1e-3);
  EXPECT_LT(solver.state().energy.damping_dissipated / k0, 1e-3);
}

TEST(StableStep, EstimateIsBelowTheWaveSpeedBoundAndSeparatesStableFromUnstable) {
  for (double alpha : {0.0, 0.02}) {
    Model model = scenes::single_disc(
        scenes::elastic_material(MaterialLaw::neo_hookean, alpha, 0.495), 0.5, 0.1);
    const double omega = estimate_max_frequency(model, 0);
    EXPECT_LT(omega, wave_speed_frequency_bound(model, 0));
    const double dt_critical = critical_time_step(omega, alpha);
    // Growth of the largest displacement over 3000 steps from a small pattern exciting every
    // mode: below the limit the energy is conserved or damped, so amplitudes stay of the same
    // order; above it, the highest mode is amplified every step.
    auto growth = [&](double factor) {
      Model m = model;
      for (std::size_t i = 0; i < m.node_count(); ++i) {
        m.nodes.ux[i] = 1e-6 * std::sin(12.9898 * static_cast<double>(i));
        m.nodes.uy[i] = 1e-6 * std::cos(78.233 * static_cast<double>(i));
      }
      auto largest = [&] {
        double u = 0.0;
        for (std::size_t i = 0; i < m.node_count(); ++i)
          u = std::max({u, std::abs(m.nodes.ux[i]), std::abs(m.nodes.uy[i])});
        return u;
      };
      const double initial = largest();
      Stepper solver(m);
      try {
        for (int s = 0; s < 3000; ++s)
          solver.step(factor * dt_critical);
      } catch (const Error&) {
        return 1e300;
      }
      return largest() / initial;
    };
    const double below = growth(0.97), above = growth(1.1);
    std::printf("alpha %.2f: amplitude growth at 0.97 dt_crit %.3g, at 1.1 dt_crit %.3g\n", alpha,
                below, above);
    EXPECT_LT(below, 10.0) << "alpha " << alpha;
    EXPECT_GT(above, 1e3) << "alpha " << alpha;
  }
}

TEST(StableStep, DampingSetsTheLimitForThePapersParameters) {
  // docs/method.md §Stable step: E = 10, rho = 1, nu = 0.495, h ~ 0.12, alpha = 0.02 gives xi ~ 3
  // and dt ~ 1e-3.
  Model model = scenes::single_disc(scenes::elastic_material(MaterialLaw::neo_hookean, 0.02, 0.495),
                                    0.5, 0.12);
  const StableStep s = estimate_stable_time_step(model, 1.0);
  EXPECT_TRUE(s.damping_limited);
  EXPECT_GT(s.dt, 3e-4);
  EXPECT_LT(s.dt, 3e-3);
}

TEST(Threads, OneAndTwoThreadsGiveBitwiseIdenticalTrajectories) {
  auto run = [](int threads) {
    omp_set_num_threads(threads);
    Model model;
    const MaterialId m =
        model.add_material(scenes::elastic_material(MaterialLaw::neo_hookean, 0.02));
    for (int k = 0; k < 12; ++k) {
      const BodyId b = scenes::add_disc(model, m, Vec2(1.2 * k, 0.1 * (k % 3)), 0.5 + 0.02 * k, 0.1,
                                        "g" + std::to_string(k));
      set_rigid_velocity(model, b, Vec2(0.1 * k, -0.2), 0.5 * (k % 4));
      Mat2 f = Mat2::Identity();
      f(0, 1) = 0.01 * k;
      set_affine_deformation(model, b, f);
    }
    model.gravity = Vec2(0, -1);
    const StableStep stable = estimate_stable_time_step(model, 0.8);
    Stepper solver(model);
    for (int s = 0; s < 300; ++s)
      solver.step(stable.dt);
    return std::make_pair(model.nodes, solver.state().energy);
  };
  const auto [one, e1] = run(1);
  const auto [two, e2] = run(2);
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_TRUE(one.ux == two.ux && one.uy == two.uy && one.vx == two.vx && one.vy == two.vy);
  EXPECT_EQ(e1.elastic, e2.elastic);
  EXPECT_EQ(e1.damping_dissipated, e2.damping_dissipated);
}

TEST(Diagnosis, ExplodingStepNamesBodyNodeAndStep) {
  Model model = scenes::single_disc(scenes::elastic_material(), 0.5, 0.1);
  set_rigid_velocity(model, 0, Vec2(0, 0), 1.0);
  for (std::size_t i = 0; i < model.node_count(); ++i)
    model.nodes.ux[i] = 0.01 * std::sin(1.7 * static_cast<double>(i));
  Stepper solver(model);
  try {
    for (int s = 0; s < 1000; ++s)
      solver.step(1.0);  // far above the stable step
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("body 'disc'"), std::string::npos) << what;
    EXPECT_NE(what.find("step"), std::string::npos) << what;
  }
}

TEST(Diagnosis, InvertedGrainAmongOthersIsNamedOnAnyIntegratorAndThreadCount) {
  // Each body's forces, velocities and positions are done together (node_update.cpp): an
  // inverted body must still stop the step with its name and Gauss point, not with what its
  // invalid forces do to the update of its nodes (an implicit solve on them), whatever the
  // order in which the threads meet the bodies.
  for (const IntegratorParams& integrator :
       {IntegratorParams::explicit_integrator(), IntegratorParams::imex()})
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      Model model;
      const MaterialId m =
          model.add_material(scenes::elastic_material(MaterialLaw::neo_hookean, 0.05));
      for (int k = 0; k < 6; ++k)
        scenes::add_disc(model, m, Vec2(1.2 * k, 0.0), 0.5, 0.1, "g" + std::to_string(k));
      Mat2 inverted = Mat2::Identity();
      inverted(0, 0) = -1.0;
      set_affine_deformation(model, 3, inverted);
      Stepper solver(model, nullptr, integrator);
      try {
        solver.step(1e-4);
        FAIL() << "no error";
      } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("body 'g3': invalid deformation at Gauss point"), std::string::npos)
            << what;
        EXPECT_NE(what.find("at step 0"), std::string::npos) << what;
      }
    }
  omp_set_num_threads(omp_get_num_procs());
}

TEST(Profile, TheForceAndVelocityLoopIsBookedToBothPhases) {
  // The internal forces and the velocities share one loop over bodies (node_update.cpp), its
  // time split by what the threads measured in each: both phases get a share, and the phases
  // add up to the steps' time.
  Model model;
  const MaterialId m = model.add_material(scenes::elastic_material(MaterialLaw::neo_hookean, 0.05));
  for (int k = 0; k < 4; ++k)
    scenes::add_disc(model, m, Vec2(1.2 * k, 0.0), 0.5, 0.1, "g" + std::to_string(k));
  for (const IntegratorParams& integrator :
       {IntegratorParams::explicit_integrator(), IntegratorParams::imex()}) {
    Stepper solver(model, nullptr, integrator);
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < 20; ++s)
      solver.step(1e-4);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const StepProfile& p = solver.profile();
    EXPECT_GT(p[StepPhase::internal_forces], 0.0);
    EXPECT_GT(p[StepPhase::velocities], 0.0);
    EXPECT_LE(p.total(), elapsed);
    EXPECT_EQ(p.steps, 20);
  }
}

}  // namespace
}  // namespace sg
