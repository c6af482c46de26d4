#pragma once
// Closed polygons: the contour of a body. Vertices are stored once (the closing edge
// from the last vertex back to the first is implicit); a valid body contour is simple
// (no self-intersection) and counter-clockwise (positive signed area).
#include <vector>

#include "geometry/vec2.h"

namespace sg {

using Polygon = std::vector<Vec2>;

double signed_area(const Polygon& p);
double perimeter(const Polygon& p);
Vec2 centroid(const Polygon& p);
// Second moment of area about the centroid, polar: integral of |x - c|^2 dA (units L^4).
double polar_second_moment(const Polygon& p);
bool is_counter_clockwise(const Polygon& p);
// Crossing-number test; points exactly on the contour may be reported either way.
bool contains(const Polygon& p, const Vec2& point);
// Whether any two non-adjacent edges intersect (O(n^2): contours have ~100 vertices).
bool is_self_intersecting(const Polygon& p);
// Translates the contour so that its centroid is the origin; returns its bounding radius about
// the centroid (the largest |vertex|).
double center_on_centroid(Polygon& p);
// Smallest distance from `point` to the contour.
double distance_to_contour(const Polygon& p, const Vec2& point);

struct SegmentProjection {
  double distance;  // |point - closest|
  double t;         // closest = a + t (b - a), t in [0, 1]
  Vec2 closest;
};
SegmentProjection project_on_segment(const Vec2& point, const Vec2& a, const Vec2& b);

// Whether segments [a,b] and [c,d] intersect (touching counts).
bool segments_intersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

// Points along the contour at a uniform arc-length spacing close to `spacing`
// (at least `min_points`), starting at vertex 0. The original vertices are not kept
// unless they fall on the new spacing: use for smooth shapes.
Polygon resample_by_arc_length(const Polygon& p, double spacing, int min_points = 3);

}  // namespace sg
