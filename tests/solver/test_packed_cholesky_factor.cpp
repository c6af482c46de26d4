#include "solver/packed_cholesky_factor.h"

#include <gtest/gtest.h>

#include <random>

namespace sg {
namespace {

// A symmetric positive definite matrix of condition number about 10 (B B^T / n + I, B with
// entries uniform in [-1, 1]), from a fixed seed.
Eigen::MatrixXd well_conditioned(Eigen::Index n, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::MatrixXd b(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      b(i, j) = entry(generator);
  Eigen::MatrixXd a = b * b.transpose() / static_cast<double>(n);
  a.diagonal().array() += 1.0;
  return a;
}

// The packed single-precision solve is A^-1 b to single-precision round-off, for sizes that
// cross every column count (1, 2, a grain's 146 DOFs, a papers' grain's 422): a wrong column
// offset or a transposed pass is off by order one.
TEST(PackedCholeskyFactor, SolvesTheSystemToSinglePrecisionRoundOff) {
  for (const Eigen::Index n : {1, 2, 3, 146, 422}) {
    const Eigen::MatrixXd a = well_conditioned(n, static_cast<unsigned>(n));
    const Eigen::LLT<Eigen::MatrixXd> cholesky(a);
    ASSERT_EQ(cholesky.info(), Eigen::Success);
    PackedCholeskyFactor factor;
    factor.assign(cholesky.matrixLLT());
    EXPECT_EQ(factor.size(), n);
    EXPECT_EQ(factor.bytes(), static_cast<std::size_t>(n * (n + 1) / 2) * sizeof(float));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    const Eigen::VectorXd exact = cholesky.solve(b);
    Eigen::VectorXf x = b.cast<float>();
    factor.solve_in_place(x);
    const double relative = (x.cast<double>() - exact).norm() / exact.norm();
    // float epsilon 6e-8 times the condition number (about 10) and a small multiple.
    EXPECT_LT(relative, 5e-6) << "n = " << n;
  }
}

// Only the lower triangle is read: what lies above the diagonal of the matrix it was given
// (LLT keeps A's upper triangle there) changes nothing.
TEST(PackedCholeskyFactor, ReadsOnlyTheLowerTriangle) {
  const Eigen::MatrixXd a = well_conditioned(40, 7);
  Eigen::MatrixXd l = Eigen::LLT<Eigen::MatrixXd>(a).matrixLLT();
  PackedCholeskyFactor clean, dirty;
  clean.assign(l);
  l.triangularView<Eigen::StrictlyUpper>().setConstant(1e30);
  dirty.assign(l);
  Eigen::VectorXf x = Eigen::VectorXf::Ones(40), y = x;
  clean.solve_in_place(x);
  dirty.solve_in_place(y);
  EXPECT_EQ(x, y);
}

}  // namespace
}  // namespace sg
