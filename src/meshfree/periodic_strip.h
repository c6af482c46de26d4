#pragma once
// Discretization of a deformable periodic strip (a first body spanning the periodic cell in
// x: docs/method.md §Bodies, paper 000 §3): the domain between a flat back face and a rough
// contact surface over exactly one period L, with no duplicated nodes at the seam.
//
// Node placement (structured, no mesher): one column of nodes under (or over) every surface
// point, from the back face to the surface, at about the node spacing; the surface must be
// the graph of a function of x (a rough profile), with its points at strictly monotonic x
// spanning less than one period. Neighbouring columns are zipped into triangles (the region
// between two vertical columns is a convex trapezoid, so any monotonic zipper is a valid
// triangulation); the last column is zipped with the first one shifted by +L: the seam
// triangles. CGAL is not needed, and the columns make the seam exactly periodic, which a
// constrained Delaunay mesh of one period would not be (its Steiner points on the two vertical
// ends would not match).
//
// Periodic MLS (Belytschko 1994, as in mls.h): a Gauss point or a node sees the nodes of the
// strip and their images shifted by -L and +L. Each row entry names the original node (the
// displacement parameters of an image are those of its original: the field is periodic) and
// records which image was used (-1, 0, +1), so Sum_J N_J (X_J + image_J L e_x) = x exactly
// (linear reproduction), while Sum_J N_J X_J is not (the shifts are lost). A row never holds
// the same node twice (checked: the period must exceed the MLS supports). Quadrature covers
// exactly one period: the triangles within the period plus the seam triangles.
//
// Rendering: `body.mesh.triangles` holds only the triangles within the period (those the
// model copies and the VTU writer draws). The seam triangles join the last column to the
// first one at the far end of the cell; drawn with the nodes' own coordinates they would be a
// band across the whole cell, so they are left out of the picture: a strip is drawn with a
// gap one column wide at its seam. They are kept in `seam_triangles` (quadrature used them).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "meshfree/body_discretization.h"

namespace sg {

struct PeriodicStripDiscretization {
  // Nodes: [0, surface point count) the surface points in the given order (the contour
  // nodes), then the other nodes column by column in increasing x, each column from low to
  // high y. Gauss and node rows in this numbering (images mapped back to their originals).
  BodyDiscretization body;
  double period = 0.0;           // L
  double closing_shift_x = 0.0;  // -L (body below its surface) or +L (above)
  double back_y = 0.0;           // the flat back face
  std::vector<int> back_nodes;   // the nodes on the back face, in increasing x
  // Triangles crossing the seam: vertices of the first column are meant at +L.
  std::vector<std::array<int, 3>> seam_triangles;
  // Per row entry of body.gauss_rows / body.node_rows: the image used, -1, 0 or +1 (the
  // node's reference position plus image * L along x).
  std::vector<std::int8_t> gauss_image, node_image;
};

// `surface`: the contact surface, with the strip's material on the left of the direction of
// travel (as Model::add_rigid_strip): x strictly decreasing with closing_shift_x = -L (a body
// below its surface, back_y under every surface point) or strictly increasing with
// closing_shift_x = +L (a body above, back_y over every point); the last point joins the
// first shifted by closing_shift_x. Nodes in a column are spaced by at most about
// params.mesh.spacing or, graded (params.mesh.interior_spacing > spacing, issue #32), by a
// spacing that grows linearly with depth from params.mesh.spacing at the surface to
// params.mesh.interior_spacing at the back face (the columns stay under the surface points,
// so the cells near the back face are elongated in y by up to that ratio, and each MLS
// support reaches at least 1.5 times its node's column interval); params.mls and
// params.gauss_points as for any body. Throws sg::Error
// naming `body_name` for a surface that is not monotonic in x or spans a period or more, a
// back face on the wrong side, fewer than 3 columns, or a period too short for the supports.
PeriodicStripDiscretization discretize_periodic_strip(const Polygon& surface,
                                                      double closing_shift_x, double back_y,
                                                      const DiscretizationParams& params,
                                                      const std::string& body_name);

}  // namespace sg
