#pragma once
// The lower Cholesky factor L of a symmetric positive definite matrix A = L L^T, kept in
// single precision and packed column by column: column j holds rows j..n-1, contiguous, and
// the next column follows it. The solves of A x = b read it as one stream, front to back then
// back to front.
//
// Why not Eigen's dense matrix: Eigen has no packed triangular storage, and a full n x n
// matrix's lower triangle is n separate runs of memory. When the factors do not stay in
// cache (the 420 grains of bench_softgrain PackedCholeskySolve: 18 MB of lower triangles read
// grain after grain) the solve of a 146-DOF grain took 11.8 us from a full matrix against 5.5
// us packed; in cache (60 grains) 4.8 us both (bench/results/debian12-2core/
// packed_factor_solve.csv). Half the memory, too: 0.4 GB less for the 2,000 grains of
// examples/shear-cell-full.toml.
#include <Eigen/Dense>
#include <cstddef>
#include <vector>

namespace sg {

class PackedCholeskyFactor {
 public:
  // Keeps the lower triangle of `l` (a factor L, as Eigen::LLT leaves it in its matrix),
  // rounded to single precision.
  void assign(const Eigen::Ref<const Eigen::MatrixXd>& l);

  // x <- A^-1 x = L^-T L^-1 x: forward substitution by columns (axpy), then backward
  // substitution by columns of L, that is rows of L^T (dot products).
  void solve_in_place(Eigen::VectorXf& x) const;

  Eigen::Index size() const { return n_; }
  std::size_t bytes() const { return values_.size() * sizeof(float); }

 private:
  Eigen::Index n_ = 0;
  std::vector<float> values_;  // n (n + 1) / 2 entries
};

}  // namespace sg
