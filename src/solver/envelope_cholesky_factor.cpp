#include "solver/envelope_cholesky_factor.h"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/cuthill_mckee_ordering.hpp>
#include <numeric>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "core/error.h"

namespace sg {

void EnvelopeCholeskyFactor::order(const Eigen::SparseMatrix<double>& pattern) {
  SG_ASSERT(pattern.rows() == pattern.cols(), "a Cholesky factor's pattern is square");
  using Graph =
      boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                            boost::property<boost::vertex_color_t, boost::default_color_type,
                                            boost::property<boost::vertex_degree_t, int>>>;
  const auto n = static_cast<std::size_t>(pattern.rows());
  Graph graph(n);
  for (Eigen::Index j = 0; j < pattern.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(pattern, j); it; ++it)
      if (it.row() > j)
        boost::add_edge(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(j), graph);
  std::vector<std::size_t> reverse(n);
  // Cuthill-McKee from a pseudo-peripheral vertex of each component, written back to front.
  boost::cuthill_mckee_ordering(graph, reverse.rbegin(), boost::get(boost::vertex_color, graph),
                                boost::make_degree_map(graph));
  order_.assign(reverse.begin(), reverse.end());
}

bool EnvelopeCholeskyFactor::factor(const Eigen::MatrixXd& a) {
  SG_ASSERT(a.rows() == a.cols(), "a Cholesky factor is square");
  n_ = a.rows();
  if (static_cast<Eigen::Index>(order_.size()) != n_) {
    order_.resize(static_cast<std::size_t>(n_));
    std::iota(order_.begin(), order_.end(), 0);
  }
  thread_local Eigen::MatrixXd l;  // P A P^T's lower triangle, then L (scratch)
  l.resize(n_, n_);
  for (Eigen::Index j = 0; j < n_; ++j)
    for (Eigen::Index i = j; i < n_; ++i) {
      const auto p = order_[static_cast<std::size_t>(i)], q = order_[static_cast<std::size_t>(j)];
      l(i, j) = p >= q ? a(p, q) : a(q, p);  // the lower triangle of a
    }
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> cholesky(l);
  if (cholesky.info() != Eigen::Success) return false;
  store_tiles(l);
  return true;
}

void EnvelopeCholeskyFactor::store_tiles(const Eigen::MatrixXd& l) {
  const Eigen::Index blocks = (n_ + kTile - 1) / kTile;
  block_start_.assign(static_cast<std::size_t>(blocks) + 1, 0);
  first_tile_.assign(static_cast<std::size_t>(blocks), 0);
  tiles_.clear();
  const auto entry = [&](Eigen::Index i, Eigen::Index j) {
    return i < n_ ? static_cast<float>(l(i, j)) : 0.0f;
  };
  for (Eigen::Index block = 0; block < blocks; ++block) {
    const Eigen::Index top = block * kTile, bottom = std::min(top + kTile, n_);
    // The block's first column: the smallest first nonzero column of its rows.
    Eigen::Index first = top;
    for (Eigen::Index i = top; i < bottom; ++i) {
      Eigen::Index f = 0;
      while (f < i && l(i, f) == 0.0)
        ++f;
      first = std::min(first, f);
    }
    const Eigen::Index first_tile = first / kTile;
    first_tile_[static_cast<std::size_t>(block)] = static_cast<int>(first_tile);
    for (Eigen::Index t = first_tile; t < block; ++t) {
      Tile& tile = tiles_.emplace_back();
      for (Eigen::Index r = 0; r < kTile; ++r)
        for (Eigen::Index c = 0; c < kTile; ++c)
          tile.v[r * kTile + c] = entry(top + r, t * kTile + c);
    }
    // The diagonal tile: the inverse of L's diagonal block (lower triangular, computed in double
    // precision), 0 in the rows and columns past n (whose unknowns then stay 0).
    const Eigen::Index size = bottom - top;
    const Eigen::MatrixXd inverse = l.block(top, top, size, size)
                                        .triangularView<Eigen::Lower>()
                                        .solve(Eigen::MatrixXd::Identity(size, size));
    Tile& diagonal = tiles_.emplace_back();
    for (Eigen::Index r = 0; r < kTile; ++r)
      for (Eigen::Index c = 0; c < kTile; ++c)
        diagonal.v[r * kTile + c] = r < size && c <= r ? static_cast<float>(inverse(r, c)) : 0.0f;
    block_start_[static_cast<std::size_t>(block) + 1] = tiles_.size();
  }
}

namespace {

using Tile = EnvelopeCholeskyFactor::Tile;
constexpr int kTile = EnvelopeCholeskyFactor::kTile;

// The tile kernels, in two versions with the same arithmetic, bit for bit: per row, kTile
// partial sums (one per column of the tile), each a multiply then an add (no fused
// multiply-add), added pairwise in a fixed order: (c, c + 4), then (c, c + 2), then (0, 1).

// sums_r = sum over the tiles of sum_c tile(r, c) known_c (the known unknowns of the tile's
// columns, tile t's at known + t kTile).
void tile_row_sums_portable(const Tile* tiles, Eigen::Index count, const float* known,
                            float* sums) {
  float lanes[kTile][kTile] = {};
  for (Eigen::Index t = 0; t < count; ++t)
    for (int r = 0; r < kTile; ++r)
      for (int c = 0; c < kTile; ++c)
        lanes[r][c] += tiles[t].v[r * kTile + c] * known[t * kTile + c];
  for (int r = 0; r < kTile; ++r) {
    float half[4];
    for (int c = 0; c < 4; ++c)
      half[c] = lanes[r][c] + lanes[r][c + 4];
    sums[r] = (half[0] + half[2]) + (half[1] + half[3]);
  }
}

// unknowns_c -= tile(r, c) z_r for the rows r from the last, for every tile (tile t's unknowns
// at unknowns + t kTile).
void subtract_tile_columns_portable(const Tile* tiles, Eigen::Index count, const float* z,
                                    float* unknowns) {
  for (Eigen::Index t = 0; t < count; ++t)
    for (int c = 0; c < kTile; ++c) {
      float v = unknowns[t * kTile + c];
      for (int r = kTile - 1; r >= 0; --r)
        v -= tiles[t].v[r * kTile + c] * z[r];
      unknowns[t * kTile + c] = v;
    }
}

#if defined(__x86_64__)
__attribute__((target("avx2"))) void tile_row_sums_avx2(const Tile* tiles, Eigen::Index count,
                                                        const float* known, float* sums) {
  __m256 lanes[kTile];
  for (__m256& l : lanes)
    l = _mm256_setzero_ps();
  for (Eigen::Index t = 0; t < count; ++t) {
    const __m256 y = _mm256_loadu_ps(known + t * kTile);
    for (int r = 0; r < kTile; ++r)
      lanes[r] = _mm256_add_ps(lanes[r], _mm256_mul_ps(_mm256_load_ps(tiles[t].v + r * kTile), y));
  }
  for (int r = 0; r < kTile; ++r) {
    const __m128 half = _mm_add_ps(_mm256_castps256_ps128(lanes[r]),
                                   _mm256_extractf128_ps(lanes[r], 1));  // c + (c + 4)
    const __m128 quarter = _mm_add_ps(half, _mm_movehl_ps(half, half));  // c + (c + 2)
    sums[r] = _mm_cvtss_f32(_mm_add_ss(quarter, _mm_shuffle_ps(quarter, quarter, 1)));
  }
}

__attribute__((target("avx2"))) void subtract_tile_columns_avx2(const Tile* tiles,
                                                                Eigen::Index count, const float* z,
                                                                float* unknowns) {
  __m256 zr[kTile];
  for (int r = 0; r < kTile; ++r)
    zr[r] = _mm256_set1_ps(z[r]);
  for (Eigen::Index t = 0; t < count; ++t) {
    __m256 v = _mm256_loadu_ps(unknowns + t * kTile);
    for (int r = kTile - 1; r >= 0; --r)
      v = _mm256_sub_ps(v, _mm256_mul_ps(_mm256_load_ps(tiles[t].v + r * kTile), zr[r]));
    _mm256_storeu_ps(unknowns + t * kTile, v);
  }
}
#endif

}  // namespace

struct EnvelopeCholeskyFactor::TileKernels {
  void (*row_sums)(const Tile*, Eigen::Index, const float*, float*);
  void (*subtract_columns)(const Tile*, Eigen::Index, const float*, float*);
};

namespace {

using TileKernels = EnvelopeCholeskyFactor::TileKernels;

constexpr TileKernels kPortable{tile_row_sums_portable, subtract_tile_columns_portable};

const TileKernels& best_kernels() {
#if defined(__x86_64__)
  static constexpr TileKernels kAvx2{tile_row_sums_avx2, subtract_tile_columns_avx2};
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) return kAvx2;
#endif
  return kPortable;
}

}  // namespace

void EnvelopeCholeskyFactor::solve_in_place(Eigen::VectorXf& x) const {
  solve_with(x, best_kernels());
}

void EnvelopeCholeskyFactor::solve_in_place_portable(Eigen::VectorXf& x) const {
  solve_with(x, kPortable);
}

void EnvelopeCholeskyFactor::solve_with(Eigen::VectorXf& x, const TileKernels& kernels) const {
  SG_ASSERT(x.size() == n_, "the right-hand side has " << x.size() << " entries, not " << n_);
  const Eigen::Index blocks = static_cast<Eigen::Index>(first_tile_.size());
  permuted_.resize(blocks * kTile);
  permuted_.tail(blocks * kTile - n_).setZero();  // the rows past n (their unknowns stay 0)
  for (Eigen::Index k = 0; k < n_; ++k)
    permuted_[k] = x[order_[static_cast<std::size_t>(k)]];
  float* y = permuted_.data();
  // L y = P b, a block of rows at a time: y_block = D^-1 (b_block - sum of the tiles left of the
  // diagonal times their unknowns), D the block's diagonal block of L (its inverse is stored).
  for (Eigen::Index block = 0; block < blocks; ++block) {
    const auto b = static_cast<std::size_t>(block);
    const Tile* tiles = tiles_.data() + block_start_[b];
    const Eigen::Index count = block - first_tile_[b];
    float sums[kTile];
    kernels.row_sums(tiles, count, y + first_tile_[b] * kTile, sums);
    float* own = y + block * kTile;
    float rest[kTile];
    for (int r = 0; r < kTile; ++r)
      rest[r] = own[r] - sums[r];
    kernels.row_sums(tiles + count, 1, rest, own);
  }
  // L^T z = y, the last block first: z_block = D^-T y_block (0 minus the products, negated:
  // the same bits as their sum), then the tiles left of the diagonal, transposed, times z_block
  // are subtracted from the unknowns of their columns.
  for (Eigen::Index block = blocks - 1; block >= 0; --block) {
    const auto b = static_cast<std::size_t>(block);
    const Tile* tiles = tiles_.data() + block_start_[b];
    const Eigen::Index count = block - first_tile_[b];
    float* own = y + block * kTile;
    float minus_z[kTile] = {};
    kernels.subtract_columns(tiles + count, 1, own, minus_z);
    for (int r = 0; r < kTile; ++r)
      own[r] = -minus_z[r];
    kernels.subtract_columns(tiles, count, own, y + first_tile_[b] * kTile);
  }
  for (Eigen::Index k = 0; k < n_; ++k)
    x[order_[static_cast<std::size_t>(k)]] = y[k];
}

}  // namespace sg
