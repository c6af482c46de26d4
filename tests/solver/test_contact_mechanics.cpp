// Contact mechanics through the whole step (contact system + rigid bodies + solver):
// Coulomb threshold and friction work, cohesive pull-off and shear strength, periodicity,
// action-reaction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scenes/contact_scenes.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"

namespace sg {
namespace {

struct BlockOnPlane {
  Model model;
  BodyId plane = 0, block = 0;
};

// A 1 x 0.5 rigid block resting on a 4 x 1 rigid plane, both with contour spacing h, the block
// pressed in by `penetration` (its y held fixed: the normal force is then constant). The block
// is offset by h/2 so that no plane node sits exactly under its corners: a node inside the
// block next to its side projects onto the side (closest point) and snags it with a normal
// force p_n l ~ N h / (2 L): a node-to-segment edge effect of order h / L, kept at ~1% of N
// here by h = 0.01.
BlockOnPlane block_on_plane(double h, double penetration) {
  BlockOnPlane s;
  const MaterialId m = s.model.add_material(scenes::rigid_material());
  s.plane = s.model.add_rigid_body("plane", make_rectangle(Vec2(-2, -1), Vec2(2, 0), h), m);
  s.block = s.model.add_rigid_body(
      "block",
      make_rectangle(Vec2(-0.5 + 0.5 * h, -penetration), Vec2(0.5 + 0.5 * h, 0.5 - penetration), h),
      m);
  scenes::fix_rigid(s.model, s.plane);
  RigidDrive& d = scenes::drive_of(s.model, s.block);
  d.mode[1] = DriveMode::velocity;
  d.velocity[1] = PiecewiseLinear::constant(0.0);
  d.mode[2] = DriveMode::velocity;
  d.velocity[2] = PiecewiseLinear::constant(0.0);
  return s;
}

ContactLawParams coulomb(double mu) {
  ContactLawParams law;
  law.kind = ContactLawKind::coulomb;
  law.normal_stiffness = 1e4;
  law.tangential_stiffness = 1e4;
  law.friction = mu;
  return law;
}

TEST(Coulomb, BlockSlidesWhenTheTangentialForceExceedsMuN) {
  const double mu = 0.4, h = 0.01;
  auto run = [&](double force_ratio, double& slide, double& normal, double& dissipated,
                 double& friction_work) {
    BlockOnPlane s = block_on_plane(h, 1e-3);
    ContactSettings settings;
    settings.cutoff = 0.5 * h;
    ContactSystem contacts(s.model, scenes::single_law(s.model, coulomb(mu)), settings);
    Stepper solver(s.model, &contacts);
    const double dt = estimate_stable_time_step(s.model, 0.5, 1e4).dt;
    // Normal force first (one step), then a horizontal force ratio * mu * N on the block.
    solver.step(dt);
    normal = -s.model.rigid.fy[0];  // the plane receives the block's push downwards
    RigidDrive& d = scenes::drive_of(s.model, s.block);
    d.mode[0] = DriveMode::force;
    const double x0 = s.model.rigid.x[1];
    friction_work = 0.0;
    // The force is ramped up over 3000 steps (quasi-static: the block, with no damping, would
    // otherwise overshoot its static deflection by a factor 2), then held for up to 3000 steps,
    // or until the block has slid 0.5 (it stays on the plane).
    for (int k = 0; k < 6000 && s.model.rigid.x[1] - x0 < 0.5; ++k) {
      d.force[0] = force_ratio * mu * normal * std::min(1.0, k / 3000.0);
      const double x_before = s.model.rigid.x[1];
      solver.step(dt);
      // The friction force on the block is what it receives in x from the plane.
      friction_work += -s.model.rigid.fx[1] * (s.model.rigid.x[1] - x_before);
    }
    slide = s.model.rigid.x[1] - x0;
    dissipated = solver.state().energy.contact_dissipated;
  };
  double slide, normal, dissipated, work;
  run(0.98, slide, normal, dissipated, work);
  EXPECT_GT(normal, 0.0);
  // Below the threshold: only the elastic tangential deflection, F / (2 k_t l) ~ 4e-4.
  EXPECT_LT(std::abs(slide), 1e-3) << "slid under 0.98 mu N";
  run(1.02, slide, normal, dissipated, work);
  EXPECT_GT(slide, 1e-2) << "did not slide under 1.02 mu N";
  // Energy dissipated by the contacts = work of the friction force (to the elastic energy
  // stored in the tangential springs, ~ (mu N)^2 / (2 k_t l) ~ 1e-6).
  std::printf("friction: N = %.5g, slide = %.4g, dissipated = %.6g, friction work = %.6g\n", normal,
              slide, dissipated, work);
  EXPECT_NEAR(dissipated, work, 0.01 * work);
  EXPECT_NEAR(dissipated, mu * normal * slide, 0.02 * mu * normal * slide);
}

ContactLawParams cohesive(double strength) {
  ContactLawParams law;
  law.kind = ContactLawKind::cohesive;
  law.normal_stiffness = 1e4;
  law.tangential_stiffness = 1e4;
  law.adhesion = strength;
  law.shear_strength = strength;
  return law;
}

// Two 1 x 0.5 rigid blocks bonded face to face; the upper one is pulled at `velocity`.
// Returns the largest force the lower one receives along `direction` (0 = x, 1 = y).
double peak_bond_force(int direction, double h, double strength) {
  Model model;
  const MaterialId m = model.add_material(scenes::rigid_material());
  const BodyId lower =
      model.add_rigid_body("lower", make_rectangle(Vec2(-0.5, -0.5), Vec2(0.5, 0), h), m);
  const BodyId upper =
      model.add_rigid_body("upper", make_rectangle(Vec2(-0.5, 0), Vec2(0.5, 0.5), h), m);
  scenes::fix_rigid(model, lower);
  scenes::fix_rigid(model, upper);
  // Slow enough that the gap grows by 1e-6 per step: 1% of the breaking gap sigma_c / (2 k_n).
  scenes::drive_of(model, upper).velocity[direction] = PiecewiseLinear::constant(0.001);
  ContactSettings settings;
  settings.cutoff = 0.5 * h;
  ContactSystem contacts(model, scenes::single_law(model, cohesive(strength)), settings);
  Stepper solver(model, &contacts);
  const double dt = 1e-3;
  double peak = 0.0;
  for (int k = 0; k < 2000; ++k) {
    solver.step(dt);
    const double f = direction == 0 ? model.rigid.fx[0] : model.rigid.fy[0];
    peak = std::max(peak, std::abs(f));
  }
  EXPECT_GT(solver.state().energy.contact_dissipated, 0.0);
  return peak;
}

TEST(Cohesion, BondedFacesSeparateAtSigmaTimesLength) {
  const double c = 2.0, length = 1.0;
  const double pull = peak_bond_force(1, 0.02, c);
  std::printf("pull-off %.5g vs sigma_c l = %.5g\n", pull, c * length);
  EXPECT_NEAR(pull, c * length, 0.05 * c * length);
}

TEST(Cohesion, BondedFacesSlideAtTauTimesLength) {
  const double c = 2.0, length = 1.0;
  const double shear = peak_bond_force(0, 0.02, c);
  std::printf("shear %.5g vs tau_c l = %.5g\n", shear, c * length);
  EXPECT_NEAR(shear, c * length, 0.05 * c * length);
}

TEST(Periodicity, ContactAcrossTheSeamGivesTheSameForcesAsAwayFromIt) {
  auto forces = [](double offset) {
    Model model;
    model.periodic_x = true;
    model.x_min = 0.0;
    model.x_max = 10.0;
    const MaterialId m = model.add_material(scenes::rigid_material());
    // A square straddling x = offset and a square below it, slightly interpenetrating.
    const BodyId a = model.add_rigid_body(
        "a", make_rectangle(Vec2(offset - 0.5, 0), Vec2(offset + 0.5, 1), 0.1), m);
    const BodyId b = model.add_rigid_body(
        "b", make_rectangle(Vec2(offset - 0.3, -1.0 + 0.01), Vec2(offset + 0.7, 0.01), 0.1), m);
    scenes::fix_rigid(model, a);
    scenes::fix_rigid(model, b);
    ContactSettings settings;
    settings.cutoff = 0.05;
    ContactSystem contacts(model, scenes::single_law(model, coulomb(0.3)), settings);
    Stepper solver(model, &contacts);
    solver.step(1e-4);
    return std::vector<double>{model.rigid.fx[0], model.rigid.fy[0], model.rigid.torque[0],
                               model.rigid.fx[1], model.rigid.fy[1], model.rigid.torque[1]};
  };
  const std::vector<double> away = forces(5.0), seam = forces(0.0), seam_end = forces(9.9);
  ASSERT_GT(std::abs(away[1]), 0.0);
  for (std::size_t i = 0; i < away.size(); ++i) {
    EXPECT_NEAR(seam[i], away[i], 1e-9 * std::abs(away[1])) << i;
    EXPECT_NEAR(seam_end[i], away[i], 1e-9 * std::abs(away[1])) << i;
  }
  // Action and reaction.
  EXPECT_NEAR(away[0] + away[3], 0.0, 1e-12 * std::abs(away[1]));
  EXPECT_NEAR(away[1] + away[4], 0.0, 1e-12 * std::abs(away[1]));
}

// A first body (rigid periodic strip) that has drifted so that its closing segment (last
// point -> first point shifted by one period) lies at the seam: a block resting there must
// feel what it feels in the middle of the strip. A node above the closing segment has
// candidates at both ends of the strip (the closing segment near x_min, segment 0 near
// x_max); each needs its own periodic image. With one image per (node, body) the node was
// projected onto the far end's corner and reported a false penetration of ~0.07 (a grain of
// the shear cell was shot out of the layer and the energy balance lost 3% of the work).
TEST(Periodicity, BlockOnAStripsClosingSegmentFeelsWhatItFeelsElsewhere) {
  auto forces = [](double block_left) {
    Model model;
    model.periodic_x = true;
    model.x_min = 0.0;
    model.x_max = 10.0;
    const MaterialId m = model.add_material(scenes::rigid_material());
    // Flat surface y = 0 running right to left (material below), points at k h - 0.53.
    const double h = 0.1, drift = -0.53;
    Polygon surface;
    for (int k = 99; k >= 0; --k)
      surface.emplace_back(k * h + drift, 0.0);
    const BodyId strip = model.add_rigid_strip("strip", surface, m, -10.0, 1.0, 1.0);
    const BodyId block = model.add_rigid_body(
        "block", make_rectangle(Vec2(block_left, -0.001), Vec2(block_left + 1.0, 0.5), h), m);
    scenes::fix_rigid(model, strip);
    scenes::fix_rigid(model, block);
    ContactSettings settings;
    settings.cutoff = 0.05;
    ContactSystem contacts(model, scenes::single_law(model, coulomb(0.3)), settings);
    Stepper solver(model, &contacts);
    solver.step(1e-4);
    const auto r = static_cast<std::size_t>(model.body(block).rigid_index);
    double deepest = 0.0;
    for (const ContactRecord& c : contacts.records())
      deepest = std::min(deepest, c.gap);
    return std::vector<double>{model.rigid.fx[r], model.rigid.fy[r], deepest};
  };
  // The two placements differ by 60 h: the same block-to-strip alignment.
  const std::vector<double> seam = forces(-1.005), away = forces(4.995);
  ASSERT_GT(away[1], 0.0);
  EXPECT_NEAR(seam[0], away[0], 1e-9 * away[1]);
  EXPECT_NEAR(seam[1], away[1], 1e-9 * away[1]);
  EXPECT_NEAR(seam[2], -0.001, 1e-9);  // no contact deeper than the real penetration
}

// A position that has become non-finite (here a rigid body's, set by hand) stops the step with
// the body, the contour point and the step named.
TEST(BadInput, NonFinitePositionNamesBodyPointAndStep) {
  const double h = 0.01;
  BlockOnPlane s = block_on_plane(h, 1e-3);
  ContactSettings settings;
  settings.cutoff = 0.5 * h;
  ContactSystem contacts(s.model, scenes::single_law(s.model, coulomb(0.3)), settings);
  Stepper solver(s.model, &contacts);
  const double dt = estimate_stable_time_step(s.model, 0.5, 1e4).dt;
  solver.step(dt);
  solver.step(dt);
  s.model.rigid.y[1] = std::nan("");
  try {
    solver.step(dt);
    FAIL() << "a NaN position was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    for (const char* part : {"body 'block', contour point 0", "is not finite", "at step 2"})
      EXPECT_NE(what.find(part), std::string::npos) << "missing '" << part << "' in: " << what;
  }
}

TEST(BadInput, MaterialPairWithoutLawIsRefused) {
  Model model;
  model.add_material(scenes::rigid_material("steel"));
  model.add_material(scenes::rigid_material("glass"));
  model.add_rigid_body("a", make_rectangle(Vec2(0, 0), Vec2(1, 1), 0.2), 0);
  model.add_rigid_body("b", make_rectangle(Vec2(0, 2), Vec2(1, 3), 0.2), 1);
  MaterialPairTable table({"steel", "glass"});
  table.set(0, 0, coulomb(0.3));
  table.set(1, 1, coulomb(0.3));
  ContactSettings settings;
  settings.cutoff = 0.05;
  try {
    ContactSystem contacts(model, table, settings);
    FAIL() << "missing pair accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("glass"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sg
