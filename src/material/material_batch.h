#pragma once
// The constitutive laws of material.h evaluated for kSimdWidth Gauss points at once (one
// lane each), for the force kernel (model/internal_forces.cpp). Same formulas and the same
// order of floating-point operations as the scalar laws (which stay the reference, readable
// in Eigen), so that a lane gives the scalar result bit for bit except through the logarithm
// (batch_log below).
// Sums of more than two terms follow Eigen's order for a 2x2 matrix (column-major packets
// of two: (a00 + a01) + (a10 + a11)); the tests compare lanes with the scalar laws.
#include <cmath>
#include <utility>

#include "material/material.h"
#include "material/simd.h"

namespace sg {
inline namespace SG_SIMD_ISA {

// A 2x2 tensor per lane: xx = (0,0), xy = (0,1), yx = (1,0), yy = (1,1).
struct Tensor2B {
  DoubleBatch xx, xy, yx, yy;
};

struct ElasticBatch {
  Tensor2B first_piola;
  DoubleBatch energy_density;
};

struct ViscousBatch {
  Tensor2B first_piola;
  DoubleBatch power_density;
};

namespace batch_detail {

template <std::size_t... I>
inline DoubleBatch log_of_lanes(const DoubleBatch& x, std::index_sequence<I...>) {
  return DoubleBatch{std::log(x.get(I))...};
}

}  // namespace batch_detail

// ln x lane by lane: std::log of each lane, except in a SOFTGRAIN_NATIVE build (-march=native)
// on batches wider than 2, which uses xsimd's vector log. std::log keeps the bits of the scalar
// law, and the same bits whichever instruction set the kernel was compiled for (the default
// build's SSE2 kernel and its AVX2 one, model/force_kernel.h); on SSE2 it is also the faster
// (xsimd's log needs 64-bit integer vector operations that SSE2 lacks: 5.3-7.4 against
// 4.3-5.5 ns per value, g++ 12 -O3). xsimd's vector log at W = 8 takes 0.93 against 2.8 ns per
// value, within an ulp or two of std::log but not always the same bits (it fuses multiply-adds).
inline DoubleBatch batch_log(const DoubleBatch& x) {
#if defined(SOFTGRAIN_NATIVE_BUILD)
  if constexpr (kSimdWidth > 2) return xsimd::log(x);
#endif
  return batch_detail::log_of_lanes(x, std::make_index_sequence<kSimdWidth>());
}

namespace batch_detail {

// (a00 b00 + a01 b01) + (a10 b10 + a11 b11): Eigen's (a.array() * b.array()).sum().
inline DoubleBatch contract(const Tensor2B& a, const Tensor2B& b) {
  return (a.xx * b.xx + a.xy * b.xy) + (a.yx * b.yx + a.yy * b.yy);
}

// a^T b.
inline Tensor2B transpose_times(const Tensor2B& a, const Tensor2B& b) {
  return {a.xx * b.xx + a.yx * b.yx, a.xx * b.xy + a.yx * b.yy, a.xy * b.xx + a.yy * b.yx,
          a.xy * b.xy + a.yy * b.yy};
}

// a b.
inline Tensor2B times(const Tensor2B& a, const Tensor2B& b) {
  return {a.xx * b.xx + a.xy * b.yx, a.xx * b.xy + a.xy * b.yy, a.yx * b.xx + a.yy * b.yx,
          a.yx * b.xy + a.yy * b.yy};
}

// 0.5 (a + a^T).
inline Tensor2B symmetric_part(const Tensor2B& a) {
  const DoubleBatch half(0.5);
  return {half * (a.xx + a.xx), half * (a.xy + a.yx), half * (a.yx + a.xy), half * (a.yy + a.yy)};
}

// s I + t a, with the zero products of the identity kept (as Eigen evaluates it).
inline Tensor2B identity_plus(const DoubleBatch& s, const DoubleBatch& t, const Tensor2B& a) {
  const DoubleBatch zero = s * 0.0;
  return {s + t * a.xx, zero + t * a.xy, zero + t * a.yx, s + t * a.yy};
}

}  // namespace batch_detail

[[gnu::always_inline]] inline ElasticBatch elastic_response(const MaterialParams& m,
                                                            const Tensor2B& f) {
  const DoubleBatch mu(m.mu), lambda(m.lambda);
  switch (m.law) {
    case MaterialLaw::neo_hookean: {
      // material.cpp: P = mu (F - F^-T) + lambda ln J F^-T, W = mu/2 (I1 - 3) - mu ln J +
      // lambda/2 (ln J)^2.
      const DoubleBatch j = f.xx * f.yy - f.yx * f.xy;
      const DoubleBatch log_j = batch_log(j);
      const Tensor2B fit{f.yy / j, -f.yx / j, -f.xy / j, f.xx / j};
      const DoubleBatch i1_minus_3 =
          (f.xx * f.xx + f.xy * f.xy) + (f.yx * f.yx + f.yy * f.yy) - DoubleBatch(2.0);
      const DoubleBatch l = lambda * log_j;
      return {{mu * (f.xx - fit.xx) + l * fit.xx, mu * (f.xy - fit.xy) + l * fit.xy,
               mu * (f.yx - fit.yx) + l * fit.yx, mu * (f.yy - fit.yy) + l * fit.yy},
              DoubleBatch(0.5 * m.mu) * i1_minus_3 - mu * log_j +
                  DoubleBatch(0.5 * m.lambda) * log_j * log_j};
    }
    case MaterialLaw::saint_venant_kirchhoff: {
      // E = (F^T F - I)/2, S = lambda tr(E) I + 2 mu E, P = F S, W = lambda/2 tr(E)^2 + mu E:E.
      const DoubleBatch half(0.5), one(1.0);
      const Tensor2B c = batch_detail::transpose_times(f, f);
      const Tensor2B e{half * (c.xx - one), half * (c.xy - 0.0), half * (c.yx - 0.0),
                       half * (c.yy - one)};
      const DoubleBatch tr = e.xx + e.yy;
      const Tensor2B s = batch_detail::identity_plus(lambda * tr, DoubleBatch(2.0 * m.mu), e);
      return {batch_detail::times(f, s),
              DoubleBatch(0.5 * m.lambda) * tr * tr + mu * batch_detail::contract(e, e)};
    }
  }
  return {{DoubleBatch(0.0), DoubleBatch(0.0), DoubleBatch(0.0), DoubleBatch(0.0)},
          DoubleBatch(0.0)};
}

// material.h viscous_second_piola: alpha (lambda tr(E_dot) I + 2 mu E_dot).
inline Tensor2B viscous_second_piola(const MaterialParams& m, const Tensor2B& strain_rate) {
  const Tensor2B s =
      batch_detail::identity_plus(DoubleBatch(m.lambda) * (strain_rate.xx + strain_rate.yy),
                                  DoubleBatch(2.0 * m.mu), strain_rate);
  const DoubleBatch alpha(m.damping);
  return {alpha * s.xx, alpha * s.xy, alpha * s.yx, alpha * s.yy};
}

// material.h viscous_response, lane by lane; `rotation` is the body's (one for all lanes).
[[gnu::always_inline]] inline ViscousBatch viscous_response(const MaterialParams& m,
                                                            const Tensor2B& f,
                                                            const Tensor2B& f_rate,
                                                            const Mat2& rotation) {
  switch (m.damping_model) {
    case DampingModel::objective: {
      const Tensor2B strain_rate =
          batch_detail::symmetric_part(batch_detail::transpose_times(f, f_rate));
      const Tensor2B s = viscous_second_piola(m, strain_rate);
      return {batch_detail::times(f, s), batch_detail::contract(s, strain_rate)};
    }
    case DampingModel::corotational: {
      const Tensor2B r{DoubleBatch(rotation(0, 0)), DoubleBatch(rotation(0, 1)),
                       DoubleBatch(rotation(1, 0)), DoubleBatch(rotation(1, 1))};
      const Tensor2B strain_rate =
          batch_detail::symmetric_part(batch_detail::transpose_times(r, f_rate));
      const Tensor2B s = viscous_second_piola(m, strain_rate);
      return {batch_detail::times(r, s), batch_detail::contract(s, strain_rate)};
    }
    case DampingModel::reference_stiffness: {
      const Tensor2B strain_rate = batch_detail::symmetric_part(f_rate);
      const Tensor2B p = viscous_second_piola(m, strain_rate);
      return {p, batch_detail::contract(p, strain_rate)};
    }
  }
  return {{DoubleBatch(0.0), DoubleBatch(0.0), DoubleBatch(0.0), DoubleBatch(0.0)},
          DoubleBatch(0.0)};
}

}  // namespace SG_SIMD_ISA
}  // namespace sg
