#include "material/material.h"

#include <cmath>

#include "core/error.h"

namespace sg {

const char* to_string(DampingModel model) {
  switch (model) {
    case DampingModel::objective:
      return "objective";
    case DampingModel::corotational:
      return "corotational";
    case DampingModel::reference_stiffness:
      return "reference_stiffness";
  }
  return "?";
}

const char* to_string(VolumetricFormulation formulation) {
  switch (formulation) {
    case VolumetricFormulation::standard:
      return "standard";
    case VolumetricFormulation::fbar:
      return "fbar";
  }
  return "?";
}

const char* to_string(MaterialLaw law) {
  switch (law) {
    case MaterialLaw::neo_hookean:
      return "neo_hookean";
    case MaterialLaw::saint_venant_kirchhoff:
      return "saint_venant_kirchhoff";
  }
  return "?";
}

void validate(const MaterialDef& def) {
  SG_VERIFY(def.young > 0.0 && std::isfinite(def.young),
            "material '" << def.name << "': young = " << def.young << ", expected > 0");
  SG_VERIFY(def.poisson > -1.0 && def.poisson < 0.5,
            "material '" << def.name << "': poisson = " << def.poisson
                         << ", expected -1 < poisson < 0.5 (0.5 is incompressible, which a "
                            "compressible law cannot represent)");
  SG_VERIFY(def.density > 0.0 && std::isfinite(def.density),
            "material '" << def.name << "': density = " << def.density << ", expected > 0");
  SG_VERIFY(def.damping >= 0.0 && std::isfinite(def.damping),
            "material '" << def.name << "': damping = " << def.damping << ", expected >= 0");
}

MaterialParams make_material_params(const MaterialDef& def) {
  validate(def);
  MaterialParams m;
  m.law = def.law;
  const double e = def.young, nu = def.poisson;
  m.lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  m.mu = e / (2.0 * (1.0 + nu));
  m.density = def.density;
  m.damping = def.damping;
  m.damping_model = def.damping_model;
  m.volumetric = def.volumetric;
  return m;
}

double p_wave_speed(const MaterialParams& m) {
  return std::sqrt((m.lambda + 2.0 * m.mu) / m.density);
}

ElasticResponse elastic_response(const MaterialParams& m, const Mat2& f) {
  switch (m.law) {
    case MaterialLaw::neo_hookean: {
      // W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2 with I1 = tr(F^T F) + 1 (F_zz = 1);
      // P = mu (F - F^-T) + lambda ln J F^-T (Belytschko, Liu & Moran, Nonlinear FE, eq. 5.4.57).
      const double j = f.determinant();
      const double log_j = std::log(j);
      Mat2 f_inv_t;
      f_inv_t << f(1, 1), -f(1, 0), -f(0, 1), f(0, 0);
      f_inv_t /= j;
      const double i1_minus_3 = f.squaredNorm() - 2.0;
      return {m.mu * (f - f_inv_t) + m.lambda * log_j * f_inv_t,
              0.5 * m.mu * i1_minus_3 - m.mu * log_j + 0.5 * m.lambda * log_j * log_j};
    }
    case MaterialLaw::saint_venant_kirchhoff: {
      // E = (F^T F - I)/2, S = lambda tr(E) I + 2 mu E, P = F S, W = lambda/2 tr(E)^2 + mu E:E.
      const Mat2 e = 0.5 * (f.transpose() * f - Mat2::Identity());
      const double tr = e.trace();
      const Mat2 s = m.lambda * tr * Mat2::Identity() + 2.0 * m.mu * e;
      return {f * s, 0.5 * m.lambda * tr * tr + m.mu * e.squaredNorm()};
    }
  }
  return {Mat2::Zero(), 0.0};
}

Mat2 viscous_second_piola(const MaterialParams& m, const Mat2& strain_rate) {
  return m.damping * (m.lambda * strain_rate.trace() * Mat2::Identity() + 2.0 * m.mu * strain_rate);
}

ViscousResponse viscous_response(const MaterialParams& m, const Mat2& f, const Mat2& f_rate,
                                 const Mat2& rotation) {
  switch (m.damping_model) {
    case DampingModel::objective: {
      // Green-Lagrange strain rate E_dot = sym(F^T F_dot): zero for any rigid motion.
      const Mat2 ft_fdot = f.transpose() * f_rate;
      const Mat2 strain_rate = 0.5 * (ft_fdot + ft_fdot.transpose());
      const Mat2 s_viscous = viscous_second_piola(m, strain_rate);
      return {f * s_viscous, (s_viscous.array() * strain_rate.array()).sum()};
    }
    case DampingModel::corotational: {
      // The small-strain rate in the body's rotated frame: zero for a rigid motion of the body.
      const Mat2 rt_fdot = rotation.transpose() * f_rate;
      const Mat2 strain_rate = 0.5 * (rt_fdot + rt_fdot.transpose());
      const Mat2 s_viscous = viscous_second_piola(m, strain_rate);
      return {rotation * s_viscous, (s_viscous.array() * strain_rate.array()).sum()};
    }
    case DampingModel::reference_stiffness: {
      // sigma_v = alpha C0 : sym(grad v): the force is alpha K0 v (K0 = sum w B^T C0 B).
      const Mat2 strain_rate = 0.5 * (f_rate + f_rate.transpose());
      const Mat2 p_viscous = viscous_second_piola(m, strain_rate);
      return {p_viscous, (p_viscous.array() * strain_rate.array()).sum()};
    }
  }
  SG_THROW("unknown damping model");
}

CauchyStress cauchy_stress(const MaterialParams& m, const Mat2& f) {
  const double j = f.determinant();
  const Mat2 sigma = elastic_response(m, f).first_piola * f.transpose() / j;
  double zz = 0.0;
  switch (m.law) {
    case MaterialLaw::neo_hookean:
      // sigma = mu/J (b - I) + lambda ln J / J I, with b_zz = 1.
      zz = m.lambda * std::log(j) / j;
      break;
    case MaterialLaw::saint_venant_kirchhoff: {
      // S_zz = lambda tr(E) (E_zz = 0), sigma_zz = F_zz S_zz F_zz / J.
      const Mat2 e = 0.5 * (f.transpose() * f - Mat2::Identity());
      zz = m.lambda * e.trace() / j;
      break;
    }
  }
  return {sigma(0, 0), sigma(1, 1), 0.5 * (sigma(0, 1) + sigma(1, 0)), zz};
}

double CauchyStress::von_mises() const {
  return std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) +
                   3.0 * xy * xy);
}

}  // namespace sg
