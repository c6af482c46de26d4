// A deformable strip whose back face is servo-loaded (NodeDrive with DriveMode::load on y: the
// back-face nodes move as one carrier under F(t) - c v, the pressure loading of a deformable
// top first body) while it is velocity-driven in x: the carrier's equation, the terminal
// velocity, and the energy ledger with the load's work and the servo dissipation booked apart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "model/kinematics.h"
#include "scenes/free_grains.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"

namespace sg {
namespace {

// The shared flat rubber strip (tests/scenes/free_grains.h): period 10, h = 0.1, mass 10.
BodyId add_strip(Model& model) {
  return scenes::add_flat_rubber_strip(model);
}

// Under gravity (g = -1, weight -10) the strip hangs from its back face, which is pulled up by
// F = 5 (ramped over 1) against the servo force -c v with c = 20, and slides along x at a
// velocity ramped to 0.5. No contacts: the whole strip ends translating at the terminal
// velocity v = (F + M g) / c = -0.25, after about 14 relaxation times M / c = 0.5.
TEST(StripServo, LoadedBackFaceMovesAsOneReachesTerminalVelocityAndTheLedgerCloses) {
  Model model;
  model.gravity = Vec2(0.0, -1.0);
  const BodyId strip = add_strip(model);
  const Body& body = model.body(strip);
  NodeDrive& d = model.node_drives[static_cast<std::size_t>(body.node_drive)];
  const double load = 5.0, c = 20.0;
  d.mode[0] = DriveMode::velocity;
  d.velocity[0] = PiecewiseLinear{{0.0, 0.2}, {0.0, 0.5}};
  d.mode[1] = DriveMode::load;
  d.load[1] = PiecewiseLinear{{0.0, 1.0}, {0.0, load}};
  d.load_damping[1] = c;
  Stepper solver(model);
  const double dt = estimate_stable_time_step(model, 0.5).dt;
  const double mass = total_mass(model);
  ASSERT_NEAR(mass, 10.0, 1e-9);
  const double weight = -mass;  // M g_y
  double carrier_mass = 0.0;
  for (int i : d.nodes)
    carrier_mass += model.nodes.mass[static_cast<std::size_t>(i)];
  ASSERT_GT(carrier_mass, 0.0);
  ASSERT_LT(carrier_mass, 0.1 * mass);  // the back face only

  Vec2 impulse(0, 0);  // of the reaction and of gravity: the change of momentum
  const int steps = static_cast<int>(std::ceil(8.0 / dt));
  for (int k = 0; k < steps; ++k) {
    const double t = solver.state().time;
    solver.step(dt);
    impulse += dt * (d.reaction + Vec2(0.0, weight));
    // One vertical degree of freedom: every back-face node has the carrier's velocity, and the
    // drive's reaction on them is the carrier's external force F(t_n) - c v_n+1/2.
    const double v = model.nodes.vy[static_cast<std::size_t>(d.nodes.front())];
    for (int i : d.nodes) {
      ASSERT_EQ(model.nodes.vy[static_cast<std::size_t>(i)], v);
      ASSERT_EQ(model.nodes.vx[static_cast<std::size_t>(i)], d.velocity[0](t + 0.5 * dt));
    }
    ASSERT_NEAR(d.reaction.y(), d.load[1](t) - c * v, 1e-9 * load) << "step " << k;
  }
  // Internal forces sum to zero: the impulse is the strip's momentum, up to round-off.
  const Vec2 momentum = linear_momentum(model);
  EXPECT_NEAR(impulse.x(), momentum.x(), 1e-10 * mass);
  EXPECT_NEAR(impulse.y(), momentum.y(), 1e-10 * mass);
  // Terminal velocity: the strip's mean and the carrier's (exp(-14) ~ 1e-6 of the transient
  // left, plus the damped ringing of the strip's own modes).
  const double terminal = (load + weight) / c;
  EXPECT_NEAR(momentum.y() / mass, terminal, 1e-4 * std::abs(terminal));
  EXPECT_NEAR(model.nodes.vy[static_cast<std::size_t>(d.nodes.front())], terminal,
              1e-4 * std::abs(terminal));
  // Along x the strip follows its back face (the x ramp rang its shear mode, which the light
  // damping alpha = 0.01 has not yet stopped: measured lag 0.0012).
  EXPECT_NEAR(momentum.x() / mass, 0.5, 0.01);

  // The ledger: gravity's work, the load's and the x drive's reaction's are external, the
  // servo's viscous work is servo dissipation (the carrier's reaction is not booked again).
  // At the terminal state the servo dissipates c v^2 per unit time, 1.25 here over ~7 units.
  const EnergyLedger& e = solver.state().energy;
  EXPECT_GT(e.servo_dissipated, 0.8 * c * terminal * terminal * 7.0);
  EXPECT_LT(e.servo_dissipated, 1.2 * c * terminal * terminal * 8.0);
  // As in DeformableStrip.DrivenBackFaceBooksItsWorkAndTheLedgerCloses: what remains is the
  // scheme's O(dt^2) mismatch on a nonlinear damped body.
  EXPECT_LT(std::abs(e.residual()), 1e-6 * e.external_work)
      << "residual " << e.residual() << " of external work " << e.external_work;
  std::printf("servo dissipated %.6g, external work %.6g, residual %.3g\n", e.servo_dissipated,
              e.external_work, e.residual());
}

// A node drive cannot take a constant force: refused with the body's name.
TEST(StripServo, ForceModeOnNodesIsRefused) {
  Model model;
  const BodyId strip = add_strip(model);
  model.node_drives[static_cast<std::size_t>(model.body(strip).node_drive)].mode[1] =
      DriveMode::force;
  Stepper solver(model);
  try {
    solver.step(1e-4);
    FAIL() << "force mode accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'strip'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sg
