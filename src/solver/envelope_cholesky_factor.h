#pragma once
// The lower Cholesky factor L of a symmetric positive definite matrix, P A P^T = L L^T, kept
// in single precision over its envelope, in 8 x 8 tiles. The permutation P is a reverse
// Cuthill-McKee ordering of A's pattern (Boost.Graph), which gathers each row's entries near the
// diagonal. The rows come in blocks of 8; a block keeps the tiles from the one holding its rows'
// first nonzero column up to the diagonal, each row-major, and in place of the diagonal tile the
// inverse of L's diagonal block. Nothing outside the envelope is dropped: the entries of L
// before the first nonzero of A's row are exact zeros (they are sums of products of zeros), and
// so are those a tile adds around the envelope.
//
// Why: the grains' triangular solves run every step for every grain (2,000 of them in
// examples/shear-cell-full.toml). Stored by rows over the envelope (28.5 kB per 146-DOF grain of
// bench/scenes/imex-cell.toml), a solve was a chain of short dot products and axpys, one row
// waiting for the previous one's unknown: 2.7 us per grain, bound by the instructions per row
// and that chain, not by the bytes (3.2 us from memory). In tiles (34 kB, the 8 x 8 tiles round
// the envelope out), the products with the known unknowns are whole tiles (8 AVX2 multiplies
// and adds, the 8 rows' sums independent) and a block's own unknowns are one more tile product
// with the inverse diagonal block instead of 8 dependent rows: 1.8 us in cache, 2.1 us from L3
// (bench/results/debian12-2core/envelope_factor_solve.csv); at the papers' size (factors from
// memory, 178 -> 204 MiB) the imex step still gained about 5%.
//
// Determinism: the AVX2 kernels (chosen at run time where the processor has them) and the
// portable ones do the same multiplies and adds in the same order (8 partial sums per row, added
// pairwise in a fixed order, no fused multiply-add): the same bits on any x86-64 machine.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cstddef>
#include <vector>

namespace sg {

class EnvelopeCholeskyFactor {
 public:
  // The ordering of the next factorizations: reverse Cuthill-McKee of the graph of `pattern`'s
  // off-diagonal entries (its values are not read). Without a call: the identity.
  void order(const Eigen::SparseMatrix<double>& pattern);

  // Factors `a` (symmetric positive definite, in the original numbering; only its lower
  // triangle is read) in double precision in the ordering, keeps L's envelope in single
  // precision. False if `a` is not positive definite (the factor is then unusable).
  bool factor(const Eigen::MatrixXd& a);

  // x <- A^-1 x (original numbering): L y = P x a block of rows at a time (the tiles left of the
  // diagonal, then the inverse diagonal block), L^T z = y a block at a time from the last, then
  // x = P^T z.
  void solve_in_place(Eigen::VectorXf& x) const;
  // The same without the AVX2 kernels, for the test that both give the same bits.
  void solve_in_place_portable(Eigen::VectorXf& x) const;

  Eigen::Index size() const { return n_; }
  // Tiles and block offsets (the ordering and the scratch vector are a few n).
  std::size_t bytes() const {
    return tiles_.size() * sizeof(Tile) + block_start_.size() * sizeof(std::size_t) +
           first_tile_.size() * sizeof(int);
  }

  static constexpr int kTile = 8;  // rows and columns of a tile: one AVX2 register of floats
  struct alignas(32) Tile {
    float v[kTile * kTile];  // row-major
  };
  struct TileKernels;  // the AVX2 or the portable tile products (envelope_cholesky_factor.cpp)

 private:
  void store_tiles(const Eigen::MatrixXd& l);
  void solve_with(Eigen::VectorXf& x, const TileKernels& kernels) const;

  Eigen::Index n_ = 0;
  std::vector<int> order_;   // position k of the ordering holds original index order_[k]
  std::vector<Tile> tiles_;  // block b's: tiles_[block_start_[b] .. block_start_[b + 1]), the
                             // last its inverse diagonal block
  std::vector<std::size_t> block_start_;
  std::vector<int> first_tile_;  // block b's first tile column (its tiles: first_tile_[b] .. b)
  mutable Eigen::VectorXf permuted_;  // scratch of the solve (one per body: thread-safe per body)
};

}  // namespace sg
