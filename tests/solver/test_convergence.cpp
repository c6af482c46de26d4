// h-convergence on a non-homogeneous static problem with a closed-form solution: a free
// disc under the self-equilibrated radial body force b = beta x (the "rotating disc" load),
// plane strain, small strain. Linear elasticity gives (Timoshenko & Goodier §32, plane strain):
//   u_r(r) = C r - beta r^3 / (8 (lambda + 2 mu)),
//   C = beta a^2 (4 lambda + 6 mu) / (16 (lambda + mu)(lambda + 2 mu)),
// which makes sigma_rr(a) = 0. The static state is found by dynamic relaxation (explicit
// steps with a mass-proportional numerical damping tuned to the lowest mode); the load is
// small (strain ~1e-5) so the geometric non-linearity is far below the discretization error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/internal_forces.h"
#include "model/kinematics.h"
#include "scenes/free_grains.h"
#include "solver/stable_time_step.h"

namespace sg {
namespace {

double exact_radial_displacement(double r, double a, double beta, const MaterialParams& m) {
  const double c =
      beta * a * a * (4 * m.lambda + 6 * m.mu) / (16 * (m.lambda + m.mu) * (m.lambda + 2 * m.mu));
  return c * r - beta * r * r * r / (8 * (m.lambda + 2 * m.mu));
}

// Relative L2 error of the displacement over the Gauss points after relaxation.
double solve_and_measure(double h) {
  const double radius = 1.0, beta = 1e-4;
  Model model = scenes::single_disc(scenes::elastic_material(MaterialLaw::saint_venant_kirchhoff),
                                    radius, h, 6);
  const MaterialParams& m = model.materials[0];
  const Body& body = model.bodies[0];
  const std::size_t n = model.node_count();
  // Consistent load f_I = integral(N_I rho beta X).
  std::vector<double> load_x(n, 0.0), load_y(n, 0.0);
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    const Vec2 x = gauss_reference_position(model, 0, g);
    const double w = model.gauss_weight[static_cast<std::size_t>(g)];
    for (auto k = model.gauss_rows.offset[static_cast<std::size_t>(g)];
         k < model.gauss_rows.offset[static_cast<std::size_t>(g) + 1]; ++k) {
      const auto j = static_cast<std::size_t>(model.gauss_rows.node[static_cast<std::size_t>(k)]);
      load_x[j] +=
          w * model.gauss_rows.value[static_cast<std::size_t>(k)] * m.density * beta * x.x();
      load_y[j] +=
          w * model.gauss_rows.value[static_cast<std::size_t>(k)] * m.density * beta * x.y();
    }
  }
  // Dynamic relaxation: v <- (1 - c dt) v + dt f / m with c ~ 2 omega_min (critical damping of
  // the lowest mode, omega_min ~ 2.5 c_s / a).
  // 0.7 of the undamped limit: the mass-proportional damping lowers the stable step of
  // symplectic Euler (to about 2 sqrt(1 - c dt / 2) / omega).
  const double dt = 0.7 * critical_time_step(estimate_max_frequency(model, 0), 0.0);
  const double c = 2.0 * 2.5 * std::sqrt(m.mu / m.density) / radius;
  NodeState& s = model.nodes;
  double load_norm = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    load_norm += load_x[i] * load_x[i] + load_y[i] * load_y[i];
  load_norm = std::sqrt(load_norm);
  for (int it = 0; it < 200000; ++it) {
    for (std::size_t i = 0; i < n; ++i) {
      s.fx[i] = load_x[i];
      s.fy[i] = load_y[i];
    }
    add_internal_forces(model);
    double residual = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      residual += s.fx[i] * s.fx[i] + s.fy[i] * s.fy[i];
      s.vx[i] = (1 - c * dt) * s.vx[i] + dt * s.inverse_mass[i] * s.fx[i];
      s.vy[i] = (1 - c * dt) * s.vy[i] + dt * s.inverse_mass[i] * s.fy[i];
      s.ux[i] += dt * s.vx[i];
      s.uy[i] += dt * s.vy[i];
    }
    if (std::sqrt(residual) < 1e-9 * load_norm) {
      std::printf("h = %.3f: %zu nodes, relaxed in %d iterations\n", h, n, it);
      break;
    }
  }
  double error2 = 0.0, norm2 = 0.0;
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    const Vec2 x = gauss_reference_position(model, 0, g);
    Vec2 u(0, 0);
    for (auto k = model.gauss_rows.offset[static_cast<std::size_t>(g)];
         k < model.gauss_rows.offset[static_cast<std::size_t>(g) + 1]; ++k) {
      const auto j = static_cast<std::size_t>(model.gauss_rows.node[static_cast<std::size_t>(k)]);
      u += model.gauss_rows.value[static_cast<std::size_t>(k)] * Vec2(s.ux[j], s.uy[j]);
    }
    const double r = x.norm();
    const Vec2 exact =
        r > 0 ? Vec2(exact_radial_displacement(r, radius, beta, m) / r * x) : Vec2(0, 0);
    const double w = model.gauss_weight[static_cast<std::size_t>(g)];
    error2 += w * (u - exact).squaredNorm();
    norm2 += w * exact.squaredNorm();
  }
  return std::sqrt(error2 / norm2);
}

TEST(Convergence, DiscUnderRadialBodyForceConvergesAtSecondOrder) {
  const double spacings[3] = {0.2, 0.1, 0.05};
  double errors[3];
  for (int i = 0; i < 3; ++i)
    errors[i] = solve_and_measure(spacings[i]);
  const double order_1 = std::log(errors[0] / errors[1]) / std::log(2.0);
  const double order_2 = std::log(errors[1] / errors[2]) / std::log(2.0);
  std::printf("L2 displacement errors %.3e %.3e %.3e, observed orders %.2f %.2f\n", errors[0],
              errors[1], errors[2], order_1, order_2);
  // Linear MLS: O(h^2) in the L2 norm of the displacement. The polygonal contour and the
  // quadrature also err at O(h^2). We require an observed order of at least 1.6 on the
  // finest pair and a small error at the finest level.
  EXPECT_GT(order_2, 1.6);
  EXPECT_LT(errors[2], 1e-2);
}

}  // namespace
}  // namespace sg
