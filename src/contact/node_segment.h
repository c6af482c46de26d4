#pragma once
// Narrow phase of the node-to-segment contact: where a slave node stands relative to the
// contour of a master body. Pure geometry (docs/architecture.md §Conventions 5): positions in,
// projection out; no body, no state.
//
// Contours. A contour is a polyline through a body's boundary nodes with the body's material
// on the LEFT of the direction of travel, so the outward normal of segment [a, b] is
// n = -perp(b - a) / |b - a| and the tangent is t = perp(n) = (b - a) / |b - a|:
//   - a closed body contour is counter-clockwise (docs/method.md §Bodies) and the last
//     segment joins the last point back to the first;
//   - a periodic strip (a first body spanning the periodic cell) is closed too, but its last
//     segment joins the last point to (first point + closing_shift), closing_shift = (±L, 0);
//     e.g. the top surface of a lower first body runs from right to left;
//   - an open polyline has no closing segment; its end points have one neighbour.
//
// The projection is the closest point of the contour (over the candidate segments), and the
// signed gap is the signed distance to the contour: negative = penetration (the node is on
// the material side). The normal is the direction of the node from its closest point
// (the gradient of the signed distance), so at corners:
//
//    convex corner, node outside          concave corner, node outside
//          o  node                             \    o    /
//           \  n = (x - v)/|x - v|              \   |   /     two segments at equal
//            v-------                            \  | /       distance on the bisector:
//           /  (wedge beyond the vertex)          \ |/        the lower segment index wins
//          /                                       v
//
// - beyond a convex vertex (the closest point is the vertex) the normal turns continuously
//   from one segment's normal to the next, and the gap is the distance to the vertex;
// - near a concave vertex, or inside a convex one, the node projects onto two segments; the
//   closest one is chosen, ties go to the lower segment index. The gap (the distance) is
//   continuous across the switch; only the direction of the normal turns there, and the
//   normal traction (which depends on the gap) does not jump.
// The inside/outside sign of a vertex projection comes from the vertex pseudo-normal (the
// sum of the two adjacent segment normals), which is exact for the closest vertex.
// One narrow phase serves every pair of bodies, rigid or deformable (paper 000 §4: "the same
// contact algorithm may then be applied for any couple of grains"), so there is no dispatch
// table keyed by shape types.
#include <span>

#include "geometry/vec2.h"

namespace sg {

// A non-owning view of one contour (see the header comment for `closed` and
// `closing_shift`). Segment i runs from point i to point i+1 (the last one, when closed,
// to points[0] + closing_shift).
struct ContourView {
  std::span<const Vec2> points;
  bool closed = true;
  Vec2 closing_shift = Vec2::Zero();

  int point_count() const { return static_cast<int>(points.size()); }
  int segment_count() const;
  Vec2 segment_start(int segment) const;
  Vec2 segment_end(int segment) const;
};

// Unit outward normal of segment [a, b] (material on the left of a -> b).
inline Vec2 outward_normal(const Vec2& a, const Vec2& b) {
  return -perp(b - a).normalized();
}

struct NodeProjection {
  int segment = -1;             // master segment index; -1 if there was no candidate
  double t = 0.0;               // projection = start + t (end - start), t in [0, 1]
  Vec2 point = Vec2::Zero();    // closest point of the contour
  Vec2 normal = Vec2::Zero();   // unit, outward from the master (see header comment)
  Vec2 tangent = Vec2::Zero();  // perp(normal): along the contour's direction of travel
  double gap = 0.0;             // signed normal gap (node - point) . normal; < 0 penetration
  double distance = 0.0;        // |node - point| = |gap|
};

// Projection of `node` onto one segment of `contour`, with the corner rules above when the
// closest point is an end vertex.
NodeProjection project_on_contour_segment(const Vec2& node, const ContourView& contour,
                                          int segment);

// The distance project_on_contour_segment(node, contour, segment) reports, bit for bit, without
// its normals: a search over many candidate segments compares these and projects only on the
// closest (ContactSystem::project_group).
double contour_segment_distance(const Vec2& node, const ContourView& contour, int segment);

// The closest projection over `candidate_segments` (e.g. from the broad phase); ties go to
// the lower segment index whatever the order of the candidates. segment == -1 if empty.
NodeProjection project_on_contour(const Vec2& node, const ContourView& contour,
                                  std::span<const int> candidate_segments);
// Over all segments of the contour.
NodeProjection project_on_contour(const Vec2& node, const ContourView& contour);

// Whether `a` is a better (closer) projection than `b` under the rule above (distance, then
// lower segment index): for callers reducing over candidates with different periodic shifts.
bool is_closer(const NodeProjection& a, const NodeProjection& b);

// Slip increment ds of the node relative to the master surface between two configurations
// (contact_law.h): the change of the node's tangential offset from the master material point
// at parameter `t` of the segment,
//   ds = t_new . (x_new - p_new) - t_old . (x_old - p_old),  p = a + t (b - a),
// t_old/t_new the segment's unit tangent in each configuration. A rigid motion (translation
// and rotation) of node and segment together gives ds = 0; sliding the node by d along the
// segment gives ds = d.
double tangential_slip_increment(const Vec2& node_old, const Vec2& segment_start_old,
                                 const Vec2& segment_end_old, const Vec2& node_new,
                                 const Vec2& segment_start_new, const Vec2& segment_end_new,
                                 double t);

// Tributary length of contour point i: half of each adjacent segment (one segment at the
// ends of an open contour). The force of a contact on a node is traction x this length.
double tributary_length(const ContourView& contour, int point);
// All of them, out.size() == contour.point_count(). They sum to the contour's length.
void tributary_lengths(const ContourView& contour, std::span<double> out);

}  // namespace sg
