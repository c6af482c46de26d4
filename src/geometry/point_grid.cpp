#include "geometry/point_grid.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace sg {

PointGrid::PointGrid(std::span<const Vec2> points, double cell_size)
    : points_(points.begin(), points.end()), cell_size_(cell_size) {
  SG_ASSERT(cell_size > 0.0, "cell size " << cell_size);
  if (points_.empty()) {
    origin_ = Vec2::Zero();
    cell_start_.assign(2, 0);
    return;
  }
  Vec2 lo = points_.front(), hi = points_.front();
  for (const Vec2& p : points_) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  origin_ = lo;
  nx_ = std::max(1, static_cast<int>((hi.x() - lo.x()) / cell_size_) + 1);
  ny_ = std::max(1, static_cast<int>((hi.y() - lo.y()) / cell_size_) + 1);
  // Guard against degenerate huge grids (a thin strip with a tiny cell): cap the cell count.
  while (static_cast<double>(nx_) * ny_ > 4.0 * static_cast<double>(points_.size()) + 64.0) {
    cell_size_ *= 1.5;
    nx_ = std::max(1, static_cast<int>((hi.x() - lo.x()) / cell_size_) + 1);
    ny_ = std::max(1, static_cast<int>((hi.y() - lo.y()) / cell_size_) + 1);
  }
  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  std::vector<int> count(cells + 1, 0);
  std::vector<int> cell_of(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    cell_of[i] = cell_y(points_[i].y()) * nx_ + cell_x(points_[i].x());
    ++count[static_cast<std::size_t>(cell_of[i]) + 1];
  }
  for (std::size_t c = 0; c < cells; ++c)
    count[c + 1] += count[c];
  cell_start_ = count;
  order_.resize(points_.size());
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (std::size_t i = 0; i < points_.size(); ++i)
    order_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_of[i])]++)] =
        static_cast<int>(i);
}

int PointGrid::cell_x(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - origin_.x()) / cell_size_)), 0, nx_ - 1);
}
int PointGrid::cell_y(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - origin_.y()) / cell_size_)), 0, ny_ - 1);
}

void PointGrid::for_each_within(const Vec2& center, double radius,
                                const std::function<void(int)>& visit) const {
  if (points_.empty()) return;
  const int x0 = cell_x(center.x() - radius), x1 = cell_x(center.x() + radius);
  const int y0 = cell_y(center.y() - radius), y1 = cell_y(center.y() + radius);
  std::vector<int> found;
  const double r2 = radius * radius;
  for (int cy = y0; cy <= y1; ++cy)
    for (int cx = x0; cx <= x1; ++cx) {
      const std::size_t c = static_cast<std::size_t>(cy * nx_ + cx);
      for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const int i = order_[static_cast<std::size_t>(k)];
        if ((points_[static_cast<std::size_t>(i)] - center).squaredNorm() < r2) found.push_back(i);
      }
    }
  std::sort(found.begin(), found.end());
  for (int i : found)
    visit(i);
}

double PointGrid::kth_neighbour_distance(int i, int k) const {
  SG_ASSERT(k >= 1 && static_cast<std::size_t>(k) < points_.size(),
            "k=" << k << " with " << points_.size() << " points");
  const Vec2 center = points_[static_cast<std::size_t>(i)];
  double radius = cell_size_;
  std::vector<double> distances;
  for (;;) {
    distances.clear();
    for_each_within(center, radius, [&](int j) {
      if (j != i) distances.push_back((points_[static_cast<std::size_t>(j)] - center).norm());
    });
    if (distances.size() >= static_cast<std::size_t>(k)) break;
    radius *= 2.0;
  }
  std::nth_element(distances.begin(), distances.begin() + (k - 1), distances.end());
  return distances[static_cast<std::size_t>(k - 1)];
}

}  // namespace sg
