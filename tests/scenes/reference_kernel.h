#pragma once
// The scalar force kernel as it was before the blocked SIMD layout (one Gauss point at a time
// over the CSR rows of Model::gauss_rows, the scalar laws of material.h): the reference the
// tests compare model/internal_forces.h with, and the baseline of bench_roofline.cpp.
#include <algorithm>
#include <cmath>
#include <vector>

#include "model/internal_forces.h"
#include "model/kinematics.h"

namespace sg::scenes {

inline BodyForceResult reference_body_internal_forces(const Model& model, BodyId body_id,
                                                      const double* ux, const double* uy,
                                                      const double* vx, const double* vy,
                                                      double* fx, double* fy, bool with_damping,
                                                      double* viscous_fx = nullptr,
                                                      double* viscous_fy = nullptr) {
  const Body& body = model.body(body_id);
  const MaterialParams& material = model.material(body.material);
  const bool damped = with_damping && material.damping > 0.0;
  const ShapeRows& rows = model.gauss_rows;
  const std::int32_t* offset = rows.offset.data();
  const std::int32_t* node = rows.node.data();
  const double* dndx = rows.dndx.data();
  const double* dndy = rows.dndy.data();

  // The corotational damping model turns its strain rate with the body's mean rotation at u.
  const Mat2 rotation = damped && material.damping_model == DampingModel::corotational
                            ? body_rotation(model, body, ux, uy).matrix()
                            : Mat2::Identity();
  BodyForceResult result;
  const bool split_viscous = damped && viscous_fx != nullptr;
  if (viscous_fx) std::fill(viscous_fx, viscous_fx + body.node_count(), 0.0);
  if (viscous_fy) std::fill(viscous_fy, viscous_fy + body.node_count(), 0.0);
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    const auto begin = offset[g], end = offset[g + 1];
    // Displacement gradient H = F - I and its rate, in one pass over the row (the row's
    // indices and gradients are loaded once).
    double h00 = 0, h01 = 0, h10 = 0, h11 = 0;
    double r00 = 0, r01 = 0, r10 = 0, r11 = 0;
    if (damped) {
      for (auto k = begin; k < end; ++k) {
        const auto j = node[k];
        const double gx = dndx[k], gy = dndy[k];
        h00 += ux[j] * gx;
        h01 += ux[j] * gy;
        h10 += uy[j] * gx;
        h11 += uy[j] * gy;
        r00 += vx[j] * gx;
        r01 += vx[j] * gy;
        r10 += vy[j] * gx;
        r11 += vy[j] * gy;
      }
    } else {
      for (auto k = begin; k < end; ++k) {
        const auto j = node[k];
        const double gx = dndx[k], gy = dndy[k];
        h00 += ux[j] * gx;
        h01 += ux[j] * gy;
        h10 += uy[j] * gx;
        h11 += uy[j] * gy;
      }
    }
    Mat2 f;
    f << 1.0 + h00, h01, h10, 1.0 + h11;
    const double jacobian = f.determinant();
    if (!(jacobian > 0.0) || !std::isfinite(jacobian)) {
      result.bad_gauss_point = g;
      result.bad_jacobian = jacobian;
      return result;
    }
    const ElasticResponse elastic = elastic_response(material, f);
    Mat2 p = elastic.first_piola;
    const double w = model.gauss_weight[static_cast<std::size_t>(g)];
    result.elastic_energy += w * elastic.energy_density;
    Mat2 p_viscous = Mat2::Zero();
    if (damped) {
      Mat2 f_rate;
      f_rate << r00, r01, r10, r11;
      const ViscousResponse viscous = viscous_response(material, f, f_rate, rotation);
      p_viscous = viscous.first_piola;
      p += p_viscous;
      result.damping_power += w * viscous.power_density;
    }
    // f_J -= w P grad0 N_J (and the viscous part apart, for the energy ledger).
    const double p00 = w * p(0, 0), p01 = w * p(0, 1), p10 = w * p(1, 0), p11 = w * p(1, 1);
    if (split_viscous) {
      const double q00 = w * p_viscous(0, 0), q01 = w * p_viscous(0, 1);
      const double q10 = w * p_viscous(1, 0), q11 = w * p_viscous(1, 1);
      for (auto k = begin; k < end; ++k) {
        const auto j = node[k];
        const double gx = dndx[k], gy = dndy[k];
        fx[j] -= p00 * gx + p01 * gy;
        fy[j] -= p10 * gx + p11 * gy;
        viscous_fx[j] -= q00 * gx + q01 * gy;
        viscous_fy[j] -= q10 * gx + q11 * gy;
      }
    } else {
      for (auto k = begin; k < end; ++k) {
        const auto j = node[k];
        const double gx = dndx[k], gy = dndy[k];
        fx[j] -= p00 * gx + p01 * gy;
        fy[j] -= p10 * gx + p11 * gy;
      }
    }
  }
  return result;
}

inline void reference_deformation_gradients(const Model& model, BodyId body_id, const double* ux,
                                            const double* uy, std::vector<Mat2>& gradients) {
  const Body& body = model.body(body_id);
  const ShapeRows& rows = model.gauss_rows;
  gradients.resize(static_cast<std::size_t>(body.gauss_end - body.gauss_begin));
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    double h00 = 0, h01 = 0, h10 = 0, h11 = 0;
    for (auto k = rows.offset[g]; k < rows.offset[g + 1]; ++k) {
      const auto j = rows.node[k];
      const double gx = rows.dndx[k], gy = rows.dndy[k];
      h00 += ux[j] * gx;
      h01 += ux[j] * gy;
      h10 += uy[j] * gx;
      h11 += uy[j] * gy;
    }
    Mat2& f = gradients[static_cast<std::size_t>(g - body.gauss_begin)];
    f << 1.0 + h00, h01, h10, 1.0 + h11;
  }
}
inline void reference_viscous_operator(const Model& model, BodyId body_id,
                                       const std::vector<Mat2>& gradients, const Mat2& rotation,
                                       const double* x, const double* y, double* out_x,
                                       double* out_y) {
  const Body& body = model.body(body_id);
  const MaterialParams& material = model.material(body.material);
  const ShapeRows& rows = model.gauss_rows;
  std::fill(out_x, out_x + body.node_count(), 0.0);
  std::fill(out_y, out_y + body.node_count(), 0.0);
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    const auto begin = rows.offset[g], end = rows.offset[g + 1];
    double r00 = 0, r01 = 0, r10 = 0, r11 = 0;
    for (auto k = begin; k < end; ++k) {
      const auto j = rows.node[k];
      const double gx = rows.dndx[k], gy = rows.dndy[k];
      r00 += x[j] * gx;
      r01 += x[j] * gy;
      r10 += y[j] * gx;
      r11 += y[j] * gy;
    }
    Mat2 f_rate;
    f_rate << r00, r01, r10, r11;
    const Mat2& f = gradients[static_cast<std::size_t>(g - body.gauss_begin)];
    const Mat2 p = model.gauss_weight[static_cast<std::size_t>(g)] *
                   viscous_response(material, f, f_rate, rotation).first_piola;
    for (auto k = begin; k < end; ++k) {
      const auto j = rows.node[k];
      const double gx = rows.dndx[k], gy = rows.dndy[k];
      out_x[j] += p(0, 0) * gx + p(0, 1) * gy;
      out_y[j] += p(1, 0) * gx + p(1, 1) * gy;
    }
  }
}

}  // namespace sg::scenes
