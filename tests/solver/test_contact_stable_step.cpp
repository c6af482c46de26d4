// The stable step with contacts between deformable bodies (solver/stable_time_step.h) and a
// bonded interface that does not create energy (contact/contact_system.cpp, slip at vertices).
// Scene: two deformable blocks (1 x 0.5 each, h = 0.05, E = 10, nu = 0, undamped) bonded face
// to face by a cohesive law, each bonded to a rigid grip of the same width (corners coincide).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "model/internal_forces.h"
#include "scenes/contact_scenes.h"
#include "scenes/free_grains.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"

namespace sg {
namespace {

struct BondedBlocks {
  Model model;
  double kn = 0.0;
  BodyId bottom = -1, top = -1;
  MaterialPairTable laws{std::vector<std::string>{"soft", "grip"}};
  BondedBlocks() {
    MaterialDef soft_def = scenes::elastic_material(MaterialLaw::neo_hookean, 0.0, 0.0);
    soft_def.name = "soft";
    const MaterialId soft = model.add_material(soft_def);
    const MaterialId grip = model.add_material(scenes::rigid_material("grip"));
    const double h = 0.05;
    model.add_deformable_body("lower", make_rectangle(Vec2(0, -0.5), Vec2(1, 0), h), soft,
                              scenes::discretization(h));
    model.add_deformable_body("upper", make_rectangle(Vec2(0, 0), Vec2(1, 0.5), h), soft,
                              scenes::discretization(h));
    bottom = model.add_rigid_body("bottom", make_rectangle(Vec2(0, -0.7), Vec2(1, -0.5), h), grip);
    top = model.add_rigid_body("top", make_rectangle(Vec2(0, 0.5), Vec2(1, 0.7), h), grip);
    scenes::fix_rigid(model, bottom);
    scenes::fix_rigid(model, top);
    kn = 10.0 * soft_def.young / h;
    auto cohesive = [&](double strength) {
      ContactLawParams law;
      law.kind = ContactLawKind::cohesive;
      law.normal_stiffness = kn;
      law.tangential_stiffness = kn;
      law.adhesion = strength;
      law.shear_strength = strength;
      return law;
    };
    ContactLawParams frictionless;
    frictionless.normal_stiffness = kn;
    laws.set(soft, soft, cohesive(0.2));
    laws.set(soft, grip, cohesive(2.0));
    laws.set(grip, grip, frictionless);
  }
};

ContactSettings settings() {
  ContactSettings s;
  s.cutoff = 0.025;
  return s;
}

// Forces on the deformable parameters at the model's current displacements: internal
// (undamped) + contacts, evaluated by a copy of `contacts` so that its history is untouched.
void total_forces(Model& m, const ContactSystem& contacts, std::vector<double>& fx,
                  std::vector<double>& fy) {
  std::fill(m.nodes.fx.begin(), m.nodes.fx.end(), 0.0);
  std::fill(m.nodes.fy.begin(), m.nodes.fy.end(), 0.0);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const Body& body = m.bodies[b];
    if (body.kind != BodyKind::deformable) continue;
    const auto o = static_cast<std::size_t>(body.node_begin);
    add_body_internal_forces(m, static_cast<BodyId>(b), m.nodes.ux.data() + o,
                             m.nodes.uy.data() + o, m.nodes.vx.data() + o, m.nodes.vy.data() + o,
                             m.nodes.fx.data() + o, m.nodes.fy.data() + o, false);
  }
  ContactSystem copy = contacts;
  copy.add_contact_forces(m);
  fx = m.nodes.fx;
  fy = m.nodes.fy;
}

// Highest frequency of the assembled system (all deformable parameters; the grips are fixed):
// power iteration on M^-1/2 K M^-1/2, K x = -(f(u + eps M^-1/2 x) - f(u)) / eps. The bonded
// interface is linear (cohesive springs within their strength), so the difference is exact
// up to round-off for a small eps.
double assembled_max_frequency(Model& m, const ContactSystem& contacts) {
  const std::size_t n = m.nodes.size();
  const std::vector<double> ux0 = m.nodes.ux, uy0 = m.nodes.uy;
  std::vector<double> f0x, f0y, fx, fy, px(n), py(n);
  total_forces(m, contacts, f0x, f0y);
  for (std::size_t i = 0; i < n; ++i) {
    const double di = static_cast<double>(i);
    px[i] = std::sin(1.7 * di + 0.3);
    py[i] = std::cos(2.3 * di);
  }
  const double eps = 1e-7 * std::sqrt(m.nodes.mass[0]);
  double lambda = 0.0;
  for (int it = 0; it < 300; ++it) {
    double norm = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      norm += px[i] * px[i] + py[i] * py[i];
    norm = std::sqrt(norm);
    for (std::size_t i = 0; i < n; ++i) {
      px[i] /= norm;
      py[i] /= norm;
      const double r = std::sqrt(m.nodes.inverse_mass[i]);
      m.nodes.ux[i] = ux0[i] + eps * r * px[i];
      m.nodes.uy[i] = uy0[i] + eps * r * py[i];
    }
    total_forces(m, contacts, fx, fy);
    double rayleigh = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = std::sqrt(m.nodes.inverse_mass[i]) / eps;
      const double kx = -(fx[i] - f0x[i]) * r, ky = -(fy[i] - f0y[i]) * r;
      rayleigh += kx * px[i] + ky * py[i];
      px[i] = kx;
      py[i] = ky;
    }
    lambda = rayleigh;
  }
  m.nodes.ux = ux0;
  m.nodes.uy = uy0;
  return std::sqrt(lambda);
}

// The estimate must bound the real highest frequency once the bonds hold. Measured with the
// contact-consistent contour rows (meshfree/contour_rows.h): assembled omega = 569.4,
// estimated 624.8 (+9.7%); with point rows it was 724 vs 747. The estimate that took the partner
// body as immovable gave 510, i.e. a step 1.42 x the stable one: at 0.8 of it omega dt = 2.27 and
// the scheme created energy.
TEST(ContactStableStep, EstimateBoundsTheBondedInterfacesFrequency) {
  BondedBlocks s;
  ContactSystem contacts(s.model, s.laws, settings());
  const StableStep estimate = estimate_stable_time_step(s.model, 1.0, s.kn);
  Stepper solver(s.model, &contacts);
  for (int k = 0; k < 3; ++k)
    solver.step(0.1 * estimate.dt);  // bonds formed, nothing moved yet
  const double omega = assembled_max_frequency(s.model, contacts);
  std::printf(
      "bonded blocks: assembled omega_max %.4g, estimated %.4g (critical dt %.4g vs %.4g)\n", omega,
      estimate.omega_max, 2.0 / omega, estimate.dt);
  EXPECT_GE(estimate.omega_max, omega);
  // ... and not by a wide margin (the bound is reached by matched facing nodes).
  EXPECT_LT(estimate.omega_max, 1.15 * omega);
}

// The share of the limiting body's omega^2 the contacts carry (run.log, `softgrain info`):
// what is left of omega^2 without its own elastic frequency, and nothing without contacts.
TEST(ContactStableStep, ContactShareIsWhatTheContactsAddToOmegaSquared) {
  BondedBlocks s;
  const StableStep with = estimate_stable_time_step(s.model, 1.0, s.kn);
  ASSERT_EQ(s.model.body(with.limiting_body).kind, BodyKind::deformable);
  const double body_omega = estimate_max_frequency(s.model, with.limiting_body);
  std::printf("bonded blocks: omega_max %.4g, the body's own %.4g, contact share %.3f\n",
              with.omega_max, body_omega, with.contact_share);
  EXPECT_NEAR(with.contact_share, 1.0 - body_omega * body_omega / (with.omega_max * with.omega_max),
              1e-12);
  EXPECT_GT(with.contact_share, 0.1);
  EXPECT_LT(with.contact_share, 0.99);
  const StableStep without = estimate_stable_time_step(s.model, 1.0, 0.0);
  EXPECT_EQ(without.contact_share, 0.0);
  EXPECT_DOUBLE_EQ(without.omega_max, estimate_max_frequency(s.model, without.limiting_body));
  EXPECT_EQ(contact_share_note(with).rfind("contact penalties carry ", 0), 0u);
}

// Pulled slowly (top grip at 0.01 after a ramp), undamped, at 0.8 of the estimated step, up
// to t = 2.5 (load 0.15 = 0.74 sigma_c L: no bond reaches its strength). Nothing dissipates
// and the ledger closes. Measured: dissipated 0, residual -1.2e-6 against an external work
// of 1.1e-3 (first order in dt: -7e-7 at half the step). Before the vertex slip and the
// partner term in the step: 8.8e-4 "dissipated" by the grips' corner springs sliding at
// their threshold, residual -1e-3 (energy created), 4 interface bonds broken at 1/4 of the
// load.
TEST(ContactStableStep, BondedBlocksPulledSlowlyNeitherDissipateNorCreateEnergy) {
  BondedBlocks s;
  scenes::drive_of(s.model, s.top).velocity[1] = PiecewiseLinear{{0.0, 2.0}, {0.0, 0.01}};
  ContactSystem contacts(s.model, s.laws, settings());
  const double dt = estimate_stable_time_step(s.model, 0.8, s.kn).dt;
  Stepper solver(s.model, &contacts);
  std::size_t bonds = 0;
  while (solver.state().time < 2.5) {
    solver.step(dt);
    bonds = 0;
    for (const ContactRecord& r : contacts.records())
      if (r.active) ++bonds;
  }
  const EnergyLedger& e = solver.state().energy;
  const std::size_t r = static_cast<std::size_t>(s.model.body(s.bottom).rigid_index);
  std::printf(
      "pulled to t = %.3f: force %.4f, bonds %zu, dissipated %.3g, residual %.3g, "
      "external work %.3g\n",
      solver.state().time, s.model.rigid.fy[r], bonds, e.contact_dissipated, e.residual(),
      e.external_work);
  EXPECT_EQ(bonds, 42u + 84u);  // 2 x 21 interface nodes, 4 x 21 grip faces
  EXPECT_EQ(e.contact_dissipated, 0.0);
  EXPECT_LT(std::abs(e.residual()), 5e-3 * e.external_work);
  // Quasi-static: the grip has moved delta = 0.01 x (2 / 2 + 0.5) = 0.015 over the soft height
  // H = 1, so the pull is E delta / H = 0.15 (less ~1% for the four penalty springs in series,
  // and the ringing of the undamped blocks; measured 0.148).
  EXPECT_NEAR(s.model.rigid.fy[r], 10.0 * 0.015 / 1.0, 0.03 * 0.15);
}

}  // namespace
}  // namespace sg
