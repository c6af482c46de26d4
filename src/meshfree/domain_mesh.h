#pragma once
// Field-node placement and triangulation of one body's domain (docs/method.md §Quadrature and
// lumped mass): the contour points become the boundary nodes, a constrained Delaunay
// refinement fills the inside with nodes at about the same spacing, Lloyd smoothing evens
// them out, and the resulting triangles carry the Gauss points.
//
// The implementation uses CGAL (Delaunay_mesher_2, lloyd_optimize_mesh_2); it is kept out of
// this header on purpose: a translation unit that includes the mesher compiles in ~20 s with
// ~1 GB of memory.
#include <array>
#include <string>
#include <vector>

#include "geometry/polygon.h"

namespace sg {

struct DomainMeshParams {
  double spacing = 0.1;           // target node spacing h (length units)
  int smoothing_iterations = 10;  // Lloyd iterations on interior nodes (0 = none)
  // >= 1: interior spacing grows from h at the contour to grading*h deep inside (1 = uniform).
  // The spacing grows by at most half the distance travelled away from the contour, so the
  // mesh stays well shaped.
  double boundary_grading = 1.0;
  // > spacing: a graded mesh (issue #32): the target spacing grows linearly with the distance
  // from the contour, from `spacing` on the contour to `interior_spacing` at the body's deepest
  // point (the centre of its largest inscribed circle: radially for a disc), by at most
  // kMaxGradingSlope spacing per unit length (a thin body may not reach it); Lloyd smoothing
  // then keeps that density. 0 (or <= spacing): uniform. Not together with boundary_grading.
  double interior_spacing = 0.0;
};

// Steepest growth of a graded spacing, per unit length travelled inwards: neighbouring
// triangles then differ in size by less than half, so they stay well shaped.
inline constexpr double kMaxGradingSlope = 0.5;

struct DomainMesh {
  // [0, boundary_count): contour nodes, counter-clockwise, nodes[0] == boundary[0];
  // then interior nodes, sorted along the body's longer bounding-box side (neighbours stay
  // close in memory).
  std::vector<Vec2> nodes;
  int boundary_count = 0;
  // Counter-clockwise vertex indices into nodes, all inside the contour; each triple starts
  // at its smallest index and the list is sorted (a canonical order, for determinism).
  std::vector<std::array<int, 3>> triangles;
};

// `boundary` is the body contour already sampled at about `spacing` (CCW, simple). Its points
// become the boundary nodes; where the mesher has to insert points on the contour (contour
// edges much longer than the spacing, or edges encroached at sharp corners) they become
// boundary nodes too, in contour order. Minimum triangle angle after refinement: ~20.7 deg
// (CGAL shape bound 0.125); Lloyd smoothing usually raises it.
// Throws sg::Error naming `body_name` for a contour with fewer than 3 points, a clockwise or
// self-intersecting contour, coincident consecutive points, non-finite coordinates, a
// non-positive spacing, a spacing too large or too small for the body (below its equivalent
// diameter / kMaxDiameterPerSpacing), negative smoothing iterations, a grading below 1, an
// interior spacing that is negative, not finite or below the spacing, or both gradings.
// The finest node spacing accepted for a body of equivalent diameter D is D / this: about
// 3 million nodes in a disc.
inline constexpr double kMaxDiameterPerSpacing = 2000.0;

DomainMesh mesh_domain(const Polygon& boundary, const DomainMeshParams& params,
                       const std::string& body_name);

}  // namespace sg
