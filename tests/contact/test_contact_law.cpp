// Contact laws (contact_law.h): thresholds, slip, dissipation and energy balance.
//
// Coefficients are powers of two so that the thresholds are exactly representable:
// k_n = 1024, k_t = 512, sigma_c = 2, tau_c = 1 put the opening limit at g_n = 1/512 and the
// elastic slip limit at g_t = 1/512, both exact; "exactly at the threshold" is then exact.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "contact/contact_law.h"
#include "contact/material_pair_table.h"
#include "core/error.h"

namespace sg {
namespace {

ContactLawParams cohesive_law() {
  ContactLawParams p;
  p.kind = ContactLawKind::cohesive;
  p.normal_stiffness = 1024.0;
  p.tangential_stiffness = 512.0;
  p.adhesion = 2.0;
  p.shear_strength = 1.0;
  return p;
}

ContactLawParams coulomb_law(double friction) {
  ContactLawParams p;
  p.kind = ContactLawKind::coulomb;
  p.normal_stiffness = 1024.0;
  p.tangential_stiffness = 512.0;
  p.friction = friction;
  return p;
}

// A bond that holds, last evaluated at `previous_gap`.
ContactHistory bonded(double previous_gap = 0.0) {
  ContactHistory h;
  h.active = true;
  h.normal_gap = previous_gap;
  return h;
}

double just_above(double x) {
  return std::nextafter(x, std::numeric_limits<double>::infinity());
}

// ---------------------------------------------------------------- cohesive

TEST(CohesiveLaw, HoldsExactlyAtAdhesionAndBreaksJustBeyond) {
  const ContactLawParams law = cohesive_law();
  const double limit_gap = law.adhesion / law.normal_stiffness;  // 1/512, exact

  ContactHistory at_limit = bonded();
  const ContactTraction held = evaluate_contact_law(law, limit_gap, 0.0, at_limit);
  EXPECT_EQ(held.normal, -law.adhesion);  // p_n = -sigma_c exactly: still bonded
  EXPECT_FALSE(held.bond_broken);
  EXPECT_TRUE(at_limit.active);
  EXPECT_EQ(held.dissipated, 0.0);

  const double previous_gap = 0.75 * limit_gap;
  ContactHistory beyond = bonded(previous_gap);
  const double gap = just_above(limit_gap);
  const ContactTraction broke = evaluate_contact_law(law, gap, 0.0, beyond);
  EXPECT_TRUE(broke.bond_broken);
  EXPECT_FALSE(beyond.active);
  EXPECT_EQ(broke.normal, 0.0);
  EXPECT_EQ(broke.tangential, 0.0);
  // The elastic energy of the bond is released, time-centred between the previous
  // evaluation and this one: 1/2 k_n g_prev g_n (no stored slip here).
  EXPECT_DOUBLE_EQ(broke.dissipated, 0.5 * law.normal_stiffness * previous_gap * gap);
  EXPECT_EQ(beyond.normal_gap, gap);  // the history remembers this evaluation's gap
}

TEST(CohesiveLaw, TensionBelowAdhesionIsCarried) {
  const ContactLawParams law = cohesive_law();
  ContactHistory h = bonded();
  const ContactTraction out = evaluate_contact_law(law, 0.5 / 512.0, 0.0, h);
  EXPECT_EQ(out.normal, -1.0);  // -k_n g_n: tension, half the adhesion
  EXPECT_TRUE(h.active);
}

TEST(CohesiveLaw, BreakingReleasesNormalAndTangentialEnergy) {
  const ContactLawParams law = cohesive_law();
  ContactHistory h = bonded();
  const double previous_gap = 1.0 / 1024.0;
  evaluate_contact_law(law, previous_gap, 0.5 / 512.0, h);  // elastic slip, below tau_c / k_t
  ASSERT_EQ(h.stored_slip, 0.5 / 512.0);
  const double gap = 3.0 / 1024.0, ds = 0.25 / 512.0;
  const ContactTraction out = evaluate_contact_law(law, gap, ds, h);
  ASSERT_TRUE(out.bond_broken);
  // Time-centred: previous state (g_n = 1/1024, g_t = 0.5/512) times trial state (3/1024,
  // 0.75/512) of each spring.
  EXPECT_DOUBLE_EQ(out.dissipated, 0.5 * 1024.0 * previous_gap * gap +
                                       0.5 * 512.0 * (0.5 / 512.0) * (0.75 / 512.0));
  EXPECT_EQ(h.stored_slip, 0.0);
}

// The released energy is the one the explicit scheme actually gives up. A point mass bonded
// to a fixed face is thrown away from it, fast enough to cross the bond's whole elastic range
// in less than a step (v dt >> sigma_c / k_n, as in the shear cell), with a tangential
// velocity that stays elastic. Symplectic Euler, kinetic energy time-centred
// (1/2 m v_n-1/2 . v_n+1/2, stepper.h): K + stored + dissipated must stay equal to
// its initial value to round-off at every step, across the break. With the released energy
// 1/2 k g_trial^2 instead, the balance is off by 1/2 k g_trial (g_trial - g_prev) at the
// break (here ~1e3 times the round-off bound below).
TEST(CohesiveLaw, ReleasedEnergyClosesTheExplicitSchemesBalanceAcrossABreak) {
  const ContactLawParams law = cohesive_law();
  // omega dt = sqrt(k_n / m) dt = 1/2 (stable); the bond starts loaded at 0.4 g_c
  // (g_c = sigma_c / k_n) and opens by v dt = 1.5 g_c per step; the tangential spring stays
  // below tau_c / k_t until the break.
  const double mass = 1.0, dt = 1.0 / 64.0;
  const double g_c = law.adhesion / law.normal_stiffness;
  double gap = 0.4 * g_c, velocity_n = 1.5 * g_c / dt, velocity_t = 0.05;
  ContactHistory h = bonded();
  double dissipated = 0.0, energy0 = 0.0, previous_vn = velocity_n, previous_vt = velocity_t;
  bool broke = false;
  for (int step = 0; step < 12; ++step) {
    const double slip_increment = dt * velocity_t;
    const ContactTraction out = evaluate_contact_law(law, gap, slip_increment, h);
    broke = broke || out.bond_broken;
    dissipated += out.dissipated;
    const double stored = stored_energy(law, gap, h);
    // f = p_n along the normal (the gap direction), p_t along the tangent (unit length).
    previous_vn = velocity_n;
    previous_vt = velocity_t;
    velocity_n += dt * out.normal / mass;
    velocity_t += dt * out.tangential / mass;
    gap += dt * velocity_n;
    const double kinetic = 0.5 * mass * (previous_vn * velocity_n + previous_vt * velocity_t);
    if (step == 0) energy0 = kinetic + stored;
    EXPECT_NEAR(kinetic + stored + dissipated, energy0, 1e-14 * energy0) << "step " << step;
    EXPECT_FALSE(out.slipping) << "step " << step;
  }
  EXPECT_TRUE(broke);
  EXPECT_GT(dissipated, 1e-4 * energy0);  // the bond held a real share of the energy
}

TEST(CohesiveLaw, SticksExactlyAtShearStrengthAndSlipsJustBeyond) {
  const ContactLawParams law = cohesive_law();
  const double limit_slip = law.shear_strength / law.tangential_stiffness;  // 1/512, exact
  ContactHistory h = bonded();
  const ContactTraction stick = evaluate_contact_law(law, 0.0, limit_slip, h);
  EXPECT_EQ(stick.tangential, -law.shear_strength);
  EXPECT_FALSE(stick.slipping);
  EXPECT_EQ(stick.dissipated, 0.0);

  ContactHistory g = bonded();
  const ContactTraction slip = evaluate_contact_law(law, 0.0, just_above(limit_slip), g);
  EXPECT_TRUE(slip.slipping);
  EXPECT_EQ(slip.tangential, -law.shear_strength);
  EXPECT_EQ(g.stored_slip, limit_slip);
  EXPECT_GT(slip.dissipated, 0.0);
}

TEST(CohesiveLaw, SlidesAtShearStrengthAndDissipatesStrengthTimesPlasticSlip) {
  const ContactLawParams law = cohesive_law();
  const double elastic = law.shear_strength / law.tangential_stiffness;  // 1/512
  ContactHistory h = bonded();
  const double ds = 1.0 / 4096.0;  // 1/8 of the elastic slip: 8 steps of stick
  const int forward_steps = 200;
  double dissipated = 0.0;
  for (int i = 0; i < forward_steps; ++i) {
    const ContactTraction out = evaluate_contact_law(law, 0.0, ds, h);
    dissipated += out.dissipated;
    if (i >= 8) {  // after the elastic slip is used up: p_t = -tau_c exactly
      EXPECT_TRUE(out.slipping) << "step " << i;
      EXPECT_EQ(out.tangential, -law.shear_strength) << "step " << i;
    }
  }
  // Plastic slip = total slip - elastic slip; dissipation = tau_c x plastic slip. Each step's
  // contribution is exact in binary (dyadic numbers), so the sum is exact up to a few ulps.
  const double forward_plastic = forward_steps * ds - elastic;
  EXPECT_NEAR(dissipated, law.shear_strength * forward_plastic, 1e-14);

  // Reverse: the spring first unloads through 2 tau_c / k_t without dissipation.
  const int back_steps = 100;
  for (int i = 0; i < back_steps; ++i) {
    const ContactTraction out = evaluate_contact_law(law, 0.0, -ds, h);
    dissipated += out.dissipated;
    if (i >= 16) {
      EXPECT_EQ(out.tangential, law.shear_strength) << "step " << i;
    } else {
      EXPECT_FALSE(out.slipping) << "step " << i;
    }
  }
  const double back_plastic = back_steps * ds - 2.0 * elastic;
  EXPECT_NEAR(dissipated, law.shear_strength * (forward_plastic + back_plastic), 1e-14);
}

TEST(CohesiveLaw, BrokenBondStaysOpenAtPositiveGapAndReformsOnTouch) {
  const ContactLawParams law = cohesive_law();
  ContactHistory h = bonded();
  evaluate_contact_law(law, 0.0, 1.5 / 512.0, h);  // slipping, g_t = 1/512
  ASSERT_TRUE(evaluate_contact_law(law, 1.0 / 256.0, 0.0, h).bond_broken);

  // Back within the bonding range (g_n = sigma_c / (2 k_n) > 0) but not touching: no force.
  const ContactTraction apart = evaluate_contact_law(law, 1.0 / 1024.0, 1e-3, h);
  EXPECT_EQ(apart.normal, 0.0);
  EXPECT_EQ(apart.tangential, 0.0);
  EXPECT_FALSE(h.active);

  // Touching again: the bond re-forms, tangentially unloaded (the closing step's slip is
  // not stored).
  const ContactTraction touch = evaluate_contact_law(law, 0.0, 1e-3, h);
  EXPECT_TRUE(h.active);
  EXPECT_EQ(touch.tangential, 0.0);
  EXPECT_EQ(h.stored_slip, 0.0);
  // ... and carries tension again.
  const ContactTraction pulled = evaluate_contact_law(law, 1.0 / 1024.0, 0.0, h);
  EXPECT_EQ(pulled.normal, -1.0);
  EXPECT_FALSE(pulled.bond_broken);
}

TEST(CohesiveLaw, FreshContactAtPositiveGapDoesNotBond) {
  const ContactLawParams law = cohesive_law();
  ContactHistory h;  // new contact from the broad phase
  const ContactTraction out = evaluate_contact_law(law, 1.0 / 1024.0, 0.0, h);
  EXPECT_EQ(out.normal, 0.0);
  EXPECT_FALSE(h.active);
}

TEST(CohesiveLaw, FrictionAddsToShearStrengthInCompression) {
  ContactLawParams law = cohesive_law();
  law.friction = 0.5;
  ContactHistory h = bonded();
  // p_n = 4 (g_n = -4/1024): threshold tau_c + mu p_n = 1 + 2 = 3.
  const ContactTraction out = evaluate_contact_law(law, -4.0 / 1024.0, 1.0, h);
  EXPECT_EQ(out.normal, 4.0);
  EXPECT_EQ(out.tangential, -3.0);
  // In tension the threshold is tau_c alone.
  ContactHistory g = bonded();
  EXPECT_EQ(evaluate_contact_law(law, 1.0 / 1024.0, 1.0, g).tangential, -1.0);
}

// ---------------------------------------------------------------- Coulomb

TEST(CoulombLaw, SticksBelowAndSlipsAboveMuTimesPressure) {
  const ContactLawParams law = coulomb_law(0.5);
  const double gap = -1.0 / 1024.0;  // p_n = 1, threshold mu p_n = 0.5, elastic slip 1/1024
  ContactHistory h;
  evaluate_contact_law(law, gap, 0.0, h);  // closes
  ASSERT_TRUE(h.active);
  const ContactTraction stick = evaluate_contact_law(law, gap, 0.5 / 1024.0, h);
  EXPECT_EQ(stick.normal, 1.0);
  EXPECT_EQ(stick.tangential, -0.25);
  EXPECT_FALSE(stick.slipping);
  EXPECT_EQ(stick.dissipated, 0.0);

  const ContactTraction at = evaluate_contact_law(law, gap, 0.5 / 1024.0, h);
  EXPECT_EQ(at.tangential, -0.5);  // exactly at the threshold: still sticking
  EXPECT_FALSE(at.slipping);

  for (int i = 0; i < 10; ++i) {
    const ContactTraction slip = evaluate_contact_law(law, gap, 1.0 / 1024.0, h);
    EXPECT_TRUE(slip.slipping);
    EXPECT_EQ(slip.tangential, -law.friction * slip.normal);  // p_t == mu p_n while slipping
    EXPECT_EQ(slip.dissipated, 0.5 * (1.0 / 1024.0));         // mu p_n x plastic slip
  }
}

TEST(CoulombLaw, NoTensionAndOpeningReleasesTangentialEnergy) {
  const ContactLawParams law = coulomb_law(0.5);
  ContactHistory h;
  evaluate_contact_law(law, -1.0 / 1024.0, 0.0, h);
  evaluate_contact_law(law, -1.0 / 1024.0, 0.5 / 1024.0, h);  // g_t = 1/2048, stick
  const ContactTraction open = evaluate_contact_law(law, 1.0 / 1024.0, 0.0, h);
  EXPECT_EQ(open.normal, 0.0);  // no tension without a cohesive law
  EXPECT_EQ(open.tangential, 0.0);
  EXPECT_FALSE(h.active);
  EXPECT_DOUBLE_EQ(open.dissipated, 0.5 * 512.0 * (0.5 / 1024.0) * (0.5 / 1024.0));
}

// Work done on the contact along a tangential path = stored energy + dissipated.
// The work is integrated with the trapezoid rule on the law's own tractions; the traction
// is linear while sticking and constant while slipping, so the rule is exact except in the
// steps where stick turns into slip: there the integrand is min(k s, T), and the trapezoid
// error is k theta (1 - theta) h^2 / 2 <= k h^2 / 8 per such step (theta the position of
// the kink in the step). Hence the tolerance n_yield k_t h^2 / 8 (+ round-off).
TEST(CoulombLaw, DissipationEqualsFrictionWorkOverALoadingPath) {
  const ContactLawParams law = coulomb_law(0.3);
  const double gap = -0.003;  // p_n = 3.072, threshold 0.9216: not a dyadic number
  ContactHistory h;
  evaluate_contact_law(law, gap, 0.0, h);
  const double h_step = 1.3e-4;  // elastic slip T / k_t = 1.8e-3: ~14 steps of stick
  // Path: +40 steps, -70 steps, +45 steps, -3 steps (the last leg stays elastic).
  const int legs[] = {40, -70, 45, -3};
  double work = 0.0, dissipated = 0.0, plastic_check = 0.0;
  double previous_traction = 0.0;
  int yields = 0;
  bool was_slipping = false;
  for (const int leg : legs) {
    const double ds = leg > 0 ? h_step : -h_step;
    for (int i = 0; i < std::abs(leg); ++i) {
      const ContactTraction out = evaluate_contact_law(law, gap, ds, h);
      // Work done on the contact by the imposed slip: -p_t ds (p_t opposes the slip).
      work += -0.5 * (previous_traction + out.tangential) * ds;
      previous_traction = out.tangential;
      dissipated += out.dissipated;
      if (out.slipping) plastic_check += out.dissipated / (law.friction * out.normal);
      if (out.slipping && !was_slipping) ++yields;
      was_slipping = out.slipping;
      if (out.slipping) {
        EXPECT_DOUBLE_EQ(std::abs(out.tangential), law.friction * out.normal);
      }
    }
  }
  ASSERT_EQ(yields, 3);
  // Only the tangential work is integrated: take the normal spring's 1/2 k_n g_n^2 (loaded
  // before the path, constant along it) out of the stored energy.
  const double stored = stored_energy(law, gap, h) - 0.5 * law.normal_stiffness * gap * gap;
  const double tolerance = yields * law.tangential_stiffness * h_step * h_step / 8.0 + 1e-15;
  EXPECT_NEAR(work, stored + dissipated, tolerance);
  EXPECT_GT(dissipated, 100.0 * tolerance);  // the check is not vacuous

  // Plastic slip, analytically: each leg beyond the first uses 2 T / k_t to reverse.
  const double elastic = law.friction * (-law.normal_stiffness * gap) / law.tangential_stiffness;
  const double expected_plastic =
      (40 * h_step - elastic) + (70 * h_step - 2 * elastic) + (45 * h_step - 2 * elastic);
  EXPECT_NEAR(plastic_check, expected_plastic, 1e-12);
}

// ---------------------------------------------------------------- frictionless

TEST(FrictionlessLaw, NoTangentialTractionAndNoDissipationOverANormalCycle) {
  ContactLawParams law;
  law.kind = ContactLawKind::frictionless;
  law.normal_stiffness = 1000.0;
  ContactHistory h;
  // Gap cycle 0 -> -0.01 -> +0.01 -> 0 in steps of 1e-3, with a slip in every step. The
  // normal traction is a function of the gap alone, piecewise linear with its kink at 0 on
  // a step boundary, so the trapezoid work over the closed cycle is 0 up to round-off
  // (~60 terms of magnitude 1e-4 x 1e-16).
  double work = 0.0, dissipated = 0.0, previous_gap = 0.0, previous_normal = 0.0;
  const auto step_to = [&](double gap) {
    const ContactTraction out = evaluate_contact_law(law, gap, 1e-3, h);
    EXPECT_EQ(out.tangential, 0.0);
    EXPECT_EQ(out.dissipated, 0.0);
    EXPECT_EQ(out.normal, gap < 0.0 ? -1000.0 * gap : 0.0);
    work += -0.5 * (previous_normal + out.normal) * (gap - previous_gap);
    dissipated += out.dissipated;
    previous_gap = gap;
    previous_normal = out.normal;
  };
  for (int i = 1; i <= 10; ++i)
    step_to(-1e-3 * i);
  // Loading work into the penalty spring: 1/2 k_n g^2 = 0.05 (the cycle is not trivial).
  EXPECT_NEAR(work, 0.05, 1e-15);
  EXPECT_NEAR(work, stored_energy(law, -0.01, h), 1e-15);
  for (int i = 9; i >= -10; --i)
    step_to(-1e-3 * i);
  for (int i = 9; i >= 0; --i)
    step_to(1e-3 * i);
  EXPECT_NEAR(work, 0.0, 1e-15);
  EXPECT_EQ(dissipated, 0.0);
}

// ---------------------------------------------------------------- two-pass strengths

TEST(ContactLawParams, PerPassHalvesStrengthsOnly) {
  ContactLawParams law = cohesive_law();
  law.friction = 0.4;
  const ContactLawParams half = per_pass_params(law);
  EXPECT_EQ(half.adhesion, 1.0);
  EXPECT_EQ(half.shear_strength, 0.5);
  EXPECT_EQ(half.normal_stiffness, law.normal_stiffness);
  EXPECT_EQ(half.tangential_stiffness, law.tangential_stiffness);
  EXPECT_EQ(half.friction, law.friction);
  // Two passes of a flat contact of length l, each node of tributary length l / n on both
  // sides, break together at sigma_c / (2 k_n): total pull-off force 2 x (sigma_c / 2) l.
  ContactHistory h = bonded();
  const double pass_limit = half.adhesion / half.normal_stiffness;
  EXPECT_EQ(2.0 * -evaluate_contact_law(half, pass_limit, 0.0, h).normal, law.adhesion);
}

// ---------------------------------------------------------------- bad input

std::string error_of(const ContactLawParams& law) {
  try {
    validate(law, "contact law for materials 'soft' and 'wall'");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ContactLawParams, BadCoefficientsAreRejectedWithContext) {
  const std::string context = "contact law for materials 'soft' and 'wall'";
  const auto expect_error = [&](ContactLawParams law, const std::string& word) {
    const std::string message = error_of(law);
    EXPECT_NE(message.find(context), std::string::npos) << message;
    EXPECT_NE(message.find(word), std::string::npos) << message;
  };
  EXPECT_EQ(error_of(cohesive_law()), "");
  EXPECT_EQ(error_of(coulomb_law(0.5)), "");

  ContactLawParams law = cohesive_law();
  law.adhesion = -1.0;
  expect_error(law, "adhesion");
  law = cohesive_law();
  law.shear_strength = -0.5;
  expect_error(law, "shear strength");
  law = cohesive_law();
  law.normal_stiffness = 0.0;
  expect_error(law, "normal_stiffness");
  law = coulomb_law(0.5);
  law.tangential_stiffness = -3.0;
  expect_error(law, "tangential_stiffness");
  expect_error(coulomb_law(-0.1), "friction");
  law = coulomb_law(0.5);
  law.normal_stiffness = std::numeric_limits<double>::quiet_NaN();
  expect_error(law, "finite");
  law = coulomb_law(0.5);
  law.adhesion = 1.0;  // adhesion on a non-cohesive law: the user meant "cohesive"
  expect_error(law, "use a cohesive law");
  law.kind = ContactLawKind::frictionless;
  law.adhesion = 0.0;  // friction 0.5 on a frictionless law
  expect_error(law, "use a coulomb law");
}

TEST(MaterialPairTable, SymmetricLookup) {
  MaterialPairTable table({"soft", "wall", "hard"});
  table.set("soft", "wall", cohesive_law());
  table.set(2, 2, coulomb_law(0.5));
  EXPECT_TRUE(table.has(0, 1));
  EXPECT_TRUE(table.has(1, 0));
  EXPECT_FALSE(table.has(0, 0));
  EXPECT_EQ(&table.at(1, 0), &table.at(0, 1));
  EXPECT_EQ(table.at(1, 0).kind, ContactLawKind::cohesive);
  EXPECT_EQ(table.at(2, 2).friction, 0.5);
  const MaterialPairTable half = table.per_pass();
  EXPECT_EQ(half.at(0, 1).adhesion, 1.0);
  EXPECT_EQ(half.at(2, 2).friction, 0.5);
}

std::string table_error(const auto& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(MaterialPairTable, MissingDuplicateAndUnknownAreClearErrors) {
  MaterialPairTable table({"soft", "wall"});
  table.set("soft", "soft", cohesive_law());
  EXPECT_EQ(table_error([&] { (void)table.at(0, 1); }),
            "no contact law for materials 'soft' and 'wall'");
  EXPECT_EQ(table_error([&] { (void)table.at(1, 0); }),
            "no contact law for materials 'wall' and 'soft'");
  const std::string duplicate = table_error([&] { table.set("soft", "soft", coulomb_law(0.1)); });
  EXPECT_NE(duplicate.find("given twice"), std::string::npos) << duplicate;
  const std::string unknown = table_error([&] { (void)table.find_material("glass"); });
  EXPECT_EQ(unknown, "unknown material 'glass' (known: soft, wall)");
  ContactLawParams bad = cohesive_law();
  bad.adhesion = -2.0;
  const std::string invalid = table_error([&] { table.set("soft", "wall", bad); });
  EXPECT_NE(invalid.find("contact law for materials 'soft' and 'wall'"), std::string::npos)
      << invalid;
  const int used[] = {0, 0, 1};
  EXPECT_EQ(table_error([&] { table.verify_covers(used); }),
            "no contact law for materials 'soft' and 'wall'");
  const int soft_only[] = {0, 0};
  EXPECT_EQ(table_error([&] { table.verify_covers(soft_only); }), "");
  EXPECT_NE(table_error([&] {
              (void)MaterialPairTable({"a", "a"});
            }).find("used twice"),
            std::string::npos);
}

}  // namespace
}  // namespace sg
