#pragma once
// The pieces of the force kernel (force_kernel_impl.h). A body's node fields are copied side by
// side into a small per-thread buffer (node j's K fields at K j: ux, uy, vx, vy for the forces),
// so that one row entry reads all the fields of its node in one vector load and adds its
// force terms to all of them in one vector read-modify-write: the vectors run across the fields
// of a node, the rows are the model's CSR rows (meshfree/shape_rows.h) without padding. The
// material laws then run across W = kSimdWidth Gauss points (one per lane,
// material/material_batch.h).
//
// Every sum keeps the order of the scalar kernel: a Gauss point sums its row in row order, and
// each node receives the terms of the body's Gauss points in increasing order, starting from the
// value its force array held. So results do not depend on the SIMD width or on the thread count.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "material/material_batch.h"
#include "meshfree/shape_rows.h"
#include "model/force_kernel.h"
#include "model/model.h"

namespace sg {
inline namespace SG_SIMD_ISA {
namespace row_kernel {

constexpr int W = kSimdWidth;

// K doubles of one node in `parts` batches (one AVX batch for K = 4, two SSE2 ones on
// baseline x86-64).
template <int K>
struct FieldBatch {
  using type =
      std::conditional_t<(kSimdWidth >= K), xsimd::make_sized_batch_t<double, K>, DoubleBatch>;
  static constexpr int size = static_cast<int>(type::size);
  static constexpr int parts = K / size;
};

// Room for a body's nodes with K fields each, node j at K j (per thread, force_kernel.h).
inline double* node_buffer(int fields, int nodes, int slot) {
  return force_kernel_scratch(static_cast<std::size_t>(fields * nodes), slot);
}

// buffer[K j + k] = fields[k][j] for k < K (fields[k] null: 0).
template <int K>
void interleave(int nodes, const std::array<const double*, 4>& fields, double* buffer) {
  for (int j = 0; j < nodes; ++j)
    for (int k = 0; k < K; ++k) {
      const double* field = fields[static_cast<std::size_t>(k)];
      buffer[K * j + k] = field ? field[j] : 0.0;
    }
}

// fields[k][j] = buffer[K j + k] for k < K, the non-null fields.
template <int K>
void deinterleave(int nodes, const double* buffer, const std::array<double*, 4>& fields) {
  for (int k = 0; k < K; ++k) {
    double* field = fields[static_cast<std::size_t>(k)];
    if (!field) continue;
    for (int j = 0; j < nodes; ++j)
      field[j] = buffer[K * j + k];
  }
}

// The model's rows (meshfree/shape_rows.h) as plain pointers: held in locals, they need no
// reloading after the kernel's vector stores (which may alias anything).
struct Rows {
  const std::int32_t* offset;
  const std::int32_t* node;
  const double* dndx;
  const double* dndy;
  explicit Rows(const ShapeRows& rows)
      : offset(rows.offset.data()),
        node(rows.node.data()),
        dndx(rows.dndx.data()),
        dndy(rows.dndy.data()) {}
};

// W consecutive Gauss points of a body, [first, first + lanes), lanes <= W; padding lanes
// (l >= lanes, the body's last chunk) have weight 0 and F = I.
struct Chunk {
  int first;
  int lanes;
};

// One Gauss point's sums over its row, field by field: d[k] = sum_r x_k(node_r) dN_r/dX, e[k]
// the same with dN/dY, in row order. For the displacements this is the displacement gradient
// H = F - I: H = [[d0, e0], [d1, e1]].
template <int K>
struct RowSums {
  using Batch = typename FieldBatch<K>::type;
  static constexpr int P = FieldBatch<K>::parts, S = FieldBatch<K>::size;
  std::array<Batch, P> sx, sy;

  RowSums() {
    sx.fill(Batch(0.0));
    sy.fill(Batch(0.0));
  }
  // Row entry r.
  void add(const Rows& rows, int r, const double* buffer) {
    const double* x = buffer + K * rows.node[r];
    const double gx = rows.dndx[r], gy = rows.dndy[r];
    for (int p = 0; p < P; ++p) {
      const Batch xj = Batch::load_aligned(x + p * S);
      sx[p] += xj * gx;
      sy[p] += xj * gy;
    }
  }
  void store(double* d, double* e) const {
    for (int p = 0; p < P; ++p) {
      sx[p].store_unaligned(d + p * S);
      sy[p].store_unaligned(e + p * S);
    }
  }
};

// The row sums of Gauss point g.
template <int K>
inline void row_sums(const Rows rows, int g, const double* buffer, double* d, double* e) {
  RowSums<K> s;
  for (auto r = rows.offset[g]; r < rows.offset[g + 1]; ++r)
    s.add(rows, r, buffer);
  s.store(d, e);
}

// buffer_j -= a dN_j/dX + b dN_j/dY over g's row (a, b: K values each, aligned), node after
// node in row order: f_J -= w P grad0 N_J for P = [a b] on the fields (x, y, ...).
template <int K>
inline void subtract_row_terms(const Rows rows, int g, const double* a, const double* b,
                               double* buffer) {
  using Batch = typename FieldBatch<K>::type;
  constexpr int P = FieldBatch<K>::parts, S = FieldBatch<K>::size;
  std::array<Batch, P> ca, cb;
  for (int p = 0; p < P; ++p) {
    ca[p] = Batch::load_aligned(a + p * S);
    cb[p] = Batch::load_aligned(b + p * S);
  }
  for (auto r = rows.offset[g]; r < rows.offset[g + 1]; ++r) {
    double* f = buffer + K * rows.node[r];
    const double gx = rows.dndx[r], gy = rows.dndy[r];
    for (int p = 0; p < P; ++p) {
      const Batch t = ca[p] * gx + cb[p] * gy;
      (Batch::load_aligned(f + p * S) - t).store_aligned(f + p * S);
    }
  }
}

// The chunk's row sums as tensors: lanes[k] holds field pair k's gradient [[d_2k, e_2k],
// [d_2k+1, e_2k+1]] (k = 0: displacement, 1: velocity) for each Gauss point of the chunk.
template <int K>
inline std::array<Tensor2B, K / 2> chunk_gradients(const Rows rows, const Chunk& c,
                                                   const double* buffer) {
  alignas(kSimdAlignment) std::array<std::array<double, W>, 2 * K> v;
  for (int l = c.lanes; l < W; ++l)  // padding lanes: H = 0, F = I
    for (auto& component : v)
      component[static_cast<std::size_t>(l)] = 0.0;
  for (int l = 0; l < c.lanes; ++l) {
    std::array<double, K> d, e;
    row_sums<K>(rows, c.first + l, buffer, d.data(), e.data());
    for (int k = 0; k < K; ++k) {
      const auto i = static_cast<std::size_t>(l), j = static_cast<std::size_t>(k);
      v[2 * j][i] = d[j];
      v[2 * j + 1][i] = e[j];
    }
  }
  auto lane = [&](int k) {
    return DoubleBatch::load_aligned(v[static_cast<std::size_t>(k)].data());
  };
  std::array<Tensor2B, K / 2> out;
  for (int k = 0; k < K / 2; ++k)
    out[static_cast<std::size_t>(k)] = {lane(4 * k), lane(4 * k + 1), lane(4 * k + 2),
                                        lane(4 * k + 3)};
  return out;
}

// f -= P grad0 N over the chunk's rows, lane after lane, for K / 2 stresses p[k] (already
// weighted) acting on field pair k of the buffer.
template <int K>
inline void subtract_chunk_terms(const Rows rows, const Chunk& c,
                                 const std::array<const Tensor2B*, K / 2>& p, double* buffer) {
  // Columns of each lane's P: a = (P_xx, P_yx, ...) multiplies dN/dX, b = (P_xy, P_yy, ...).
  alignas(kSimdAlignment) std::array<std::array<double, W>, 2 * K> v;
  for (int k = 0; k < K / 2; ++k) {
    const Tensor2B& s = *p[static_cast<std::size_t>(k)];
    s.xx.store_aligned(v[static_cast<std::size_t>(2 * k)].data());
    s.yx.store_aligned(v[static_cast<std::size_t>(2 * k + 1)].data());
    s.xy.store_aligned(v[static_cast<std::size_t>(K + 2 * k)].data());
    s.yy.store_aligned(v[static_cast<std::size_t>(K + 2 * k + 1)].data());
  }
  for (int l = 0; l < c.lanes; ++l) {
    alignas(kSimdAlignment) std::array<double, K> a, b;
    for (int k = 0; k < K; ++k) {
      a[static_cast<std::size_t>(k)] = v[static_cast<std::size_t>(k)][static_cast<std::size_t>(l)];
      b[static_cast<std::size_t>(k)] =
          v[static_cast<std::size_t>(K + k)][static_cast<std::size_t>(l)];
    }
    subtract_row_terms<K>(rows, c.first + l, a.data(), b.data(), buffer);
  }
}

// The chunk's Gauss weights (0 in padding lanes).
inline DoubleBatch chunk_weights(const Model& model, const Chunk& c) {
  alignas(kSimdAlignment) std::array<double, W> w{};
  for (int l = 0; l < c.lanes; ++l)
    w[static_cast<std::size_t>(l)] = model.gauss_weight[static_cast<std::size_t>(c.first + l)];
  return DoubleBatch::load_aligned(w.data());
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

// The first lane (in order) of the chunk whose det F is not a positive finite number, or -1.
inline int first_bad_lane(const Chunk& c, const DoubleBatch& jacobian) {
  if (xsimd::all((jacobian > DoubleBatch(0.0)) & xsimd::isfinite(jacobian))) return -1;
  alignas(kSimdAlignment) std::array<double, W> j;
  jacobian.store_aligned(j.data());
  for (int l = 0; l < c.lanes; ++l)
    if (const double v = j[static_cast<std::size_t>(l)]; !(v > 0.0) || !std::isfinite(v)) return l;
  return -1;
}

// sum += value[l] over the chunk's real lanes, in lane order (the scalar kernel's order).
inline void add_lanes(const Chunk& c, const DoubleBatch& value, double& sum) {
  alignas(kSimdAlignment) std::array<double, W> v;
  value.store_aligned(v.data());
  for (int l = 0; l < c.lanes; ++l)
    sum += v[static_cast<std::size_t>(l)];
}

}  // namespace row_kernel
}  // namespace SG_SIMD_ISA
}  // namespace sg
