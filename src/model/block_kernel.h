#pragma once
// The pieces of the blocked force kernel (internal_forces.cpp): gathering a block's
// deformation gradients from the node arrays and scattering its forces back. One lane per
// Gauss point; every lane sums its row entries in the order of the scalar rows, and the
// scatter visits the lanes one after the other, so that each node receives the terms of its
// Gauss points in increasing order, as the scalar kernel adds them: the blocked kernel
// changes no sum, and results do not depend on the SIMD width.
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "material/material_batch.h"
#include "model/gauss_blocks.h"

namespace sg::block_kernel {

constexpr int W = kSimdWidth;

// One block's rows: entry (r, l) at r * W + l.
struct BlockRows {
  const std::int32_t* node;
  const double* dndx;
  const double* dndy;
  int rows;
  const std::int32_t* length;  // per lane
  const double* weight;        // per lane
  const std::int32_t* gauss;   // per lane
};

inline BlockRows block_rows(const GaussBlocks& blocks, int b) {
  const auto e = static_cast<std::size_t>(blocks.row_offset[static_cast<std::size_t>(b)]) * W;
  const auto lane = static_cast<std::size_t>(b) * W;
  return {blocks.node.data() + e,
          blocks.dndx.data() + e,
          blocks.dndy.data() + e,
          blocks.row_offset[static_cast<std::size_t>(b) + 1] -
              blocks.row_offset[static_cast<std::size_t>(b)],
          blocks.length.data() + lane,
          blocks.weight.data() + lane,
          blocks.gauss.data() + lane};
}

template <std::size_t... I>
inline DoubleBatch gather(const double* base, const std::int32_t* index,
                          std::index_sequence<I...>) {
  return DoubleBatch{base[index[I]]...};
}

// base[index[l]] in lane l.
inline DoubleBatch gather(const double* base, const std::int32_t* index) {
  return gather(base, index, std::make_index_sequence<W>());
}

// sum_r x_j (x) grad N_j over the rows of the block's lanes: the displacement gradient
// H = F - I for x = u, the rate F_dot for x = v.
inline Tensor2B gradient_sum(const BlockRows& rows, const double* x, const double* y) {
  DoubleBatch h00(0.0), h01(0.0), h10(0.0), h11(0.0);
  for (int r = 0; r < rows.rows; ++r) {
    const std::int32_t* j = rows.node + r * W;
    const DoubleBatch gx = DoubleBatch::load_aligned(rows.dndx + r * W);
    const DoubleBatch gy = DoubleBatch::load_aligned(rows.dndy + r * W);
    const DoubleBatch xj = gather(x, j), yj = gather(y, j);
    h00 += xj * gx;
    h01 += xj * gy;
    h10 += yj * gx;
    h11 += yj * gy;
  }
  return {h00, h01, h10, h11};
}

// The two sums of gradient_sum in one pass over the rows (displacement and velocity).
inline void gradient_sums(const BlockRows& rows, const double* ux, const double* uy,
                          const double* vx, const double* vy, Tensor2B& h, Tensor2B& rate) {
  DoubleBatch h00(0.0), h01(0.0), h10(0.0), h11(0.0);
  DoubleBatch r00(0.0), r01(0.0), r10(0.0), r11(0.0);
  for (int r = 0; r < rows.rows; ++r) {
    const std::int32_t* j = rows.node + r * W;
    const DoubleBatch gx = DoubleBatch::load_aligned(rows.dndx + r * W);
    const DoubleBatch gy = DoubleBatch::load_aligned(rows.dndy + r * W);
    const DoubleBatch uxj = gather(ux, j), uyj = gather(uy, j);
    const DoubleBatch vxj = gather(vx, j), vyj = gather(vy, j);
    h00 += uxj * gx;
    h01 += uxj * gy;
    h10 += uyj * gx;
    h11 += uyj * gy;
    r00 += vxj * gx;
    r01 += vxj * gy;
    r10 += vyj * gx;
    r11 += vyj * gy;
  }
  h = {h00, h01, h10, h11};
  rate = {r00, r01, r10, r11};
}

// F = I + H, as the scalar kernel forms it.
inline Tensor2B identity_plus(const Tensor2B& h) {
  const DoubleBatch one(1.0);
  return {one + h.xx, h.xy, h.yx, one + h.yy};
}

// w p, lane by lane.
inline Tensor2B weighted(const DoubleBatch& w, const Tensor2B& p) {
  return {w * p.xx, w * p.xy, w * p.yx, w * p.yy};
}

// The first lane (in order) holding a real Gauss point whose det F is not a positive finite
// number, or -1.
inline int first_bad_lane(const BlockRows& rows, const DoubleBatch& jacobian) {
  if (xsimd::all((jacobian > DoubleBatch(0.0)) & xsimd::isfinite(jacobian))) return -1;
  alignas(kSimdAlignment) std::array<double, W> j;
  jacobian.store_aligned(j.data());
  for (int l = 0; l < W; ++l)
    if (rows.gauss[l] >= 0 &&
        (!(j[static_cast<std::size_t>(l)] > 0.0) || !std::isfinite(j[static_cast<std::size_t>(l)])))
      return l;
  return -1;
}

// sum += value[l] over the real lanes, in lane order (the scalar kernel's order).
inline void add_lanes(const BlockRows& rows, const DoubleBatch& value, double& sum) {
  alignas(kSimdAlignment) std::array<double, W> v;
  value.store_aligned(v.data());
  for (int l = 0; l < W; ++l)
    if (rows.gauss[l] >= 0) sum += v[static_cast<std::size_t>(l)];
}

// The terms P grad N_j of every entry of the block, for `n` stresses: terms[(n r + c) W + l],
// c = 2 k for the x and 2 k + 1 for the y component of stress k. `terms` holds n W rows.rows
// doubles, aligned.
template <int N>
inline void force_terms(const BlockRows& rows, const std::array<const Tensor2B*, N>& p,
                        double* terms) {
  for (int r = 0; r < rows.rows; ++r) {
    const DoubleBatch gx = DoubleBatch::load_aligned(rows.dndx + r * W);
    const DoubleBatch gy = DoubleBatch::load_aligned(rows.dndy + r * W);
    for (int k = 0; k < N; ++k) {
      const Tensor2B& s = *p[static_cast<std::size_t>(k)];
      (s.xx * gx + s.xy * gy).store_aligned(terms + (2 * N * r + 2 * k) * W);
      (s.yx * gx + s.yy * gy).store_aligned(terms + (2 * N * r + 2 * k + 1) * W);
    }
  }
}

// f_j -= terms (Subtract) or += terms, lane after lane over each lane's real entries; f holds
// the 2 N arrays (x and y of each stress).
template <bool Subtract, int N>
inline void scatter(const BlockRows& rows, const double* terms,
                    const std::array<double*, 2 * N>& f) {
  for (int l = 0; l < W; ++l)
    for (int r = 0; r < rows.length[l]; ++r) {
      const auto j = rows.node[r * W + l];
      for (int c = 0; c < 2 * N; ++c) {
        const double t = terms[(2 * N * r + c) * W + l];
        if constexpr (Subtract)
          f[static_cast<std::size_t>(c)][j] -= t;
        else
          f[static_cast<std::size_t>(c)][j] += t;
      }
    }
}

}  // namespace sg::block_kernel
