#pragma once
// The tangent stiffness of deformable body 0 at the reference state by central differences of
// its elastic forces (no damping), independent of any assembled matrix: the vibration and
// damping-operator tests compare against it.
#include <Eigen/Dense>
#include <vector>

#include "model/internal_forces.h"

namespace sg::scenes {

inline Eigen::MatrixXd finite_difference_stiffness(const Model& model, double eps = 1e-6) {
  const int n = static_cast<int>(model.node_count());
  const int dofs = 2 * n;
  Eigen::MatrixXd k(dofs, dofs);
  std::vector<double> zero(static_cast<std::size_t>(n), 0.0);
  for (int c = 0; c < dofs; ++c) {
    std::vector<double> ux(zero), uy(zero), fxp(zero), fyp(zero), fxm(zero), fym(zero);
    auto& u = (c % 2 == 0) ? ux : uy;
    u[static_cast<std::size_t>(c / 2)] = eps;
    add_body_internal_forces(model, 0, ux.data(), uy.data(), zero.data(), zero.data(), fxp.data(),
                             fyp.data(), false);
    u[static_cast<std::size_t>(c / 2)] = -eps;
    add_body_internal_forces(model, 0, ux.data(), uy.data(), zero.data(), zero.data(), fxm.data(),
                             fym.data(), false);
    for (int r = 0; r < n; ++r) {
      const auto i = static_cast<std::size_t>(r);
      k(2 * r, c) = -(fxp[i] - fxm[i]) / (2 * eps);
      k(2 * r + 1, c) = -(fyp[i] - fym[i]) / (2 * eps);
    }
  }
  return k;
}

}  // namespace sg::scenes
