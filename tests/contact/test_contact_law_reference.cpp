// The reference code's other contact laws (contact_law.h): two slopes, damping, bonded
// interfaces, the linear-softening cohesive zone, each against its closed form.
//
// Impacts are integrated as the solver does (symplectic Euler, the force at the new gap):
// one contact point of length L = 1 carrying a mass m against a fixed surface, a step of
// 1/4000 of the contact's period.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "contact/contact_law.h"

namespace sg {
namespace {

constexpr double kMass = 2.0;
constexpr double kLength = 1.0;

// A frictionless-like law of `kind` with k_n = 1024 (per pass: what the contact system
// evaluates).
ContactLawParams impact_law(ContactLawKind kind) {
  ContactLawParams p;
  p.kind = kind;
  p.normal_stiffness = 1024.0;
  if (kind != ContactLawKind::frictionless) p.tangential_stiffness = 512.0;
  return per_pass_params(p);
}

struct Impact {
  double restitution = 0.0;   // v_out / v_in
  double dissipated = 0.0;    // sum of the law's dissipation x L
  double kinetic_loss = 0.0;  // 1/2 m (v_in^2 - v_out^2)
};

// The mass thrown at the surface at v_in = 1 from a gap of 0.01, until it leaves again.
Impact impact(const ContactLawParams& law) {
  const double omega = std::sqrt(law.normal_stiffness * kLength / kMass);
  const double dt = 2.0 * std::numbers::pi / omega / 4000.0;
  double gap = 0.01, velocity = -1.0;
  ContactHistory history;
  Impact out;
  bool touched = false;
  for (int step = 0; step < 1000000; ++step) {
    ContactKinematics kin;
    kin.normal_gap = gap;
    kin.interval = dt;
    kin.effective_mass = kMass;
    kin.initial_length = kLength;
    const ContactTraction t = evaluate_contact_law(law, kin, history);
    out.dissipated += kLength * t.dissipated;
    touched = touched || gap < 0.0;
    if (touched && gap > 0.0 && t.normal == 0.0) break;
    velocity += dt * kLength * t.normal / kMass;
    gap += dt * velocity;
  }
  out.restitution = velocity / 1.0;
  out.kinetic_loss = 0.5 * kMass * (1.0 - velocity * velocity);
  return out;
}

// ---------------------------------------------------------------- two slopes

TEST(TwoSlopeLaw, RestitutionIsTheSquareRootOfTheUnloadingRatio) {
  // Loaded along k_n to the deepest penetration delta (stores 1/2 k_n delta^2), unloaded
  // along r k_n (gives back r times that): e^2 = r.
  for (const double r : {1.0, 0.64, 0.25}) {
    ContactLawParams law = impact_law(ContactLawKind::two_slope);
    law.unloading_ratio = r;
    const Impact result = impact(law);
    EXPECT_NEAR(result.restitution, std::sqrt(r), 2e-3 * std::sqrt(r)) << "r = " << r;
    // What the law books as dissipated is what the mass lost.
    EXPECT_NEAR(result.dissipated, result.kinetic_loss, 2e-3 * 0.5 * kMass) << "r = " << r;
  }
}

TEST(TwoSlopeLaw, SlidesAtTheCoulombThresholdOfItsBranch) {
  ContactLawParams law = impact_law(ContactLawKind::two_slope);
  law.friction = 0.5;
  law.unloading_ratio = 0.25;
  ContactHistory h;
  (void)evaluate_contact_law(law, -0.004, 0.0, h);                 // loading: p_n = 1024 x 0.004
  ContactTraction t = evaluate_contact_law(law, -0.002, 0.01, h);  // unloading, sliding
  EXPECT_TRUE(h.unloading);
  EXPECT_DOUBLE_EQ(t.normal, 0.25 * 1024.0 * 0.002);
  EXPECT_TRUE(t.slipping);
  EXPECT_DOUBLE_EQ(t.tangential, -0.5 * t.normal);
}

// ---------------------------------------------------------------- damping

TEST(ContactDamping, ImpactLosesTheEnergyOfADampedOscillator) {
  // A mass m_eff on a spring k_n L0 with a dashpot c L0 = 2 zeta sqrt(m_eff k_n L0): a
  // half period of the damped oscillator, e = exp(-zeta pi / sqrt(1 - zeta^2)).
  for (const double zeta : {0.05, 0.2, 0.5}) {
    ContactLawParams law = impact_law(ContactLawKind::frictionless);
    law.damping_ratio = zeta;
    const Impact result = impact(law);
    const double expected = std::exp(-zeta * std::numbers::pi / std::sqrt(1.0 - zeta * zeta));
    EXPECT_NEAR(result.restitution, expected, 5e-3 * expected) << "zeta = " << zeta;
    EXPECT_NEAR(result.dissipated, result.kinetic_loss, 2e-3 * 0.5 * kMass) << "zeta = " << zeta;
  }
  // No damping: elastic.
  EXPECT_NEAR(impact(impact_law(ContactLawKind::frictionless)).restitution, 1.0, 2e-3);
}

TEST(ContactDamping, StuckTangentialOscillationDecaysAtTheDampingRatio) {
  // A mass held in contact (constant penetration) and released with a tangential offset:
  // each period the amplitude falls by exp(-2 pi zeta / sqrt(1 - zeta^2)).
  const double zeta = 0.1;
  ContactLawParams law = impact_law(ContactLawKind::coulomb);
  law.friction = 100.0;  // never slides
  law.damping_ratio = zeta;
  const double omega = std::sqrt(law.tangential_stiffness * kLength / kMass);
  const double period = 2.0 * std::numbers::pi / omega;
  const double dt = period / 4000.0;
  ContactHistory h;
  double offset = 0.01, velocity = 0.0, previous_offset = offset;
  (void)evaluate_contact_law(law, -0.01, 0.0, h);  // touch, then the stored slip is the offset
  h.stored_slip = offset;
  std::vector<double> peaks;
  for (int step = 0; step < 20000; ++step) {
    ContactKinematics kin;
    kin.normal_gap = -0.01;
    kin.slip_increment = offset - previous_offset;
    kin.interval = dt;
    kin.effective_mass = kMass;
    kin.initial_length = kLength;
    previous_offset = offset;
    const ContactTraction t = evaluate_contact_law(law, kin, h);
    ASSERT_FALSE(t.slipping);
    const double new_velocity = velocity + dt * kLength * t.tangential / kMass;
    if (velocity > 0.0 && new_velocity <= 0.0) peaks.push_back(offset);
    velocity = new_velocity;
    offset += dt * velocity;
  }
  ASSERT_GE(peaks.size(), 3u);
  const double decrement = std::exp(-2.0 * std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
  EXPECT_NEAR(peaks[2] / peaks[1], decrement, 5e-3 * decrement);
}

// ---------------------------------------------------------------- bonded

// k_n = 1024, k_b = 512, T_b = 4, c_b = 2, mu_b = 0.5; residual mu_f = 0.25, sigma_c = 1,
// tau_c = 0.5 (whole contact; a pass carries half of each strength: exact powers of two).
ContactLawParams bonded_law() {
  ContactLawParams p;
  p.kind = ContactLawKind::bonded;
  p.normal_stiffness = 1024.0;
  p.tangential_stiffness = 512.0;
  p.bond_normal_stiffness = 512.0;
  p.bond_tensile_strength = 4.0;
  p.bond_shear_strength = 2.0;
  p.bond_friction = 0.5;
  p.friction = 0.25;
  p.adhesion = 1.0;
  p.shear_strength = 0.5;
  p.bond_gap = 0.01;
  return per_pass_params(p);
}

ContactKinematics at_gap(double gap, double slip = 0.0, bool first = false) {
  ContactKinematics kin;
  kin.normal_gap = gap;
  kin.slip_increment = slip;
  kin.first_evaluation = first;
  return kin;
}

TEST(BondedLaw, PullsOffAtTheTensileStrengthThenFollowsTheResidualLaw) {
  const ContactLawParams law = bonded_law();
  ContactHistory h;
  // Intact where the surfaces are within bond_gap at the first evaluation (here open by
  // 0.002: a bond holds across it).
  ContactTraction t = evaluate_contact_law(law, at_gap(0.002, 0.0, true), h);
  EXPECT_TRUE(h.intact);
  EXPECT_EQ(t.normal, -512.0 * 0.002);
  // Pulled in small steps: holds up to T_b / 2 = 2 at g = 2 / k_b = 1/256, exactly.
  double peak = 0.0;
  for (int i = 1; i <= 100; ++i) {
    t = evaluate_contact_law(law, at_gap(i * (1.0 / 256.0) / 100.0), h);
    peak = std::max(peak, -t.normal);
  }
  EXPECT_TRUE(h.intact);
  EXPECT_EQ(peak, 2.0);
  t = evaluate_contact_law(law, at_gap(std::nextafter(1.0 / 256.0, 1.0)), h);
  EXPECT_TRUE(t.bond_broken);
  EXPECT_FALSE(h.intact);
  EXPECT_EQ(t.normal, 0.0);  // the residual bond (sigma_c / 2 = 0.5) cannot hold this either
  // The released elastic energy is booked: 1/2 k_b g_prev g_now.
  EXPECT_NEAR(t.dissipated, 0.5 * 512.0 * (1.0 / 256.0) * (1.0 / 256.0), 1e-9);
  // Residual: re-forms on touch, holds sigma_c / 2 = 0.5 in tension with k_n: g = 0.5 / 1024.
  t = evaluate_contact_law(law, at_gap(-0.001), h);
  EXPECT_EQ(t.normal, 1.024);
  t = evaluate_contact_law(law, at_gap(0.5 / 1024.0), h);
  EXPECT_EQ(t.normal, -0.5);
  t = evaluate_contact_law(law, at_gap(std::nextafter(0.5 / 1024.0, 1.0)), h);
  EXPECT_TRUE(t.bond_broken);
  EXPECT_EQ(t.normal, 0.0);
}

TEST(BondedLaw, ShearFailureAtTheBondStrengthThenResidualFriction) {
  const ContactLawParams law = bonded_law();
  ContactHistory h;
  const double gap = -1.0 / 1024.0;  // p_n = 1
  (void)evaluate_contact_law(law, at_gap(gap, 0.0, true), h);
  ASSERT_TRUE(h.intact);
  // Bond threshold c_b / 2 + mu_b p_n = 1 + 0.5 = 1.5: slip 1.5 / k_t exactly holds.
  ContactTraction t = evaluate_contact_law(law, at_gap(gap, 1.5 / 512.0), h);
  EXPECT_EQ(t.tangential, -1.5);
  EXPECT_TRUE(h.intact);
  t = evaluate_contact_law(law, at_gap(gap, 1.0 / 512.0), h);
  EXPECT_TRUE(t.bond_broken);
  EXPECT_FALSE(h.intact);
  // Residual threshold tau_c / 2 + mu_f p_n = 0.25 + 0.25 = 0.5: slides there.
  EXPECT_TRUE(t.slipping);
  EXPECT_EQ(t.tangential, -0.5);
  t = evaluate_contact_law(law, at_gap(gap, 0.01), h);
  EXPECT_EQ(t.tangential, -0.5);
  EXPECT_NEAR(t.dissipated, 0.5 * 0.01, 1e-12);  // threshold x slip
}

TEST(BondedLaw, ContactsFormedAfterTheStartAreNotBonded) {
  const ContactLawParams law = bonded_law();
  ContactHistory h;
  ContactTraction t = evaluate_contact_law(law, at_gap(-0.001), h);  // not the first evaluation
  EXPECT_FALSE(h.intact);
  EXPECT_EQ(t.normal, 1.024);  // the residual law
  t = evaluate_contact_law(law, at_gap(0.001), h);
  EXPECT_EQ(t.normal, 0.0);  // residual sigma_c / 2 = 0.5 < k_n 0.001: lets go
  // Beyond bond_gap at the first evaluation: not bonded either.
  ContactHistory far;
  (void)evaluate_contact_law(law, at_gap(0.02, 0.0, true), far);
  EXPECT_FALSE(far.intact);
}

// ---------------------------------------------------------------- cohesive zone

// k = 1000, P_lim = 2, g_lim = 0.01 (whole contact): per pass P_lim = 1, g_e = 0.001.
ContactLawParams zone_law(double residual = 0.0, double mixed_mode = 1.0) {
  ContactLawParams p;
  p.kind = ContactLawKind::cohesive_zone;
  p.normal_stiffness = 1000.0;
  p.tangential_stiffness = 1000.0;
  p.peak_traction = 2.0;
  p.critical_opening = 0.01;
  p.residual_traction = residual;
  p.mixed_mode_ratio = mixed_mode;
  p.bond_gap = 1e-6;
  return per_pass_params(p);
}

// Area under the envelope of one pass: 1/2 P g_e + 1/2 (P + P_res)(g_lim - g_e).
double fracture_energy(const ContactLawParams& pass) {
  const double g_e = pass.peak_traction / pass.normal_stiffness;
  return 0.5 * pass.peak_traction * g_e +
         0.5 * (pass.peak_traction + pass.residual_traction) * (pass.critical_opening - g_e);
}

// Drives the zone along `openings` (normal) or `slips` (tangential, at g_n = 0), returns the
// energy dissipated and the largest traction met.
struct ZonePath {
  double dissipated = 0.0, peak = 0.0;
  bool failed = false;
};

ZonePath drive(const ContactLawParams& law, const std::vector<double>& path, bool shear) {
  ContactHistory h;
  ZonePath out;
  (void)evaluate_contact_law(law, at_gap(0.0, 0.0, true), h);
  double previous = 0.0;
  for (const double x : path) {
    const ContactTraction t = shear ? evaluate_contact_law(law, at_gap(0.0, x - previous), h)
                                    : evaluate_contact_law(law, at_gap(x), h);
    previous = x;
    out.dissipated += t.dissipated;
    out.peak = std::max(out.peak, shear ? std::abs(t.tangential) : -t.normal);
    out.failed = out.failed || t.bond_broken;
  }
  return out;
}

// n equal steps from a to b (b included).
void ramp(std::vector<double>& path, double a, double b, int n) {
  for (int i = 1; i <= n; ++i)
    path.push_back(a + (b - a) * i / n);
}

TEST(CohesiveZoneLaw, CompleteOpeningDissipatesTheFractureEnergy) {
  for (const double residual : {0.0, 0.5}) {
    const ContactLawParams law = zone_law(residual);
    std::vector<double> path;
    ramp(path, 0.0, 0.012, 400);
    const ZonePath result = drive(law, path, false);
    EXPECT_TRUE(result.failed);
    EXPECT_NEAR(result.peak, law.peak_traction, 0.01 * law.peak_traction);
    EXPECT_NEAR(result.dissipated, fracture_energy(law), 0.02 * fracture_energy(law))
        << "P_res = " << residual;
  }
  EXPECT_DOUBLE_EQ(fracture_energy(zone_law()), 0.5 * 1.0 * 0.01);  // 1/2 P_lim g_lim
}

TEST(CohesiveZoneLaw, UnloadingIsElasticAndReloadingResumesTheEnvelope) {
  const ContactLawParams law = zone_law();
  std::vector<double> path;
  ramp(path, 0.0, 0.004, 100);     // past the peak: D = 1/3
  ramp(path, 0.004, -0.001, 100);  // back along the secant, into compression
  ramp(path, -0.001, 0.003, 100);  // reloading along the secant: nothing dissipated
  const ZonePath partial = drive(law, path, false);
  EXPECT_FALSE(partial.failed);
  // Dissipated so far: the area between the envelope and the secant at g_max = 0.004,
  // 1/2 g_max (P_lim - traction(g_max)) ... = 1/2 P_lim g_max - ... (triangle 0, g_e, g_max).
  const double g_e = 0.001, traction = 1.0 * (0.01 - 0.004) / (0.01 - g_e);
  const double expected =
      0.5 * 1.0 * g_e + 0.5 * (1.0 + traction) * (0.004 - g_e) - 0.5 * traction * 0.004;
  EXPECT_NEAR(partial.dissipated, expected, 0.02 * expected);
  ramp(path, 0.003, 0.012, 300);  // then to failure: the whole fracture energy
  const ZonePath complete = drive(law, path, false);
  EXPECT_TRUE(complete.failed);
  EXPECT_NEAR(complete.dissipated, fracture_energy(law), 0.02 * fracture_energy(law));
}

TEST(CohesiveZoneLaw, ShearEnvelopeIsTheNormalOneScaledByTheMixedModeRatio) {
  // r_m = 0.5: shear strength r_m P_lim at slip r_m g_e, failure at r_m g_lim, energy
  // r_m^2 G_c.
  const ContactLawParams law = zone_law(0.0, 0.5);
  std::vector<double> path;
  ramp(path, 0.0, 0.006, 400);
  const ZonePath result = drive(law, path, true);
  EXPECT_TRUE(result.failed);
  EXPECT_NEAR(result.peak, 0.5 * law.peak_traction, 0.01 * law.peak_traction);
  const double expected = 0.25 * fracture_energy(law);
  EXPECT_NEAR(result.dissipated, expected, 0.02 * expected);
}

TEST(ContactLawParams, NewLawCoefficientsAreCheckedWithTheirNames) {
  const auto message = [](const ContactLawParams& p) -> std::string {
    try {
      validate(p, "contact law for materials 'a' and 'b'");
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  ContactLawParams zone = zone_law();
  zone.peak_traction *= 2.0;  // whole-contact values for validate
  zone.residual_traction = 0.0;
  EXPECT_EQ(message(zone), "");
  zone.critical_opening = 0.0005;  // below the elastic limit of a pass, P_lim / (2 k) = 0.001
  EXPECT_NE(message(zone).find("critical_opening"), std::string::npos) << message(zone);
  ContactLawParams slope = impact_law(ContactLawKind::two_slope);
  slope.unloading_ratio = 1.5;
  EXPECT_NE(message(slope).find("unloading_ratio"), std::string::npos) << message(slope);
  ContactLawParams coulomb = impact_law(ContactLawKind::coulomb);
  coulomb.bond_gap = 0.1;  // not a coulomb coefficient
  EXPECT_NE(message(coulomb).find("bond_gap"), std::string::npos) << message(coulomb);
  coulomb.bond_gap = 0.0;
  coulomb.damping_ratio = 1.0;
  EXPECT_NE(message(coulomb).find("damping_ratio"), std::string::npos) << message(coulomb);
}

}  // namespace
}  // namespace sg
