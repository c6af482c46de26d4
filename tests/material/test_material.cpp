// Constitutive laws: closed forms, consistency of P with the energy W, objectivity, and
// positive dissipation of the objective damping.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "material/material.h"

namespace sg {
namespace {

MaterialDef soft(MaterialLaw law) {
  MaterialDef d;
  d.name = "soft";
  d.law = law;
  d.young = 10.0;
  d.poisson = 0.495;
  d.density = 1.0;
  d.damping = 0.02;
  return d;
}

Mat2 some_deformation() {
  Mat2 f;
  f << 1.15, 0.22, -0.08, 0.91;
  return f;
}

TEST(Material, LameParametersOfPlaneStrain) {
  const MaterialParams m = make_material_params(soft(MaterialLaw::neo_hookean));
  EXPECT_NEAR(m.mu, 10.0 / (2 * 1.495), 1e-12);
  EXPECT_NEAR(m.lambda, 10.0 * 0.495 / (1.495 * 0.01), 1e-9);
  // docs/method.md §Materials: c_p ~ 5.8 sqrt(E / rho) for nu = 0.495.
  EXPECT_NEAR(p_wave_speed(m) / std::sqrt(10.0), 5.8, 0.05);
}

TEST(Material, NeoHookeanUniformDilationClosedForm) {
  // F = s I: P = [mu (s - 1/s) + lambda ln(s^2) / s] I, W = mu (s^2 - 1) - mu ln s^2 + lambda/2
  // ln^2 s^2.
  const MaterialParams m = make_material_params(soft(MaterialLaw::neo_hookean));
  const double s = 1.01;
  const ElasticResponse r = elastic_response(m, s * Mat2::Identity());
  const double p = m.mu * (s - 1 / s) + m.lambda * std::log(s * s) / s;
  EXPECT_NEAR(r.first_piola(0, 0), p, 1e-12 * std::abs(p));
  EXPECT_NEAR(r.first_piola(1, 1), p, 1e-12 * std::abs(p));
  EXPECT_NEAR(r.first_piola(0, 1), 0.0, 1e-12);
  const double l = std::log(s * s);
  EXPECT_NEAR(r.energy_density, m.mu * (s * s - 1) - m.mu * l + 0.5 * m.lambda * l * l, 1e-12);
}

TEST(Material, SaintVenantKirchhoffUniaxialClosedForm) {
  // F = diag(s, 1): E = diag((s^2-1)/2, 0), S_xx = (lambda + 2 mu) E_xx, P_xx = s S_xx.
  const MaterialParams m = make_material_params(soft(MaterialLaw::saint_venant_kirchhoff));
  const double s = 1.2, exx = 0.5 * (s * s - 1);
  Mat2 f = Mat2::Identity();
  f(0, 0) = s;
  const ElasticResponse r = elastic_response(m, f);
  EXPECT_NEAR(r.first_piola(0, 0), s * (m.lambda + 2 * m.mu) * exx, 1e-9);
  EXPECT_NEAR(r.first_piola(1, 1), m.lambda * exx, 1e-9);
  EXPECT_NEAR(r.energy_density, 0.5 * (m.lambda + 2 * m.mu) * exx * exx, 1e-9);
}

TEST(Material, FirstPiolaIsTheDerivativeOfTheEnergy) {
  for (MaterialLaw law : {MaterialLaw::neo_hookean, MaterialLaw::saint_venant_kirchhoff}) {
    const MaterialParams m = make_material_params(soft(law));
    const Mat2 f = some_deformation();
    const Mat2 p = elastic_response(m, f).first_piola;
    const double h = 1e-6;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        Mat2 fp = f, fm = f;
        fp(i, j) += h;
        fm(i, j) -= h;
        const double fd =
            (elastic_response(m, fp).energy_density - elastic_response(m, fm).energy_density) /
            (2 * h);
        // Central difference error ~ h^2 W''' ~ 1e-12 * lambda; round-off ~ 1e-16 W / h.
        EXPECT_NEAR(p(i, j), fd, 1e-6 * (m.lambda + m.mu)) << to_string(law) << " " << i << j;
      }
  }
}

TEST(Material, ObjectivityRotationGivesNoStressAndRotatesStress) {
  for (MaterialLaw law : {MaterialLaw::neo_hookean, MaterialLaw::saint_venant_kirchhoff}) {
    const MaterialParams m = make_material_params(soft(law));
    for (double angle : {0.3, std::numbers::pi / 2, 2.5}) {
      const Mat2 r = rotation(angle);
      const ElasticResponse rigid = elastic_response(m, r);
      EXPECT_NEAR(rigid.first_piola.norm(), 0.0, 1e-12 * m.lambda) << to_string(law);
      EXPECT_NEAR(rigid.energy_density, 0.0, 1e-12 * m.lambda);
      const Mat2 f = some_deformation();
      const ElasticResponse a = elastic_response(m, f), b = elastic_response(m, r * f);
      EXPECT_NEAR((b.first_piola - r * a.first_piola).norm(), 0.0, 1e-10 * a.first_piola.norm());
      EXPECT_NEAR(b.energy_density, a.energy_density, 1e-10 * a.energy_density);
      EXPECT_NEAR(cauchy_stress(m, r * f).von_mises(), cauchy_stress(m, f).von_mises(),
                  1e-10 * cauchy_stress(m, f).von_mises());
    }
  }
}

TEST(Material, CauchyStressOfUniformDilation) {
  // Neo-Hookean, F = s I in plane: sigma = mu/J (b - I) + lambda ln J / J I, J = s^2.
  const MaterialParams m = make_material_params(soft(MaterialLaw::neo_hookean));
  const double s = 0.98, j = s * s;
  const CauchyStress c = cauchy_stress(m, s * Mat2::Identity());
  EXPECT_NEAR(c.xx, m.mu / j * (s * s - 1) + m.lambda * std::log(j) / j, 1e-10);
  EXPECT_NEAR(c.zz, m.lambda * std::log(j) / j, 1e-10);
  EXPECT_NEAR(c.xy, 0.0, 1e-12);
  EXPECT_NEAR(c.von_mises(), std::abs(c.xx - c.zz), 1e-10);
  EXPECT_NEAR(c.pressure(), -(2 * c.xx + c.zz) / 3, 1e-12);
}

TEST(Material, ViscousStressIsDissipativeAndVanishesWithoutStrainRate) {
  const MaterialParams m = make_material_params(soft(MaterialLaw::neo_hookean));
  Mat2 rate;
  rate << 0.3, -0.1, -0.1, -0.2;
  const Mat2 s = viscous_second_piola(m, rate);
  EXPECT_GT((s.array() * rate.array()).sum(), 0.0);
  // alpha (lambda tr I + 2 mu E_dot)
  EXPECT_NEAR(s(0, 1), m.damping * 2 * m.mu * -0.1, 1e-12);
  EXPECT_NEAR(s(0, 0), m.damping * (m.lambda * 0.1 + 2 * m.mu * 0.3), 1e-10);
  EXPECT_EQ(viscous_second_piola(m, Mat2::Zero()).norm(), 0.0);
}

TEST(Material, BadParametersNameTheMaterialAndValue) {
  MaterialDef d = soft(MaterialLaw::neo_hookean);
  d.poisson = 0.5;
  try {
    validate(d);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'soft': poisson = 0.5"), std::string::npos) << e.what();
  }
  d = soft(MaterialLaw::neo_hookean);
  d.young = 0.0;
  EXPECT_THROW(validate(d), Error);
  d.young = -3.0;
  EXPECT_THROW(make_material_params(d), Error);
  d = soft(MaterialLaw::neo_hookean);
  d.density = 0.0;
  EXPECT_THROW(validate(d), Error);
  d = soft(MaterialLaw::neo_hookean);
  d.damping = -1.0;
  EXPECT_THROW(validate(d), Error);
}

}  // namespace
}  // namespace sg
