#include "solver/packed_cholesky_factor.h"

#include "core/error.h"

namespace sg {

void PackedCholeskyFactor::assign(const Eigen::Ref<const Eigen::MatrixXd>& l) {
  SG_ASSERT(l.rows() == l.cols(), "a Cholesky factor is square");
  n_ = l.rows();
  values_.resize(static_cast<std::size_t>(n_ * (n_ + 1) / 2));
  float* column = values_.data();
  for (Eigen::Index j = 0; j < n_; ++j) {
    const Eigen::Index length = n_ - j;
    Eigen::Map<Eigen::VectorXf>(column, length) = l.col(j).tail(length).cast<float>();
    column += length;
  }
}

void PackedCholeskyFactor::solve_in_place(Eigen::VectorXf& x) const {
  SG_ASSERT(x.size() == n_, "the right-hand side has " << x.size() << " entries, not " << n_);
  using Segment = Eigen::Map<Eigen::VectorXf>;
  using Column = Eigen::Map<const Eigen::VectorXf>;
  // L y = b: y_j = b_j / L_jj, then b_i -= L_ij y_j below.
  const float* column = values_.data();
  for (Eigen::Index j = 0; j < n_; ++j) {
    const Eigen::Index below = n_ - j - 1;
    x[j] /= column[0];
    Segment(x.data() + j + 1, below) -= x[j] * Column(column + 1, below);
    column += below + 1;
  }
  // L^T x = y: x_j = (y_j - sum_i>j L_ij x_i) / L_jj, last row first.
  for (Eigen::Index j = n_ - 1; j >= 0; --j) {
    const Eigen::Index below = n_ - j - 1;
    column -= below + 1;
    x[j] = (x[j] - Column(column + 1, below).dot(Segment(x.data() + j + 1, below))) / column[0];
  }
}

}  // namespace sg
