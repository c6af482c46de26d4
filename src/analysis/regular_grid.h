#pragma once
// The regular Eulerian grid of the coherence analysis (paper 002 §2.2: square mesh,
// spacing Delta x = Delta y = 1 grain diameter), periodic along x.
//
// Node (i, j) sits at (x0 + i hx, y0 + j hy), i in [0, nx), j in [0, ny); flat index
// j nx + i. Along x the spacing is adjusted to hx = L / nx, nx = round(L / spacing), so
// that the grid tiles the period exactly: node nx would be node 0 again. Along y the grid
// spans [y_min, y_max] with hy = spacing as asked (the last row may stop short of y_max).
#include <cstddef>

namespace sg {

struct RegularGrid {
  double x0 = 0.0, length = 1.0;  // periodic span [x0, x0 + length)
  double y0 = 0.0;
  int nx = 1, ny = 1;
  double hx = 1.0, hy = 1.0;

  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
  }
  double x(int i) const { return x0 + i * hx; }
  double y(int j) const { return y0 + j * hy; }
  // i wrapped into [0, nx).
  int wrap_i(int i) const { return ((i % nx) + nx) % nx; }
};

// Throws sg::Error unless length > 0, spacing > 0, y_max >= y_min.
RegularGrid make_periodic_grid(double x0, double length, double y_min, double y_max,
                               double spacing);

}  // namespace sg
