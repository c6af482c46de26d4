// Changes of the time step in the explicit solver (issue #4 "Step control";
// solver/stepper.h): the variable-step central difference and the energy ledger's
// pairing of each interval with its own step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "model/internal_forces.h"
#include "model/kinematics.h"
#include "scenes/contact_scenes.h"
#include "scenes/free_grains.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"

namespace sg {
namespace {

// A scene: a model, its contacts (may be null) and the stable step at `fraction`.
struct Scene {
  Model model;
  std::unique_ptr<ContactSystem> contacts;
  double stable = 0.0;  // estimated critical step x 0.3
};

// A free disc (radius 0.5, spacing 0.07) released from a uniaxial stretch.
std::unique_ptr<Scene> stretched_grain(MaterialLaw law, double damping, double strain = 0.05) {
  auto s = std::make_unique<Scene>();
  s->model = scenes::single_disc(scenes::elastic_material(law, damping), 0.5, 0.07);
  Mat2 stretch = Mat2::Identity();
  stretch(0, 0) = 1.0 + strain;
  set_affine_deformation(s->model, 0, stretch);
  s->stable = estimate_stable_time_step(s->model, 0.3).dt;
  return s;
}

// The strip of test_strip_servo.cpp: a damped rubber strip (period 10) whose back face is
// velocity-driven along x (ramped to 0.5) and servo-loaded along y (F ramped to 5, c = 20)
// under gravity: node drives of both kinds, a node carrier, bulk damping.
std::unique_ptr<Scene> servo_strip() {
  auto s = std::make_unique<Scene>();
  Model& model = s->model;
  model.gravity = Vec2(0.0, -1.0);
  const BodyId strip = scenes::add_flat_rubber_strip(model);
  NodeDrive& d = model.node_drives[static_cast<std::size_t>(model.body(strip).node_drive)];
  d.mode[0] = DriveMode::velocity;
  d.velocity[0] = PiecewiseLinear{{0.0, 0.2}, {0.0, 0.5}};
  d.mode[1] = DriveMode::load;
  d.load[1] = PiecewiseLinear{{0.0, 0.3}, {0.0, 5.0}};
  d.load_damping[1] = 20.0;
  s->stable = estimate_stable_time_step(model, 0.3).dt;
  return s;
}

// Rigid bodies and contacts: a damped elastic disc between a fixed rigid disc below and a
// rigid disc above that is servo-loaded down (F ramped to -2, c = 5) and pushed along x by a
// constant force, free to turn, under gravity; frictionless contacts.
std::unique_ptr<Scene> loaded_rigid_disc() {
  auto s = std::make_unique<Scene>();
  Model& model = s->model;
  model.gravity = Vec2(0.0, -1.0);
  const MaterialId m =
      model.add_material(scenes::elastic_material(MaterialLaw::neo_hookean, 0.005));
  const double h = 0.07;
  scenes::add_disc(model, m, Vec2(0, 0), 0.5, h, "soft");
  const MaterialId w = model.add_material(scenes::rigid_material());
  const BodyId floor = model.add_rigid_body("floor", make_disc(Vec2(0, -1.02), 0.5, h), w);
  scenes::fix_rigid(model, floor);
  const BodyId top = model.add_rigid_body("top", make_disc(Vec2(0.05, 1.02), 0.5, h), w);
  RigidDrive& d = scenes::drive_of(model, top);
  d.mode[0] = DriveMode::force;
  d.force[0] = 0.05;
  d.mode[1] = DriveMode::load;
  d.load[1] = PiecewiseLinear{{0.0, 0.3}, {0.0, -2.0}};
  d.load_damping[1] = 5.0;
  ContactLawParams law;
  law.kind = ContactLawKind::frictionless;
  law.normal_stiffness = 200.0;
  ContactSettings settings;
  settings.cutoff = 0.5 * h;
  s->contacts = std::make_unique<ContactSystem>(model, scenes::single_law(model, law), settings);
  s->stable = estimate_stable_time_step(model, 0.3, s->contacts->max_stiffness()).dt;
  return s;
}

struct LedgerRun {
  double worst_residual = 0.0;  // largest |residual| / energy scale over the run
  double final_residual = 0.0;  // residual / energy scale at the end
  double step_change = 0.0;     // EnergyLedger::step_change / energy scale at the end
  double time = 0.0;
};

// Steps `scene` with dt_k = pattern[k mod size] x stable for `steps` steps.
LedgerRun run_ledger(Scene& scene, const std::vector<double>& pattern, long steps) {
  Stepper solver(scene.model, scene.contacts.get());
  LedgerRun r;
  double scale = 0.0;
  for (long k = 0; k < steps; ++k) {
    solver.step(pattern[static_cast<std::size_t>(k) % pattern.size()] * scene.stable);
    const EnergyLedger& e = solver.state().energy;
    scale = std::max(
        scale, std::abs(e.kinetic) + e.elastic + e.contact_elastic + std::abs(e.external_work));
    r.worst_residual = std::max(r.worst_residual, std::abs(e.residual()));
  }
  r.worst_residual /= scale;
  r.final_residual = solver.state().energy.residual() / scale;
  r.step_change = solver.state().energy.step_change / scale;
  r.time = solver.state().time;
  return r;
}

const std::vector<double> kChanging = {1.0, 0.5, 0.5, 1.3, 0.7};

// Steps a scene at a constant step dt, at a constant 1.3 dt, and with the steps changing
// every step through dt, dt/2, dt/2, 1.3 dt, 0.7 dt (dt = 0.3 of the critical step: periodic
// changes of the step pump energy into the modes whose period is near the pattern's, and
// at 0.38-0.39 of the critical step this pattern's resonance reaches the highest mode, for
// the update before issue #4's fix and after it alike, measured on one oscillator).
// The residual with changing steps stays at the level of the constant-step runs (within 3x:
// measured 2.2x on the rigid disc in contact, 1.0x elsewhere; the first-order update before
// the fix gave 10x and more, up to 7e5x); the energy
// booked as step change is 0 for a constant step.
void expect_ledger_closes_under_changing_steps(const char* name,
                                               const std::function<std::unique_ptr<Scene>()>& make,
                                               long steps) {
  const LedgerRun constant = run_ledger(*make(), {1.0}, steps);
  const LedgerRun large = run_ledger(*make(), {1.3}, steps);
  const LedgerRun changing = run_ledger(*make(), kChanging, steps);
  std::printf(
      "%s: worst |residual| / energy scale: constant dt %.3e, constant 1.3 dt %.3e, "
      "changing %.3e (final %.3e, %.3e, %.3e); step change booked %.3e\n",
      name, constant.worst_residual, large.worst_residual, changing.worst_residual,
      constant.final_residual, large.final_residual, changing.final_residual, changing.step_change);
  EXPECT_LT(changing.worst_residual, 3.0 * std::max(constant.worst_residual, large.worst_residual))
      << name;
  EXPECT_EQ(constant.step_change, 0.0) << name;
  EXPECT_EQ(large.step_change, 0.0) << name;
  EXPECT_NE(changing.step_change, 0.0) << name;
}

// Measured worst |residual| / energy scale over the run, constant dt / constant 1.3 dt /
// changing steps, after the fix (before it, with v_n+1/2 = v_n-1/2 + dt_+ a_n and each
// interval closed with the next step, in brackets):
//   grain at 1e-6 strain  5.3e-8 / 8.6e-8 / 5.1e-8  (3.7e-2: the first-order term)
//   grain at 5% strain    3.4e-3 / 5.7e-3 / 3.3e-3  (3.4e-2)
//   damped grain          9.6e-5 / 1.7e-4 / 9.3e-5  (1.1e-2)
//   servo strip           3.0e-11 / 4.9e-11 / 2.8e-11 (2.8e-4)
//   loaded rigid disc     2.3e-5 / 1.5e-5 / 3.1e-5  (1.2e-4)
// The step change booked oscillates with the pattern and does not drift (grain at 1e-6
// strain: between -2.4e-4 and 3.9e-3 of the energy, sampled every 500 of 20000 steps).
TEST(VariableStep, LedgerOfAnUndampedGrainClosesUnderChangingSteps) {
  // Saint-Venant-Kirchhoff at 1e-6 strain: a linear system up to the 1e-6 geometric
  // non-linearity, whose ledger closes to 5e-8 for a constant step.
  expect_ledger_closes_under_changing_steps(
      "grain at 1e-6 strain",
      [] { return stretched_grain(MaterialLaw::saint_venant_kirchhoff, 0.0, 1e-6); }, 2000);
  expect_ledger_closes_under_changing_steps(
      "grain at 5% strain",
      [] { return stretched_grain(MaterialLaw::saint_venant_kirchhoff, 0.0); }, 2000);
}

TEST(VariableStep, LedgerOfADampedGrainClosesUnderChangingSteps) {
  expect_ledger_closes_under_changing_steps(
      "damped grain", [] { return stretched_grain(MaterialLaw::neo_hookean, 0.01); }, 2000);
}

TEST(VariableStep, LedgerOfAServoLoadedStripClosesUnderChangingSteps) {
  expect_ledger_closes_under_changing_steps("servo strip", servo_strip, 2000);
}

TEST(VariableStep, LedgerOfALoadedRigidDiscClosesUnderChangingSteps) {
  expect_ledger_closes_under_changing_steps("loaded rigid disc", loaded_rigid_disc, 3000);
}

// Accuracy: a free disc released from rest in a 5% stretch, its displacements at a fixed
// time T against a reference run with a constant step 16 times smaller than the finest.
// The step changes twice at fixed times: dt over [0, 3T/8), dt/2 over [3T/8, 11T/16),
// 1.25 dt to T (a halving, then a growth, as the step controller makes them).
// The solver takes the initial velocities as v_-1/2 (stepper.h); a start from rest at
// t = 0 is v_-1/2 = -dt_0/2 a_0 + O(dt^3) (v is odd in t), which `consistent` sets.
struct Segment {
  double fraction;  // of the base step
  long steps;       // per unit of `refinement`
};

std::vector<double> displacements_at(const std::vector<Segment>& schedule, double dt,
                                     long refinement, bool consistent) {
  std::unique_ptr<Scene> s = stretched_grain(MaterialLaw::neo_hookean, 0.0);
  NodeState& n = s->model.nodes;
  if (consistent) {
    std::fill(n.fx.begin(), n.fx.end(), 0.0);
    std::fill(n.fy.begin(), n.fy.end(), 0.0);
    add_internal_forces(s->model);
    const double first = schedule.front().fraction * dt;
    for (std::size_t i = 0; i < n.size(); ++i) {
      n.vx[i] = -0.5 * first * n.inverse_mass[i] * n.fx[i];
      n.vy[i] = -0.5 * first * n.inverse_mass[i] * n.fy[i];
    }
  }
  Stepper solver(s->model);
  for (const Segment& segment : schedule)
    for (long k = 0; k < segment.steps * refinement; ++k)
      solver.step(segment.fraction * dt);
  std::vector<double> u;
  for (std::size_t i = 0; i < n.size(); ++i) {
    u.push_back(n.ux[i]);
    u.push_back(n.uy[i]);
  }
  return u;
}

double rms_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

// Measured rms errors (consistent start) for dt = 0.2, 0.1, 0.05, 0.025 of the critical step:
// changing steps 7.6e-5, 2.0e-5, 5.1e-6, 1.29e-6 (orders 1.91, 1.98, 1.99), constant step
// 8.0e-5 ... 1.37e-6 (1.90, 1.97, 1.99). Before the fix (v_n+1/2 = v_n-1/2 + dt_+ a_n, each
// change of the step a velocity error 1/2 (dt_+ - dt_-) a_n): 1.1e-4, 4.7e-5, 2.2e-5,
// 1.08e-5, orders 1.25, 1.09, 1.02.
TEST(VariableStep, ChangingStepsConvergeAtSecondOrder) {
  // Coarsest base step 0.2 of the critical step, T = 128 of it (about 2.3 periods of the
  // ovalling mode); segments of 48, 40 and 40 base steps.
  const double coarse = (0.2 / 0.3) * stretched_grain(MaterialLaw::neo_hookean, 0.0)->stable;
  const std::vector<Segment> changing = {{1.0, 48}, {0.5, 80}, {1.25, 32}};
  const std::vector<Segment> constant = {{1.0, 128}};
  for (const bool consistent : {true, false}) {
    const std::vector<double> reference = displacements_at(constant, coarse / 128, 128, consistent);
    double previous = 0.0, previous_constant = 0.0;
    for (int k = 0; k < 4; ++k) {
      const long refinement = 1L << k;
      const double dt = coarse / static_cast<double>(refinement);
      const double error =
          rms_difference(displacements_at(changing, dt, refinement, consistent), reference);
      const double error_constant =
          rms_difference(displacements_at(constant, dt, refinement, consistent), reference);
      std::printf(
          "%s start, dt = %.4g: changing steps error %.3e (order %.2f), constant dt %.3e "
          "(order %.2f)\n",
          consistent ? "consistent" : "rest", dt, error, k > 0 ? std::log2(previous / error) : 0.0,
          error_constant, k > 0 ? std::log2(previous_constant / error_constant) : 0.0);
      if (k >= 2) {
        const double order = std::log2(previous / error);
        if (consistent) {
          // Second order, with an error no larger than the constant step's (measured
          // 1.98, 1.99 and 0.94 of it).
          EXPECT_GT(order, 1.9);
          EXPECT_LT(order, 2.1);
          EXPECT_LT(error, 1.1 * error_constant);
        } else {
          // A start from rest taken as v_-1/2 = 0 is the motion shifted by dt_0/2 in time:
          // first order, with or without step changes (measured 1.12, 1.07).
          EXPECT_GT(order, 0.9);
          EXPECT_LT(order, 1.3);
        }
      }
      previous = error;
      previous_constant = error_constant;
    }
  }
}

}  // namespace
}  // namespace sg
