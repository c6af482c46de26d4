#include "analysis/velocity_grid.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace sg {
namespace {

// Grains sorted into columns of width >= rho along x (periodic) and rows along y, so a
// node only looks at the 3 x 3 cells around it. Rebuilt per snapshot; not a hot loop.
struct CellList {
  int ncx = 1, ncy = 1;
  double cx = 1.0, cy = 1.0, y_lo = 0.0;
  std::vector<int> start;  // CSR over cells
  std::vector<int> items;

  int cell(int ix, int iy) const { return iy * ncx + ix; }
};

CellList build_cells(const std::vector<Vec2>& wrapped, const RegularGrid& g, double rho) {
  CellList c;
  c.ncx = std::max(1, static_cast<int>(std::floor(g.length / rho)));
  c.cx = g.length / c.ncx;
  double y_lo = g.y0, y_hi = g.y(g.ny - 1);
  for (const auto& p : wrapped) {
    y_lo = std::min(y_lo, p.y());
    y_hi = std::max(y_hi, p.y());
  }
  c.y_lo = y_lo;
  c.cy = rho;
  c.ncy = 1 + static_cast<int>(std::floor((y_hi - y_lo) / rho));
  const auto ncell = static_cast<std::size_t>(c.ncx * c.ncy);
  std::vector<int> count(ncell + 1, 0);
  std::vector<int> cell_of(wrapped.size());
  for (std::size_t k = 0; k < wrapped.size(); ++k) {
    const int ix = std::min(c.ncx - 1, static_cast<int>((wrapped[k].x() - g.x0) / c.cx));
    const int iy = std::min(c.ncy - 1, static_cast<int>((wrapped[k].y() - y_lo) / c.cy));
    cell_of[k] = c.cell(ix, iy);
    ++count[static_cast<std::size_t>(cell_of[k]) + 1];
  }
  for (std::size_t i = 1; i <= ncell; ++i)
    count[i] += count[i - 1];
  c.start = count;
  c.items.resize(wrapped.size());
  for (std::size_t k = 0; k < wrapped.size(); ++k)
    c.items[static_cast<std::size_t>(count[static_cast<std::size_t>(cell_of[k])]++)] =
        static_cast<int>(k);
  return c;
}

}  // namespace

VelocityGrid interpolate_velocity_grid(const GrainSnapshot& grains, const RegularGrid& grid,
                                       const VelocityFitParams& params) {
  const double rho = params.support_radius;
  SG_VERIFY(rho > 0.0, "velocity grid: support radius " << rho << " is not positive");
  SG_VERIFY(2.0 * rho < grid.length, "velocity grid: support radius "
                                         << rho << " must be below half the period "
                                         << grid.length);
  VelocityGrid out;
  out.grid = grid;
  out.velocity.assign(grid.size(), Vec2::Zero());
  out.valid.assign(grid.size(), 0);
  // Positions wrapped into the period [x0, x0 + L).
  std::vector<Vec2> wrapped(grains.size());
  for (std::size_t k = 0; k < grains.size(); ++k) {
    double x = std::fmod(grains.position[k].x() - grid.x0, grid.length);
    if (x < 0.0) x += grid.length;
    if (x >= grid.length) x -= grid.length;  // fmod of a tiny negative, rounded up
    wrapped[k] = Vec2(grid.x0 + x, grains.position[k].y());
  }
  if (grains.size() == 0) return out;
  const CellList cells = build_cells(wrapped, grid, rho);
  const double inv_rho = 1.0 / rho;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const Vec2 p(grid.x(i), grid.y(j));
      const int cx = std::min(cells.ncx - 1, static_cast<int>((p.x() - grid.x0) / cells.cx));
      const int cy = static_cast<int>(std::floor((p.y() - cells.y_lo) / cells.cy));
      // Moment matrix A = sum w b b^T and right-hand sides sum w b v, with the basis
      // b = [1, dx/rho, dy/rho] centred on the node (scaled: A is O(1) whatever rho).
      Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
      Eigen::Matrix<double, 3, 2> rhs = Eigen::Matrix<double, 3, 2>::Zero();
      int seen = 0;
      // ncx may be 1 or 2: visit each distinct column once.
      const int columns = std::min(3, cells.ncx);
      for (int ox = 0; ox < columns; ++ox) {
        const int ix = (cx - 1 + ox + cells.ncx) % cells.ncx;
        for (int iy = cy - 1; iy <= cy + 1; ++iy) {
          if (iy < 0 || iy >= cells.ncy) continue;
          const int c = cells.cell(ix, iy);
          for (int s = cells.start[static_cast<std::size_t>(c)];
               s < cells.start[static_cast<std::size_t>(c) + 1]; ++s) {
            const auto k = static_cast<std::size_t>(cells.items[static_cast<std::size_t>(s)]);
            double dx = wrapped[k].x() - p.x();
            // Nearest periodic image along x (exact periodicity; rho < L/2).
            if (dx > 0.5 * grid.length) dx -= grid.length;
            if (dx < -0.5 * grid.length) dx += grid.length;
            const double dy = wrapped[k].y() - p.y();
            const double q = std::sqrt(dx * dx + dy * dy) * inv_rho;
            if (q >= 1.0) continue;
            const double w = cubic_spline_weight(q);
            const Eigen::Vector3d b(1.0, dx * inv_rho, dy * inv_rho);
            a.noalias() += w * b * b.transpose();
            rhs.noalias() += w * b * grains.velocity[k].transpose();
            ++seen;
          }
        }
      }
      if (seen < params.min_grains) continue;
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
      eig.computeDirect(a, Eigen::EigenvaluesOnly);
      const auto lambda = eig.eigenvalues();  // ascending
      if (!(lambda(0) > params.min_eigen_ratio * lambda(2))) continue;
      // The fitted linear field evaluated at the node is its constant coefficient.
      const Eigen::Matrix<double, 3, 2> coef = a.ldlt().solve(rhs);
      const std::size_t n = grid.index(i, j);
      out.velocity[n] = Vec2(coef(0, 0), coef(0, 1));
      out.valid[n] = 1;
    }
  return out;
}

}  // namespace sg
