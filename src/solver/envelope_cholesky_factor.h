#pragma once
// The lower Cholesky factor L of a symmetric positive definite matrix, P A P^T = L L^T, kept
// in single precision and stored by rows over its envelope: row i holds L(i, f_i .. i - 1),
// where f_i is its first nonzero column, then 1 / L(i, i), contiguous, and the next row
// follows it. The permutation P is a reverse Cuthill-McKee ordering of A's pattern
// (Boost.Graph), which gathers each row's entries near the diagonal. Nothing outside the envelope
// is dropped: the entries of L before the first nonzero of A's row are exact zeros (they are sums
// of products of zeros), so the solve is that of the dense factor, summed in another order.
//
// Why: the grains' triangular solves are bound by the bytes they read once the factors do not
// stay in cache (every step, for each of the 2,000 grains of examples/shear-cell-full.toml).
// A grain couples each node with those of its MLS supports, so in the ordering its rows are
// short: 28.5 kB per grain of bench/scenes/imex-cell.toml against 36.4 kB by rows in the
// grain's own numbering (87 kB as full matrices); 178 MiB for the papers' 2,000 grains against
// 394 MiB for their whole lower triangles (softgrain info). Solve of a 146-DOF grain with the
// factors from memory: 3.0 us, against 5.5 us for the lower triangle packed column after
// column and 10 us from full matrices (bench/results/debian12-2core/envelope_factor_solve.csv).
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

  // x <- A^-1 x (original numbering): L y = P x by rows (dot products), then L^T z = y by
  // rows of L (axpy), x = P^T z.
  void solve_in_place(Eigen::VectorXf& x) const;

  Eigen::Index size() const { return n_; }
  // Values and row offsets (the ordering and the scratch vector are a few n).
  std::size_t bytes() const {
    return values_.size() * sizeof(float) + row_start_.size() * sizeof(std::size_t);
  }

 private:
  struct EnvelopeRow {
    const float* entries;  // L(i, i - below .. i - 1)
    Eigen::Index below;    // i - f_i
    float inverse_diagonal;
  };
  EnvelopeRow row(Eigen::Index i) const;

  Eigen::Index n_ = 0;
  std::vector<int> order_;              // position k of the ordering holds original index order_[k]
  std::vector<float> values_;           // row i: L(i, i + 1 - length_i .. i)
  std::vector<std::size_t> row_start_;  // row i is values_[row_start_[i] .. row_start_[i + 1])
  mutable Eigen::VectorXf permuted_;    // scratch of the solve (one per body: thread-safe per body)
};

}  // namespace sg
