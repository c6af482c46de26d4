#include "geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace sg {

namespace {
const Vec2& next_vertex(const Polygon& p, std::size_t i) {
  return p[(i + 1) % p.size()];
}
}  // namespace

double signed_area(const Polygon& p) {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    twice_area += cross(p[i], next_vertex(p, i));
  return 0.5 * twice_area;
}

double perimeter(const Polygon& p) {
  double length = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    length += (next_vertex(p, i) - p[i]).norm();
  return length;
}

Vec2 centroid(const Polygon& p) {
  // Shoelace formula, vertices taken relative to p[0] for round-off.
  const Vec2 origin = p.front();
  double twice_area = 0.0;
  Vec2 moment(0.0, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i] - origin, b = next_vertex(p, i) - origin;
    const double c = cross(a, b);
    twice_area += c;
    moment += c * (a + b);
  }
  return origin + moment / (3.0 * twice_area);
}

double polar_second_moment(const Polygon& p) {
  // Sum over the triangles (c, p_i, p_i+1): Ixx + Iyy of each about c.
  const Vec2 c = centroid(p);
  double twice_moment = 0.0;  // 12 * J accumulated as in the standard polygon formula
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i] - c, b = next_vertex(p, i) - c;
    const double k = cross(a, b);
    twice_moment += k * (a.squaredNorm() + a.dot(b) + b.squaredNorm());
  }
  return twice_moment / 12.0;
}

bool is_counter_clockwise(const Polygon& p) {
  return signed_area(p) > 0.0;
}

bool contains(const Polygon& p, const Vec2& point) {
  bool inside = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const Vec2 &a = p[i], &b = p[j];
    if ((a.y() > point.y()) != (b.y() > point.y())) {
      const double x_cross = a.x() + (point.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (point.x() < x_cross) inside = !inside;
    }
  }
  return inside;
}

SegmentProjection project_on_segment(const Vec2& point, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  double t = length2 > 0.0 ? (point - a).dot(ab) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec2 closest = a + t * ab;
  return {(point - closest).norm(), t, closest};
}

bool segments_intersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(d - c, a - c), d2 = cross(d - c, b - c);
  const double d3 = cross(b - a, c - a), d4 = cross(b - a, d - a);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto on_segment = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  return (d1 == 0 && on_segment(c, d, a)) || (d2 == 0 && on_segment(c, d, b)) ||
         (d3 == 0 && on_segment(a, b, c)) || (d4 == 0 && on_segment(a, b, d));
}

bool is_self_intersecting(const Polygon& p) {
  const std::size_t n = p.size();
  if (n < 3) return true;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
      if (adjacent) {
        // Adjacent edges share a vertex; they intersect improperly only if they fold back.
        if (p[i] == next_vertex(p, i) || p[j] == next_vertex(p, j)) return true;
        continue;
      }
      if (segments_intersect(p[i], next_vertex(p, i), p[j], next_vertex(p, j))) return true;
    }
  }
  return false;
}

double center_on_centroid(Polygon& p) {
  const Vec2 c = centroid(p);
  double radius = 0.0;
  for (Vec2& v : p) {
    v -= c;
    radius = std::max(radius, v.norm());
  }
  return radius;
}

double distance_to_contour(const Polygon& p, const Vec2& point) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i)
    best = std::min(best, project_on_segment(point, p[i], next_vertex(p, i)).distance);
  return best;
}

Polygon resample_by_arc_length(const Polygon& p, double spacing, int min_points) {
  SG_ASSERT(spacing > 0.0, "spacing " << spacing);
  const double total = perimeter(p);
  const int count = std::max(min_points, static_cast<int>(std::lround(total / spacing)));
  const double step = total / count;
  Polygon out;
  out.reserve(static_cast<std::size_t>(count));
  std::size_t edge = 0;
  double edge_start = 0.0;  // arc length at p[edge]
  for (int k = 0; k < count; ++k) {
    const double s = k * step;
    double edge_length = (next_vertex(p, edge) - p[edge]).norm();
    while (s > edge_start + edge_length && edge + 1 < p.size()) {
      edge_start += edge_length;
      ++edge;
      edge_length = (next_vertex(p, edge) - p[edge]).norm();
    }
    const double t = edge_length > 0.0 ? (s - edge_start) / edge_length : 0.0;
    out.push_back(p[edge] + std::clamp(t, 0.0, 1.0) * (next_vertex(p, edge) - p[edge]));
  }
  return out;
}

}  // namespace sg
