#include "contact/node_segment.h"

#include "core/error.h"
#include "geometry/polygon.h"

namespace sg {

int ContourView::segment_count() const {
  const int n = point_count();
  if (n < 2) return 0;
  return closed ? n : n - 1;
}

Vec2 ContourView::segment_start(int segment) const {
  return points[static_cast<std::size_t>(segment)];
}

Vec2 ContourView::segment_end(int segment) const {
  const int n = point_count();
  if (segment + 1 < n) return points[static_cast<std::size_t>(segment + 1)];
  return points[0] + closing_shift;  // the closing segment of a closed contour
}

namespace {

// Outward normal of the segment sharing vertex `vertex_at_end ? segment+1 : segment` with
// `segment`, on the other side; the zero vector at the free end of an open contour.
Vec2 adjacent_normal(const ContourView& contour, int segment, bool vertex_at_end) {
  const int m = contour.segment_count();
  int other = vertex_at_end ? segment + 1 : segment - 1;
  if (contour.closed) {
    other = (other + m) % m;
  } else if (other < 0 || other >= m) {
    return Vec2::Zero();
  }
  return outward_normal(contour.segment_start(other), contour.segment_end(other));
}

}  // namespace

NodeProjection project_on_contour_segment(const Vec2& node, const ContourView& contour,
                                          int segment) {
  SG_ASSERT(segment >= 0 && segment < contour.segment_count(),
            "segment " << segment << " of a contour with " << contour.segment_count());
  const Vec2 a = contour.segment_start(segment);
  const Vec2 b = contour.segment_end(segment);
  const SegmentProjection closest = project_on_segment(node, a, b);
  const Vec2 segment_normal = outward_normal(a, b);

  NodeProjection out;
  out.segment = segment;
  out.t = closest.t;
  out.point = closest.closest;
  out.distance = closest.distance;
  if (closest.t > 0.0 && closest.t < 1.0) {
    // Interior of the segment: the segment's own normal.
    out.normal = segment_normal;
    out.gap = (node - out.point).dot(segment_normal);
  } else {
    // The closest point is an end vertex v: normal along (node - v) (convex wedge), oriented
    // outward with the vertex pseudo-normal n_segment + n_adjacent.
    const bool at_end = closest.t >= 1.0;
    const Vec2 pseudo_normal = segment_normal + adjacent_normal(contour, segment, at_end);
    out.point = at_end ? b : a;  // the vertex exactly (a + 1 (b - a) may round off b)
    const Vec2 offset = node - out.point;
    out.distance = offset.norm();
    if (out.distance > 0.0) {
      const double side = offset.dot(pseudo_normal) >= 0.0 ? 1.0 : -1.0;
      out.normal = side * offset / out.distance;
      out.gap = side * out.distance;
    } else {
      // On the vertex itself: any direction of the normal cone; take the pseudo-normal.
      const double norm = pseudo_normal.norm();
      out.normal = norm > 0.0 ? Vec2(pseudo_normal / norm) : segment_normal;
      out.gap = 0.0;
    }
  }
  out.tangent = perp(out.normal);
  return out;
}

double contour_segment_distance(const Vec2& node, const ContourView& contour, int segment) {
  const Vec2 a = contour.segment_start(segment);
  const Vec2 b = contour.segment_end(segment);
  // As project_on_contour_segment: on the interior project_on_segment's distance, at an end the
  // distance to that vertex exactly.
  const SegmentProjection closest = project_on_segment(node, a, b);
  if (closest.t > 0.0 && closest.t < 1.0) return closest.distance;
  return (node - (closest.t >= 1.0 ? b : a)).norm();
}

bool is_closer(const NodeProjection& a, const NodeProjection& b) {
  if (a.segment < 0) return false;
  if (b.segment < 0) return true;
  if (a.distance != b.distance) return a.distance < b.distance;
  return a.segment < b.segment;
}

NodeProjection project_on_contour(const Vec2& node, const ContourView& contour,
                                  std::span<const int> candidate_segments) {
  NodeProjection best;
  for (const int segment : candidate_segments) {
    const NodeProjection candidate = project_on_contour_segment(node, contour, segment);
    if (is_closer(candidate, best)) best = candidate;
  }
  return best;
}

NodeProjection project_on_contour(const Vec2& node, const ContourView& contour) {
  NodeProjection best;
  for (int segment = 0; segment < contour.segment_count(); ++segment) {
    const NodeProjection candidate = project_on_contour_segment(node, contour, segment);
    if (is_closer(candidate, best)) best = candidate;
  }
  return best;
}

double tangential_slip_increment(const Vec2& node_old, const Vec2& segment_start_old,
                                 const Vec2& segment_end_old, const Vec2& node_new,
                                 const Vec2& segment_start_new, const Vec2& segment_end_new,
                                 double t) {
  const Vec2 point_old = segment_start_old + t * (segment_end_old - segment_start_old);
  const Vec2 point_new = segment_start_new + t * (segment_end_new - segment_start_new);
  const Vec2 tangent_old = (segment_end_old - segment_start_old).normalized();
  const Vec2 tangent_new = (segment_end_new - segment_start_new).normalized();
  return tangent_new.dot(node_new - point_new) - tangent_old.dot(node_old - point_old);
}

double tributary_length(const ContourView& contour, int point) {
  const int n = contour.point_count();
  SG_VERIFY(point >= 0 && point < n,
            "contour point " << point << " out of range (" << n << " points)");
  const int m = contour.segment_count();
  const auto segment_length = [&](int s) {
    return (contour.segment_end(s) - contour.segment_start(s)).norm();
  };
  double length = 0.0;
  // Segment ending at `point` (point - 1 -> point) and segment starting at it.
  const int before = contour.closed ? (point - 1 + m) % m : point - 1;
  if (m > 0 && before >= 0) length += 0.5 * segment_length(before);
  if (point < m) length += 0.5 * segment_length(point);
  return length;
}

void tributary_lengths(const ContourView& contour, std::span<double> out) {
  SG_VERIFY(out.size() == contour.points.size(),
            "tributary_lengths: " << out.size() << " outputs for " << contour.points.size()
                                  << " contour points");
  for (int i = 0; i < contour.point_count(); ++i)
    out[static_cast<std::size_t>(i)] = tributary_length(contour, i);
}

}  // namespace sg
