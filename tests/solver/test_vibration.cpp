// The lowest non-rigid vibration frequency of a free elastic disc in plane strain, against
// the analytic solution (Love, "A treatise on the mathematical theory of elasticity", §5xx;
// Achenbach, "Wave propagation in elastic solids", §6.x: free vibrations of a circular
// cylinder in plane strain).
//
// Displacement potentials phi = A J_n(h r) cos(n t), psi = B J_n(k r) sin(n t), h = omega/c_p,
// k = omega/c_s, give u_r = U(r) cos(n t), u_t = V(r) sin(n t) with
//   U = f' + n g / r,  V = -n f / r - g',  f = A J_n(h r), g = B J_n(k r).
// Traction-free boundary r = a:
//   sigma_rr = (lambda + 2 mu) U' + lambda (U + n V) / r = 0
//   sigma_rt = mu (-n U / r + V' - V / r) = 0
// The frequencies are the roots of the 2x2 determinant in (A, B). The discrete spectrum is
// computed from the stiffness of the discretized disc (finite differences of the internal
// force kernel around the reference state) and the lumped mass matrix.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <numbers>

#include "model/internal_forces.h"
#include "scenes/finite_difference_stiffness.h"
#include "scenes/free_grains.h"

namespace sg {
namespace {

struct Radial {
  double u, du, v, dv;  // U, U', V, V' at r for one potential with unit amplitude
};

double bessel(int n, double x) {
  return std::cyl_bessel_j(static_cast<double>(n), x);
}
double bessel_d1(int n, double x) {
  return n == 0 ? -bessel(1, x) : 0.5 * (bessel(n - 1, x) - bessel(n + 1, x));
}
// J'' from Bessel's equation: x^2 J'' + x J' + (x^2 - n^2) J = 0.
double bessel_d2(int n, double x) {
  return -bessel_d1(n, x) / x - (1.0 - n * n / (x * x)) * bessel(n, x);
}

// Potential phi = J_n(h r): f = J_n(h r), g = 0.
Radial from_phi(int n, double h, double r) {
  const double f = bessel(n, h * r), df = h * bessel_d1(n, h * r),
               ddf = h * h * bessel_d2(n, h * r);
  return {df, ddf, -n * f / r, -n * (df / r - f / (r * r))};
}
// Potential psi = J_n(k r): f = 0, g = J_n(k r).
Radial from_psi(int n, double k, double r) {
  const double g = bessel(n, k * r), dg = k * bessel_d1(n, k * r),
               ddg = k * k * bessel_d2(n, k * r);
  return {n * g / r, n * (dg / r - g / (r * r)), -dg, -ddg};
}

double frequency_determinant(int n, double omega, double radius, double lambda, double mu,
                             double rho) {
  const double cp = std::sqrt((lambda + 2 * mu) / rho), cs = std::sqrt(mu / rho);
  const Radial a = from_phi(n, omega / cp, radius), b = from_psi(n, omega / cs, radius);
  auto srr = [&](const Radial& q) {
    return (lambda + 2 * mu) * q.du + lambda * (q.u + n * q.v) / radius;
  };
  auto srt = [&](const Radial& q) { return mu * (-n * q.u / radius + q.dv - q.v / radius); };
  return srr(a) * srt(b) - srr(b) * srt(a);
}

// Smallest positive root of the determinant for any n in 0..4: the lowest non-rigid mode.
double analytic_lowest_frequency(double radius, double lambda, double mu, double rho) {
  const double cs = std::sqrt(mu / rho);
  double best = 1e300;
  for (int n = 0; n <= 4; ++n) {
    auto d = [&](double w) { return frequency_determinant(n, w, radius, lambda, mu, rho); };
    const double step = 1e-3 * cs / radius;
    double w0 = 0.05 * cs / radius, d0 = d(w0);
    for (double w1 = w0 + step; w1 < 12.0 * cs / radius; w1 += step) {
      const double d1 = d(w1);
      if ((d0 < 0) != (d1 < 0)) {
        double lo = w1 - step, hi = w1;  // bisection
        for (int it = 0; it < 100; ++it) {
          const double mid = 0.5 * (lo + hi);
          if ((d(lo) < 0) == (d(mid) < 0))
            lo = mid;
          else
            hi = mid;
        }
        best = std::min(best, 0.5 * (lo + hi));
        break;
      }
      d0 = d1;
    }
  }
  return best;
}

TEST(Vibration, AnalyticTorsionalRootIsTheKnownConstant) {
  // n = 0 torsional mode: k a J_1'(k a) = J_1(k a), first root k a = 5.1356 (Achenbach).
  // With nu such that the breathing mode is higher, n = 0 alone must find it.
  const double lambda = 1.0, mu = 1.0, rho = 1.0, a = 1.0;
  auto d = [&](double w) { return frequency_determinant(0, w, a, lambda, mu, rho); };
  // d is the product of the breathing and torsional factors; check it vanishes at 5.1356.
  EXPECT_LT(std::abs(d(5.1356)), 1e-3 * std::abs(d(4.5)));
}

TEST(Vibration, LowestNonRigidFrequencyOfADiscMatchesTheAnalyticValue) {
  const double radius = 1.0, h = 0.1;
  Model model = scenes::single_disc(scenes::elastic_material(), radius, h);
  const MaterialParams& m = model.materials[0];
  const double omega_exact = analytic_lowest_frequency(radius, m.lambda, m.mu, m.density);

  const int n = static_cast<int>(model.node_count());
  const int dofs = 2 * n;
  const Eigen::MatrixXd k = scenes::finite_difference_stiffness(model);
  // Symmetric up to the finite-difference error: the Galerkin stiffness is symmetric.
  EXPECT_LT((k - k.transpose()).norm(), 1e-6 * k.norm());
  Eigen::VectorXd inv_sqrt_m(dofs);
  for (int i = 0; i < n; ++i)
    inv_sqrt_m(2 * i) = inv_sqrt_m(2 * i + 1) =
        1.0 / std::sqrt(model.nodes.mass[static_cast<std::size_t>(i)]);
  const Eigen::MatrixXd a =
      inv_sqrt_m.asDiagonal() * (0.5 * (k + k.transpose())) * inv_sqrt_m.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(a, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& lambda = eig.eigenvalues();
  // Three rigid modes (two translations, one rotation) at zero frequency.
  for (int i = 0; i < 3; ++i)
    EXPECT_LT(std::abs(lambda(i)), 1e-6 * lambda(3)) << i;
  const double omega_discrete = std::sqrt(lambda(3));
  for (int i = 0; i < 10; ++i)
    std::printf("mode %d: omega %.5f\n", i, std::sqrt(std::max(0.0, lambda(i))));
  std::printf(
      "lowest non-rigid: discrete %.6f, analytic %.6f (omega a / c_s = %.4f), error %.3f%%\n",
      omega_discrete, omega_exact, omega_exact * radius / std::sqrt(m.mu / m.density),
      100 * (omega_discrete / omega_exact - 1));
  EXPECT_NEAR(omega_discrete / omega_exact, 1.0, 0.02);  // issue requirement: 2%
  // The ovalling mode is doubly degenerate (cos 2t and sin 2t).
  EXPECT_NEAR(std::sqrt(lambda(4)) / omega_discrete, 1.0, 0.01);
}

// The lowest non-rigid angular frequency of a free disc's discretization (three rigid modes
// at zero checked), and the one after it (the other half of the doubly degenerate mode).
struct LowestModes {
  double first = 0.0, second = 0.0;
};
LowestModes lowest_non_rigid_modes(const Model& model) {
  const int n = static_cast<int>(model.node_count());
  const Eigen::MatrixXd k = scenes::finite_difference_stiffness(model);
  Eigen::VectorXd inv_sqrt_m(2 * n);
  for (int i = 0; i < n; ++i)
    inv_sqrt_m(2 * i) = inv_sqrt_m(2 * i + 1) =
        1.0 / std::sqrt(model.nodes.mass[static_cast<std::size_t>(i)]);
  const Eigen::MatrixXd a =
      inv_sqrt_m.asDiagonal() * (0.5 * (k + k.transpose())) * inv_sqrt_m.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(a, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& lambda = eig.eigenvalues();
  for (int i = 0; i < 3; ++i)
    EXPECT_LT(std::abs(lambda(i)), 1e-6 * lambda(3)) << i;
  return {std::sqrt(lambda(3)), std::sqrt(lambda(4))};
}

// Issue #32: the same closed form on a graded disc (contour spacing 0.1 as the uniform test,
// interior 0.3 at the centre, paper 003's ratio of 3), against the uniform disc of the same
// contour spacing. No spurious low mode: the lowest non-rigid one is the ovalling mode, doubly
// degenerate. Measured: graded 207 nodes, omega 4.5446 (-1.30%), its pair 4.5459; uniform
// 384 nodes, 4.5833 (-0.47%); analytic 4.6047. Grading saves 46% of the nodes for 0.8% of
// frequency; the bound is 1.6%.
TEST(Vibration, GradedDiscLowestFrequencyMatchesTheAnalyticValue) {
  const double radius = 1.0, h = 0.1, interior = 0.3;
  const Model graded = scenes::single_graded_disc(scenes::elastic_material(), radius, h, interior);
  const Model uniform = scenes::single_disc(scenes::elastic_material(), radius, h);
  const MaterialParams& m = graded.materials[0];
  const double omega_exact = analytic_lowest_frequency(radius, m.lambda, m.mu, m.density);
  const LowestModes g = lowest_non_rigid_modes(graded);
  const LowestModes u = lowest_non_rigid_modes(uniform);
  std::printf(
      "graded: %zu nodes, omega %.5f (%+.3f%%), pair %.5f; uniform: %zu nodes, omega "
      "%.5f (%+.3f%%); analytic %.5f\n",
      graded.node_count(), g.first, 100.0 * (g.first / omega_exact - 1.0), g.second,
      uniform.node_count(), u.first, 100.0 * (u.first / omega_exact - 1.0), omega_exact);
  EXPECT_LT(graded.node_count(), uniform.node_count());
  EXPECT_NEAR(g.first / omega_exact, 1.0, 0.016);
  EXPECT_NEAR(g.second / g.first, 1.0, 0.01);
}

}  // namespace
}  // namespace sg
