#pragma once
// A uniform bucket grid over a fixed set of points, for neighbour queries during
// discretization (MLS supports, k nearest neighbours). Built once per body; not used
// in the time loop (the contact broad phase has its own structure).
// for_each_within takes a std::function: a type-erased call per visited point, which
// docs/architecture.md §Conventions 2 keeps out of time steps; here it runs at model build only,
// and a template would put the grid's code into every caller.
#include <functional>
#include <span>
#include <vector>

#include "geometry/vec2.h"

namespace sg {

class PointGrid {
 public:
  // `cell_size` > 0; points are copied.
  PointGrid(std::span<const Vec2> points, double cell_size);

  // Calls visit(index) for every point within `radius` of `center` (distance < radius),
  // in increasing index order.
  void for_each_within(const Vec2& center, double radius,
                       const std::function<void(int)>& visit) const;

  // Distance from points[i] to its k-th nearest other point (k >= 1).
  double kth_neighbour_distance(int i, int k) const;

  std::size_t size() const { return points_.size(); }

 private:
  std::vector<Vec2> points_;
  Vec2 origin_;
  double cell_size_;
  int nx_ = 1, ny_ = 1;
  std::vector<int>
      cell_start_;  // CSR: points of cell c are order_[cell_start_[c] .. cell_start_[c+1])
  std::vector<int> order_;
  int cell_x(double x) const;
  int cell_y(double y) const;
};

}  // namespace sg
