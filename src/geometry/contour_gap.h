#pragma once
// How close two body contours are: whether they overlap (an edge of one crosses or touches an
// edge of the other, or one closed contour lies inside the other), the smallest gap between
// them, and how deep an overlap goes. One definition for the packer (geometry/packing.h: a
// placement must keep a gap), for `softgrain generate` (report/sample_report.h: the smallest
// gap of the built sample) and for anything else that asks.
//
// Contour b is given with a translation `shift_b` (a periodic image) instead of a translated
// copy, so the packer's inner loop copies nothing. Every distance is vertex to edge, both
// ways: the exact distance between two polylines that do not cross.
#include "geometry/bounding_box.h"
#include "geometry/polygon.h"

namespace sg {

// A contour's edges: vertex i to vertex i + 1, and the last vertex back to the first; for an
// open contour (a periodic strip's surface) back to the first shifted by closing_shift along x,
// its image in the next period.
struct ContourEdges {
  const Polygon& points;
  bool open = false;
  double closing_shift = 0.0;

  std::size_t size() const { return points.size(); }
  Vec2 edge_end(std::size_t i) const {
    if (i + 1 < points.size()) return points[i + 1];
    return open ? Vec2(points.front() + Vec2(closing_shift, 0.0)) : points.front();
  }
};

// Whether an edge of a crosses or touches an edge of b + shift_b, or (gap > 0) a vertex of one
// comes closer than `gap` to an edge of the other. Edges of a whose box is farther than `gap`
// from b's are skipped.
bool contour_edges_interfere(const ContourEdges& a, const ContourEdges& b, const Vec2& shift_b,
                             double gap);

// Whether one closed contour lies inside the other, tested on one vertex of each (valid when no
// edges cross).
bool contour_inside_other(const Polygon& a, const Polygon& b, const Vec2& shift_b);

// Whether closed contours a and b + shift_b overlap or come closer than `gap`.
bool contours_interfere(const Polygon& a, const Polygon& b, const Vec2& shift_b, double gap);

// Whether two closed contours overlap: an edge of one crosses or touches an edge of the
// other, or one lies inside the other.
bool contours_overlap(const Polygon& a, const Polygon& b);

// The smallest distance between contours a and b + shift_b that do not cross (length).
double contour_gap(const ContourEdges& a, const ContourEdges& b, const Vec2& shift_b);

// How deep closed contours a and b + shift_b overlap: the largest distance of a vertex of one
// inside the other to the other's contour (0 if no vertex is inside).
double overlap_depth(const Polygon& a, const Polygon& b, const Vec2& shift_b);

}  // namespace sg
