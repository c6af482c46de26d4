// The viscous force the IMEX solve carries from one step to the next (reference_stiffness,
// solver/implicit_viscosity.h "The viscous force carried by the solve"): -C v_n+1/2 =
// f_v(v_n-1/2) + 2 (F* - F_n). Checked against the kernel's force at every step, and for when
// the kernel must compute it again (velocities changed from outside, a new step, its age).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/kinematics.h"
#include "scenes/free_grains.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"

namespace sg {
namespace {

// A reference-stiffness disc (alpha 0.05, nu 0.45), stretched and spinning: every mode moves.
Model stretched_spinning_disc() {
  MaterialDef m = scenes::elastic_material(MaterialLaw::neo_hookean, 0.05, 0.45, 10.0);
  m.damping_model = DampingModel::reference_stiffness;
  Model model = scenes::single_disc(m, 1.0, 0.2);
  Mat2 stretch;
  stretch << 1.02, 0.0, 0.0, 0.99;
  set_affine_deformation(model, 0, stretch);
  set_rigid_velocity(model, 0, Vec2(0.3, -0.1), 0.7);
  return model;
}

IntegratorParams imex(int dense_factor_limit) {
  IntegratorParams p = IntegratorParams::imex();
  p.imex_dense_factor_limit = dense_factor_limit;
  return p;
}

// Largest difference between the two models' node velocities, relative to the largest speed.
double velocity_difference(const Model& a, const Model& b) {
  double difference = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    difference = std::max({difference, std::abs(a.nodes.vx[i] - b.nodes.vx[i]),
                           std::abs(a.nodes.vy[i] - b.nodes.vy[i])});
    largest = std::max({largest, std::abs(a.nodes.vx[i]), std::abs(a.nodes.vy[i])});
  }
  return difference / largest;
}

bool same_velocities(const Model& a, const Model& b) {
  return a.nodes.vx == b.nodes.vx && a.nodes.vy == b.nodes.vy;
}

// 300 steps with the carried force against the same steps with the kernel's force at every
// step (the history dropped before each): the same motion to the solve's round-off. With the
// sparse double-precision factor that is round-off of double (measured 3.8e-14); with the
// single-precision dense factor the operator the solve applies differs from C by about 1e-7
// relative, and so does the carried force (measured 2.6e-6). A carried force without the
// factor 2 (f_v* instead of -C v_n+1/2) moves the velocities by 2.7e-3 relative here.
TEST(CarriedViscousForce, MovesTheBodyAsTheKernelsForceToTheSolvesRoundOff) {
  const struct {
    int dense_factor_limit;
    double tolerance;
  } cases[] = {{0, 1e-11}, {IntegratorParams::kDefaultDenseFactorLimit, 1e-5}};
  for (const auto& [limit, tolerance] : cases) {
    Model carried_model = stretched_spinning_disc(), kernel_model = stretched_spinning_disc();
    Stepper carried(carried_model, nullptr, imex(limit)),
        kernel(kernel_model, nullptr, imex(limit));
    const double dt = 0.8 * estimate_stable_time_step(carried_model, 1.0, 0.0, imex(limit)).dt;
    for (int s = 0; s < 300; ++s) {
      carried.step(dt);
      kernel.drop_implicit_history();
      kernel.step(dt);
    }
    const double difference = velocity_difference(carried_model, kernel_model);
    const ViscousSolveStatistics st = carried.viscous_statistics();
    std::printf(
        "dense factor limit %d: velocities differ by %.3g relative; %ld of %ld forces "
        "carried, %ld dense bodies\n",
        limit, difference, st.carried_forces, st.solves, st.dense_bodies);
    EXPECT_LT(difference, tolerance) << limit;
    EXPECT_EQ(st.dense_bodies, limit == 0 ? 0 : 1);
    // Carried but at the first step and at each age limit (every kCarriedSteps).
    EXPECT_EQ(st.carried_forces, 300 - 3);
    EXPECT_EQ(kernel.viscous_statistics().carried_forces, 0);
    // The damping dissipated (summed from the carried force's power) agrees too.
    const double carried_dissipated = carried.state().energy.damping_dissipated;
    EXPECT_GT(carried_dissipated, 0.0);
    EXPECT_NEAR(carried_dissipated, kernel.state().energy.damping_dissipated,
                tolerance * carried_dissipated);
  }
}

// Steps of two models that do the same thing, `a` carrying its viscous forces; before step
// `dropped`, b drops its history (its kernel computes the force); `change(step, model)` may
// change either model before a step, `dt(step)` the step.
template <class Change, class Dt>
void step_both(Model& a, Model& b, int steps, int dropped, Change&& change, Dt&& dt) {
  Stepper sa(a, nullptr, imex(0)), sb(b, nullptr, imex(0));
  for (int s = 0; s < steps; ++s) {
    change(s, a);
    change(s, b);
    if (s == dropped) sb.drop_implicit_history();
    sa.step(dt(s));
    sb.step(dt(s));
  }
}

// Whatever changes the velocities between two steps (a caller, a rejected step restored, a
// checkpoint read) makes the next step compute the force with the kernel: the same bits as a
// stepper that dropped its history there.
TEST(CarriedViscousForce, AChangeOfVelocitiesFromOutsideIsComputedAgain) {
  Model a = stretched_spinning_disc(), b = stretched_spinning_disc();
  const double dt = 0.8 * estimate_stable_time_step(a, 1.0, 0.0, imex(0)).dt;
  const auto kick = [](int step, Model& m) {
    if (step != 20) return;
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      m.nodes.vx[i] *= 1.0 + 0.01 * std::sin(static_cast<double>(i));
  };
  step_both(a, b, 40, 20, kick, [dt](int) { return dt; });
  EXPECT_TRUE(same_velocities(a, b));
  // Which is a sharp test: without the kick, a drop at step 20 changes the bits (the carried
  // force is not the kernel's to the bit).
  Model c = stretched_spinning_disc(), d = stretched_spinning_disc();
  step_both(
      c, d, 40, 20, [](int, Model&) {}, [dt](int) { return dt; });
  EXPECT_FALSE(same_velocities(c, d));
}

// A new step size (a new factor: the carried force was exact for the old one's operator) and
// the age limit (kCarriedSteps solves) make the kernel compute the force again.
TEST(CarriedViscousForce, ANewStepAndTheAgeLimitComputeItAgain) {
  Model a = stretched_spinning_disc(), b = stretched_spinning_disc();
  const double dt = 0.8 * estimate_stable_time_step(a, 1.0, 0.0, imex(0)).dt;
  const auto nothing = [](int, Model&) {};
  step_both(a, b, 30, 15, nothing, [dt](int s) { return s < 15 ? dt : 0.9 * dt; });
  EXPECT_TRUE(same_velocities(a, b));
  Model c = stretched_spinning_disc(), d = stretched_spinning_disc();
  const int limit = ImplicitViscosity::kCarriedSteps;
  step_both(c, d, limit + 10, limit, nothing, [dt](int) { return dt; });
  EXPECT_TRUE(same_velocities(c, d));
  Model e = stretched_spinning_disc(), f = stretched_spinning_disc();
  step_both(e, f, limit + 10, limit - 1, nothing, [dt](int) { return dt; });
  EXPECT_FALSE(same_velocities(e, f)) << "a drop one step earlier changes the bits";
}

}  // namespace
}  // namespace sg
