#pragma once
// Random displacements and velocities of every node of a model, for the force-kernel tests
// (test_force_kernel.cpp, test_fbar.cpp): u = 0.02 r + (0.05 x, -0.03 y) (strains of a few
// percent), v = r, r uniform in [-1, 1] per component, drawn in node order from `seed`.
#include <random>

#include "model/model.h"

namespace sg::scenes {

inline void set_random_motion(Model& model, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  NodeState& n = model.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    n.ux[i] = 0.02 * u(random) + 0.05 * n.ref_x[i];
    n.uy[i] = 0.02 * u(random) - 0.03 * n.ref_y[i];
    n.vx[i] = u(random);
    n.vy[i] = u(random);
  }
}

}  // namespace sg::scenes
