#include "solver/envelope_cholesky_factor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
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

// A grain-like operator: M + K on an m x m grid of nodes (2 DOFs each) coupled with the
// nodes within distance 2, numbered in a shuffled order (as a mesher may leave them), so that
// only an ordering brings the entries near the diagonal.
Eigen::MatrixXd shuffled_grid_operator(int m, unsigned seed) {
  const int nodes = m * m;
  std::vector<int> label(static_cast<std::size_t>(nodes));
  std::iota(label.begin(), label.end(), 0);
  std::shuffle(label.begin(), label.end(), std::mt19937(seed));
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * nodes, 2 * nodes);
  for (int p = 0; p < nodes; ++p)
    for (int q = 0; q < nodes; ++q) {
      const int dx = p % m - q % m, dy = p / m - q / m;
      if (p == q || dx * dx + dy * dy > 4) continue;
      const int i = 2 * label[static_cast<std::size_t>(p)],
                j = 2 * label[static_cast<std::size_t>(q)];
      a.block<2, 2>(i, j) = Eigen::Matrix2d::Constant(-0.1 / (dx * dx + dy * dy));
    }
  // Diagonally dominant: positive definite.
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    a(i, i) = 1.0 + a.row(i).cwiseAbs().sum();
  return a;
}

double relative_error(const EnvelopeCholeskyFactor& factor, const Eigen::MatrixXd& a) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  const Eigen::VectorXd exact = a.llt().solve(b);
  Eigen::VectorXf x = b.cast<float>();
  factor.solve_in_place(x);
  return (x.cast<double>() - exact).norm() / exact.norm();
}

// The single-precision solve is A^-1 b to single-precision round-off, for sizes that cross
// every tile boundary (1, 2, 3, a grain's 146 DOFs, a papers' grain's 422: a last block of 1,
// 2, 3, 2 and 6 rows): a wrong tile offset or a transposed pass is off by order one. A dense
// matrix's envelope is its lower triangle: all the tiles of the lower block triangle.
TEST(EnvelopeCholeskyFactor, SolvesTheSystemToSinglePrecisionRoundOff) {
  for (const Eigen::Index n : {1, 2, 3, 146, 422}) {
    const Eigen::MatrixXd a = well_conditioned(n, static_cast<unsigned>(n));
    EnvelopeCholeskyFactor factor;
    ASSERT_TRUE(factor.factor(a));
    EXPECT_EQ(factor.size(), n);
    const auto blocks = static_cast<std::size_t>((n + 7) / 8);
    EXPECT_EQ(factor.bytes(), blocks * (blocks + 1) / 2 * 64 * sizeof(float) +
                                  (blocks + 1) * sizeof(std::size_t) + blocks * sizeof(int));
    // float epsilon 6e-8 times the condition number (about 10) and a small multiple.
    EXPECT_LT(relative_error(factor, a), 5e-6) << "n = " << n;
  }
}

// On a sparse operator numbered at random, the ordering shrinks the envelope to a fraction of
// the lower triangle (a band of about 2 m nodes on the m x m grid, rounded out to whole 8 x 8
// tiles) and the solve, permuted in and out, is still A^-1 b. Without the ordering the envelope
// stays nearly the whole triangle.
TEST(EnvelopeCholeskyFactor, TheOrderingShrinksTheEnvelopeAndKeepsTheSolution) {
  const int m = 12;
  const Eigen::MatrixXd a = shuffled_grid_operator(m, 3);
  const Eigen::Index n = a.rows();
  const std::size_t triangle = static_cast<std::size_t>(n * (n + 1) / 2) * sizeof(float);
  EnvelopeCholeskyFactor plain, ordered;
  ASSERT_TRUE(plain.factor(a));
  ordered.order(a.sparseView());
  ASSERT_TRUE(ordered.factor(a));
  EXPECT_GT(plain.bytes(), 8 * triangle / 10);
  EXPECT_LT(ordered.bytes(), 35 * triangle / 100);
  EXPECT_LT(relative_error(plain, a), 5e-6);
  EXPECT_LT(relative_error(ordered, a), 5e-6);
}

// Only the lower triangle is read: what lies above the diagonal changes nothing.
TEST(EnvelopeCholeskyFactor, ReadsOnlyTheLowerTriangle) {
  const Eigen::MatrixXd a = shuffled_grid_operator(5, 7);
  Eigen::MatrixXd dirty_a = a;
  dirty_a.triangularView<Eigen::StrictlyUpper>().setConstant(1e30);
  EnvelopeCholeskyFactor clean, dirty;
  clean.order(a.sparseView());
  dirty.order(a.sparseView());
  ASSERT_TRUE(clean.factor(a));
  ASSERT_TRUE(dirty.factor(dirty_a));
  Eigen::VectorXf x = Eigen::VectorXf::Ones(a.rows()), y = x;
  clean.solve_in_place(x);
  dirty.solve_in_place(y);
  EXPECT_EQ(x, y);
}

// The AVX2 tile kernels (chosen where the processor has them) and the portable ones add the
// same products in the same order: the same bits, so that results do not depend on the machine.
TEST(EnvelopeCholeskyFactor, TheAvx2AndPortableSolvesGiveTheSameBits) {
  for (const int m : {3, 12}) {
    const Eigen::MatrixXd a = shuffled_grid_operator(m, 5);
    EnvelopeCholeskyFactor factor;
    factor.order(a.sparseView());
    ASSERT_TRUE(factor.factor(a));
    Eigen::VectorXf best = Eigen::VectorXf::LinSpaced(a.rows(), -1.0f, 2.0f), portable = best;
    factor.solve_in_place(best);
    factor.solve_in_place_portable(portable);
    EXPECT_EQ(best, portable) << "m = " << m;
  }
}

// A matrix that is not positive definite is refused.
TEST(EnvelopeCholeskyFactor, RefusesAnIndefiniteMatrix) {
  Eigen::MatrixXd a = well_conditioned(10, 1);
  a(4, 4) = -1.0;
  EnvelopeCholeskyFactor factor;
  EXPECT_FALSE(factor.factor(a));
}

}  // namespace
}  // namespace sg
