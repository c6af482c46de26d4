#pragma once
// Axis-aligned bounding boxes of points and contours: the cheap first test before an exact
// contour test (geometry/contour_gap.h), and the extent of a picture (render/).
#include <limits>

#include "geometry/polygon.h"

namespace sg {

struct BoundingBox {
  // Empty until a point is added (lo above hi).
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = Vec2::Constant(-std::numeric_limits<double>::infinity());

  void add(const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool empty() const { return !(hi.x() >= lo.x() && hi.y() >= lo.y()); }
  Vec2 size() const { return hi - lo; }
  BoundingBox shifted(const Vec2& d) const { return {lo + d, hi + d}; }
};

// The box of the contour's vertices; of the vertices each translated by `shift`.
BoundingBox bounding_box(const Polygon& p);
BoundingBox bounding_box(const Polygon& p, const Vec2& shift);

// Whether the boxes are more than `gap` apart along x or along y (then nothing in one comes
// within `gap` of anything in the other).
inline bool boxes_apart(const BoundingBox& a, const BoundingBox& b, double gap) {
  return a.hi.x() + gap < b.lo.x() || b.hi.x() + gap < a.lo.x() || a.hi.y() + gap < b.lo.y() ||
         b.hi.y() + gap < a.lo.y();
}

}  // namespace sg
