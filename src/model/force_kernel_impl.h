#pragma once
// The force kernel's functions (force_kernel.h), for the instruction set of the translation
// unit that includes this header: force_kernel_default.cpp (the build's flags) and
// force_kernel_avx2.cpp (AVX2). Everything here lives in that unit's inline namespace
// (material/simd.h), so the two compilations never share a function.
#include <algorithm>
#include <array>

#include "material/material_batch.h"
#include "model/fbar_kernel_impl.h"
#include "model/force_kernel.h"
#include "model/row_kernel.h"

namespace sg {
inline namespace SG_SIMD_ISA {
namespace force_kernel_impl {

using namespace row_kernel;

struct ChunkStress {
  Tensor2B total;    // w P
  Tensor2B viscous;  // w P_v (damped bodies)
};

// The stresses of one chunk's lanes at F = I + H with rate `rate` (damped), the energies
// added to `result` lane by lane.
inline ChunkStress chunk_stress(const MaterialParams& material, const Chunk& c,
                                const DoubleBatch& w, const Tensor2B& f, const Tensor2B* rate,
                                const Mat2& rotation, BodyForceResult& result) {
  const ElasticBatch elastic = elastic_response(material, f);
  add_lanes(c, w * elastic.energy_density, result.elastic_energy);
  Tensor2B p = elastic.first_piola;
  ChunkStress out;
  if (rate) {
    const ViscousBatch viscous = viscous_response(material, f, *rate, rotation);
    p = {p.xx + viscous.first_piola.xx, p.xy + viscous.first_piola.xy,
         p.yx + viscous.first_piola.yx, p.yy + viscous.first_piola.yy};
    add_lanes(c, w * viscous.power_density, result.damping_power);
    out.viscous = weighted(w, viscous.first_piola);
  }
  out.total = weighted(w, p);
  return out;
}

// F of a chunk's lanes into out[0 .. c.lanes).
inline void store_gradients(const Chunk& c, const Tensor2B& f, Mat2* out) {
  alignas(kSimdAlignment) std::array<std::array<double, W>, 4> v;
  f.xx.store_aligned(v[0].data());
  f.xy.store_aligned(v[1].data());
  f.yx.store_aligned(v[2].data());
  f.yy.store_aligned(v[3].data());
  for (int l = 0; l < c.lanes; ++l) {
    const auto i = static_cast<std::size_t>(l);
    out[l] << v[0][i], v[1][i], v[2][i], v[3][i];
  }
}

// The body's forces with KU state fields per node (2: u; 4: u and v, damped bodies) and KF
// force fields (2: f; 4: f and its viscous part).
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
  BodyForceResult result;
  for (int first = body.gauss_begin; first < body.gauss_end; first += W) {
    const Chunk c{first, std::min(W, body.gauss_end - first)};
    // Displacement gradient H = F - I and (damped) its rate, in one pass over the rows.
    const std::array<Tensor2B, KU / 2> gradients = chunk_gradients<KU>(rows, c, state);
    const Tensor2B f = identity_plus(gradients[0]);
    if (a.gradients) store_gradients(c, f, a.gradients + (c.first - body.gauss_begin));
    const DoubleBatch jacobian = f.xx * f.yy - f.yx * f.xy;
    if (const int bad = first_bad_lane(c, jacobian); bad >= 0) {
      result.bad_gauss_point = c.first + bad;
      result.bad_jacobian = jacobian.get(static_cast<std::size_t>(bad));
      return result;
    }
    const ChunkStress stress =
        chunk_stress(material, c, chunk_weights(model, c), f,
                     KU == 4 ? &gradients[KU / 2 - 1] : nullptr, rotation, result);
    // f_J -= w P grad0 N_J (and the viscous part apart, for the energy ledger).
    if constexpr (KF == 4)
      subtract_chunk_terms<4>(rows, c, {&stress.total, &stress.viscous}, force);
    else
      subtract_chunk_terms<2>(rows, c, {&stress.total}, force);
  }
  deinterleave<KF>(nodes, force, {a.fx, a.fy, a.viscous_fx, a.viscous_fy});
  return result;
}

inline BodyForceResult forces(const Model& model, const Body& body, const BodyArrays& a,
                              bool damped, const Mat2& rotation) {
  if (model.material(body.material).volumetric == VolumetricFormulation::fbar) {
    if (!damped) return fbar_kernel::body_forces<2, 2>(model, body, a, rotation);
    if (a.viscous_fx == nullptr) return fbar_kernel::body_forces<4, 2>(model, body, a, rotation);
    return fbar_kernel::body_forces<4, 4>(model, body, a, rotation);
  }
  if (!damped) return body_forces<2, 2>(model, body, a, rotation);
  if (a.viscous_fx == nullptr) return body_forces<4, 2>(model, body, a, rotation);
  return body_forces<4, 4>(model, body, a, rotation);
}

inline void deformation_gradients(const Model& model, const Body& body, const double* ux,
                                  const double* uy, Mat2* out) {
  const int nodes = body.node_count();
  double* state = node_buffer(2, nodes, 0);
  interleave<2>(nodes, {ux, uy, nullptr, nullptr}, state);
  const Rows rows(model.gauss_rows);
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    std::array<double, 2> d, e;
    row_sums<2>(rows, g, state, d.data(), e.data());
    out[g - body.gauss_begin] << 1.0 + d[0], e[0], d[1], 1.0 + e[1];
  }
}

// The deformation gradients of a chunk's lanes from the stored per-point ones (identity in
// padding lanes).
inline Tensor2B load_gradients(const Chunk& c, const Mat2* gradients, int gauss_begin) {
  alignas(kSimdAlignment) std::array<std::array<double, W>, 4> v;
  for (int l = 0; l < W; ++l) {
    const auto i = static_cast<std::size_t>(l);
    const Mat2 f = l < c.lanes ? gradients[c.first + l - gauss_begin] : Mat2::Identity();
    v[0][i] = f(0, 0);
    v[1][i] = f(0, 1);
    v[2][i] = f(1, 0);
    v[3][i] = f(1, 1);
  }
  return {DoubleBatch::load_aligned(v[0].data()), DoubleBatch::load_aligned(v[1].data()),
          DoubleBatch::load_aligned(v[2].data()), DoubleBatch::load_aligned(v[3].data())};
}

inline void viscous_operator(const Model& model, const Body& body, const Mat2* gradients,
                             const Mat2& rotation, const double* x, const double* y, double* out_x,
                             double* out_y) {
  const MaterialParams& material = model.material(body.material);
  const int nodes = body.node_count();
  double* state = node_buffer(2, nodes, 0);
  double* out = node_buffer(2, nodes, 1);
  interleave<2>(nodes, {x, y, nullptr, nullptr}, state);
  interleave<2>(nodes, {nullptr, nullptr, nullptr, nullptr}, out);
  const Rows rows(model.gauss_rows);
  for (int first = body.gauss_begin; first < body.gauss_end; first += W) {
    const Chunk c{first, std::min(W, body.gauss_end - first)};
    const Tensor2B f_rate = chunk_gradients<2>(rows, c, state)[0];
    const Tensor2B f = load_gradients(c, gradients, body.gauss_begin);
    const Tensor2B p = weighted(chunk_weights(model, c),
                                viscous_response(material, f, f_rate, rotation).first_piola);
    // out = C x = -f_v(x): the terms added, where the forces subtract them (negation is
    // exact, so these are the bits of adding p's terms).
    const Tensor2B minus_p{-p.xx, -p.xy, -p.yx, -p.yy};
    subtract_chunk_terms<2>(rows, c, {&minus_p}, out);
  }
  deinterleave<2>(nodes, out, {out_x, out_y, nullptr, nullptr});
}

// This unit's kernel.
inline ForceKernel kernel() {
  return {xsimd::default_arch::name(), &forces, &deformation_gradients, &viscous_operator};
}

}  // namespace force_kernel_impl
}  // namespace SG_SIMD_ISA
}  // namespace sg
