#pragma once
// The F-bar force kernel (material.h VolumetricFormulation::fbar), in the instruction set of
// the unit that includes it (force_kernel_impl.h): the same rows, batches and sum orders as the
// standard kernel, so that its default and AVX2 versions give the same bits and the result
// does not depend on the thread count.
//
// de Souza Neto, Peric, Dutko & Owen (1996), Int. J. Solids Struct. 33:3277, in plane strain
// (F_zz = 1) with a patch p of Gauss points (model/gauss_patches.h):
//   J_g = det F_g,  J_bar = sum_{g in p} w_g J_g / W_p,  W_p = sum_{g in p} w_g,
//   F_bar_g = a_g F_g,  a_g = (J_bar / J_g)^(1/2)       (so det F_bar_g = J_bar),
//   Pi = sum_g w_g W(F_bar_g)                          (the elastic energy booked).
// Its exact gradient: with P_bar = dW/dF at F_bar, q_g = P_bar_g : F_bar_g and, from
// dJ_g = J_g F_g^-T : dF_g and dJ_bar = sum_h (w_h / W_p) J_h F_h^-T : dF_h,
//   dPi = sum_g w_g P_bar_g : (a_g dF_g + 1/2 a_g F_g (dJ_bar / J_bar - dJ_g / J_g))
//       = sum_h w_h P_h : dF_h,
//   P_h = a_h P_bar_h + 1/2 ((J_h / J_bar) Q_p - q_h) F_h^-T,  Q_p = sum_{g in p} w_g q_g / W_p,
// and f_J -= w_h P_h grad0 N_J as in the standard kernel. The second term couples the points
// of a patch (through Q_p); for a homogeneous F it vanishes and P_h = P(F).
//
// The viscous stress keeps F, not F_bar: it is then linear in the velocities with the same
// symmetric operator as the standard form (the IMEX integrator's, force_kernel.h
// viscous_operator), and vanishes at rest, where locking stiffens the equilibria.
#include <algorithm>
#include <array>
#include <cmath>

#include "material/material_batch.h"
#include "model/force_kernel.h"
#include "model/row_kernel.h"

namespace sg {
inline namespace SG_SIMD_ISA {
namespace fbar_kernel {

using namespace row_kernel;

// Per-point arrays of a body (each padded to whole chunks): F, J, the rate F', a P_bar, q.
enum PointArray : int { kF = 0, kJ = 4, kRate = 5, kScaledP = 9, kQ = 13, kPointArrays = 14 };

struct PointArrays {
  double* base;
  int padded;  // points rounded up to a multiple of W
  double* at(int array, int offset) const { return base + array * padded + offset; }
  void store(int array, int offset, const DoubleBatch& v) const {
    v.store_aligned(at(array, offset));
  }
  DoubleBatch load(int array, int offset) const {
    return DoubleBatch::load_aligned(at(array, offset));
  }
  void store(int array, int offset, const Tensor2B& t) const {
    store(array, offset, t.xx);
    store(array + 1, offset, t.xy);
    store(array + 2, offset, t.yx);
    store(array + 3, offset, t.yy);
  }
  Tensor2B load_tensor(int array, int offset) const {
    return {load(array, offset), load(array + 1, offset), load(array + 2, offset),
            load(array + 3, offset)};
  }
};

// value[patch of each lane's point] (`padding` in padding lanes).
inline DoubleBatch patch_lanes(const Chunk& c, int offset, const int* patch, const double* value,
                               double padding) {
  alignas(kSimdAlignment) std::array<double, W> v;
  for (int l = 0; l < W; ++l)
    v[static_cast<std::size_t>(l)] = l < c.lanes ? value[patch[offset + l]] : padding;
  return DoubleBatch::load_aligned(v.data());
}

// mean[p] = sum_{g in p} w_g x_g / weight[p], the points in order.
inline void patch_means(int points, const int* patch, const double* w, const double* x,
                        const double* weight, int patches, double* mean) {
  std::fill(mean, mean + patches, 0.0);
  for (int g = 0; g < points; ++g)
    mean[patch[g]] += w[g] * x[g];
  for (int p = 0; p < patches; ++p)
    mean[p] /= weight[p];
}

// The body's forces with F-bar elasticity; KU, KF as in force_kernel_impl.h body_forces.
template <int KU, int KF>
BodyForceResult body_forces(const Model& model, const Body& body, const BodyArrays& a,
                            const Mat2& rotation) {
  const MaterialParams& material = model.material(body.material);
  const int nodes = body.node_count();
  double* state = node_buffer(KU, nodes, 0);
  double* force = node_buffer(KF, nodes, 1);
  interleave<KU>(nodes, {a.ux, a.uy, a.vx, a.vy}, state);
  interleave<KF>(nodes, {a.fx, a.fy, a.viscous_fx, a.viscous_fy}, force);
  const Rows rows(model.gauss_rows);
  const int points = body.gauss_end - body.gauss_begin;
  const int padded = (points + W - 1) / W * W;
  const PointArrays arrays{force_kernel_scratch(static_cast<std::size_t>(kPointArrays * padded), 2),
                           padded};
  const int patches = body.patch_count;
  double* patch_values = force_kernel_scratch(static_cast<std::size_t>(3 * patches), 3);
  double* patch_weight = patch_values;
  double* j_bar = patch_values + patches;
  double* q_bar = patch_values + 2 * patches;
  const int* patch = model.gauss_patch.data() + body.gauss_begin;
  const double* w = model.gauss_weight.data() + body.gauss_begin;
  BodyForceResult result;

  // 1. F (and its rate) at every point, and J = det F.
  for (int first = body.gauss_begin; first < body.gauss_end; first += W) {
    const Chunk c{first, std::min(W, body.gauss_end - first)};
    const int o = first - body.gauss_begin;
    const std::array<Tensor2B, KU / 2> gradients = chunk_gradients<KU>(rows, c, state);
    const Tensor2B f = identity_plus(gradients[0]);
    const DoubleBatch jacobian = f.xx * f.yy - f.yx * f.xy;
    if (const int bad = first_bad_lane(c, jacobian); bad >= 0) {
      result.bad_gauss_point = c.first + bad;
      result.bad_jacobian = jacobian.get(static_cast<std::size_t>(bad));
      return result;
    }
    arrays.store(kF, o, f);
    arrays.store(kJ, o, jacobian);
    if constexpr (KU == 4) arrays.store(kRate, o, gradients[1]);
  }
  std::fill(patch_weight, patch_weight + patches, 0.0);
  for (int g = 0; g < points; ++g)
    patch_weight[patch[g]] += w[g];
  patch_means(points, patch, w, arrays.at(kJ, 0), patch_weight, patches, j_bar);

  // 2. P_bar at F_bar = a F, the energy W(F_bar), q = P_bar : F_bar.
  const DoubleBatch half(0.5);
  for (int first = body.gauss_begin; first < body.gauss_end; first += W) {
    const Chunk c{first, std::min(W, body.gauss_end - first)};
    const int o = first - body.gauss_begin;
    const Tensor2B f = arrays.load_tensor(kF, o);
    const DoubleBatch scale =
        xsimd::sqrt(patch_lanes(c, o, patch, j_bar, 1.0) / arrays.load(kJ, o));
    const Tensor2B f_bar{scale * f.xx, scale * f.xy, scale * f.yx, scale * f.yy};
    const ElasticBatch elastic = elastic_response(material, f_bar);
    add_lanes(c, chunk_weights(model, c) * elastic.energy_density, result.elastic_energy);
    const Tensor2B& p = elastic.first_piola;
    arrays.store(kScaledP, o, Tensor2B{scale * p.xx, scale * p.xy, scale * p.yx, scale * p.yy});
    arrays.store(kQ, o, (p.xx * f_bar.xx + p.xy * f_bar.xy) + (p.yx * f_bar.yx + p.yy * f_bar.yy));
  }
  patch_means(points, patch, w, arrays.at(kQ, 0), patch_weight, patches, q_bar);

  // 3. P = a P_bar + 1/2 ((J / J_bar) Q - q) F^-T (plus the viscous stress at F), and
  // f_J -= w P grad0 N_J.
  for (int first = body.gauss_begin; first < body.gauss_end; first += W) {
    const Chunk c{first, std::min(W, body.gauss_end - first)};
    const int o = first - body.gauss_begin;
    const Tensor2B f = arrays.load_tensor(kF, o);
    const DoubleBatch j = arrays.load(kJ, o);
    const DoubleBatch coupling =
        half * ((j / patch_lanes(c, o, patch, j_bar, 1.0)) * patch_lanes(c, o, patch, q_bar, 0.0) -
                arrays.load(kQ, o));
    const Tensor2B fit{f.yy / j, -f.yx / j, -f.xy / j, f.xx / j};
    const Tensor2B scaled = arrays.load_tensor(kScaledP, o);
    Tensor2B p{scaled.xx + coupling * fit.xx, scaled.xy + coupling * fit.xy,
               scaled.yx + coupling * fit.yx, scaled.yy + coupling * fit.yy};
    const DoubleBatch weight = chunk_weights(model, c);
    Tensor2B viscous_part;
    if constexpr (KU == 4) {
      const ViscousBatch viscous =
          viscous_response(material, f, arrays.load_tensor(kRate, o), rotation);
      p = {p.xx + viscous.first_piola.xx, p.xy + viscous.first_piola.xy,
           p.yx + viscous.first_piola.yx, p.yy + viscous.first_piola.yy};
      add_lanes(c, weight * viscous.power_density, result.damping_power);
      viscous_part = weighted(weight, viscous.first_piola);
    }
    const Tensor2B total = weighted(weight, p);
    if constexpr (KF == 4)
      subtract_chunk_terms<4>(rows, c, {&total, &viscous_part}, force);
    else
      subtract_chunk_terms<2>(rows, c, {&total}, force);
  }
  deinterleave<KF>(nodes, force, {a.fx, a.fy, a.viscous_fx, a.viscous_fy});
  return result;
}

}  // namespace fbar_kernel
}  // namespace SG_SIMD_ISA
}  // namespace sg
