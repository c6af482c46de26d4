#include "geometry/contour_gap.h"

#include <algorithm>
#include <limits>

#include "core/error.h"

namespace sg {

namespace {

// contour_edges_interfere with b's box (translated) already known.
bool edges_interfere(const ContourEdges& a, const ContourEdges& b, const Vec2& shift_b,
                     const BoundingBox& box_b, double gap) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2& p = a.points[i];
    const Vec2 q = a.edge_end(i);
    // Skip edges of a that cannot reach b's box.
    if (boxes_apart({p.cwiseMin(q), p.cwiseMax(q)}, box_b, gap)) continue;
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2 r = b.points[j] + shift_b, s = b.edge_end(j) + shift_b;
      if (segments_intersect(p, q, r, s)) return true;
      if (gap > 0.0 && (project_on_segment(r, p, q).distance < gap ||
                        project_on_segment(p, r, s).distance < gap))
        return true;
    }
  }
  return false;
}

}  // namespace

bool contour_edges_interfere(const ContourEdges& a, const ContourEdges& b, const Vec2& shift_b,
                             double gap) {
  return edges_interfere(a, b, shift_b, bounding_box(b.points, shift_b), gap);
}

bool contour_inside_other(const Polygon& a, const Polygon& b, const Vec2& shift_b) {
  return contains(a, b[0] + shift_b) || contains(b, a[0] - shift_b);
}

bool contours_interfere(const Polygon& a, const Polygon& b, const Vec2& shift_b, double gap) {
  const BoundingBox box_b = bounding_box(b, shift_b);
  if (boxes_apart(bounding_box(a), box_b, gap)) return false;
  // No crossing edges: overlap only if one contour lies inside the other.
  return edges_interfere({a}, {b}, shift_b, box_b, gap) || contour_inside_other(a, b, shift_b);
}

bool contours_overlap(const Polygon& a, const Polygon& b) {
  SG_VERIFY(a.size() >= 3 && b.size() >= 3, "contours_overlap needs two polygons");
  return contours_interfere(a, b, Vec2::Zero(), 0.0);
}

double contour_gap(const ContourEdges& a, const ContourEdges& b, const Vec2& shift_b) {
  double gap = std::numeric_limits<double>::infinity();
  for (const Vec2& v : a.points)
    for (std::size_t j = 0; j < b.size(); ++j)
      gap = std::min(
          gap, project_on_segment(v, b.points[j] + shift_b, b.edge_end(j) + shift_b).distance);
  for (const Vec2& w : b.points)
    for (std::size_t i = 0; i < a.size(); ++i)
      gap = std::min(gap, project_on_segment(w + shift_b, a.points[i], a.edge_end(i)).distance);
  return gap;
}

double overlap_depth(const Polygon& a, const Polygon& b, const Vec2& shift_b) {
  Polygon moved_b = b;
  for (Vec2& v : moved_b)
    v += shift_b;
  double deepest = 0.0;
  for (const Vec2& v : moved_b)
    if (contains(a, v)) deepest = std::max(deepest, distance_to_contour(a, v));
  for (const Vec2& v : a)
    if (contains(moved_b, v)) deepest = std::max(deepest, distance_to_contour(moved_b, v));
  return deepest;
}

}  // namespace sg
