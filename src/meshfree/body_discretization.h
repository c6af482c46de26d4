#pragma once
// Discretization of one deformable body: its field nodes, their triangulation, the Gauss
// points with their MLS rows, the MLS rows at the nodes themselves, and the lumped
// nodal volumes. Everything is in the body's reference configuration and local numbering;
// the model copies it into global arrays.
#include <array>
#include <string>
#include <vector>

#include "geometry/node_spacing.h"
#include "meshfree/domain_mesh.h"
#include "meshfree/mls.h"
#include "meshfree/shape_rows.h"

namespace sg {

struct DiscretizationParams {
  DomainMeshParams mesh;
  MlsParams mls;
  int gauss_points = 3;  // per triangle: 1, 3, 6 or 7
};

struct BodyDiscretization {
  DomainMesh mesh;
  ShapeRows gauss_rows;              // one row per Gauss point
  std::vector<double> gauss_weight;  // quadrature weight (area), sums to the body area
  std::vector<Vec2> gauss_position;  // reference position
  // The node of its triangle nearest to each Gauss point (the largest barycentric coordinate;
  // the lowest node index on ties): the point's F-bar patch (model/gauss_patches.h).
  std::vector<int> gauss_node;
  // One row per node, evaluated at the node's reference position: the physical position of
  // node I is X_I + sum_J N_J(X_I) u_J (MLS does not interpolate), and a force applied there
  // is spread back with the same N_J(X_I).
  // Contour nodes [0, mesh.boundary_count) get instead the contact-consistent row of
  // meshfree/contour_rows.h, and contour_offset holds their d = X - Xbar (same file).
  ShapeRows node_rows;
  std::vector<Vec2> contour_offset;
  std::vector<double> support_radius;
  // integral of N_I over the body (row-sum lumping): nodal mass = density * lumped_volume.
  // Partition of unity makes the total exact: sum_I lumped_volume_I = area.
  std::vector<double> lumped_volume;
};

// `params` with a body's own node spacings (geometry/node_spacing.h): own.contour, when set,
// replaces the spacing and own.interior the interior spacing (0: uniform at own.contour);
// own.contour unset keeps params' spacings.
DiscretizationParams with_spacing(DiscretizationParams params, const NodeSpacing& own);

// Meshes the domain bounded by `boundary` (CCW, sampled at about the node spacing) and
// discretizes it.
BodyDiscretization discretize_body(const Polygon& boundary, const DiscretizationParams& params,
                                   const std::string& body_name);

// Same from an existing node set and triangulation (tests, imported meshes).
// The vertex of `triangle` with the largest barycentric coordinate of `point` (the lowest node
// index among equal ones): BodyDiscretization::gauss_node.
int nearest_vertex(const std::array<int, 3>& triangle, const std::array<double, 3>& point);

BodyDiscretization discretize_mesh(DomainMesh mesh, const DiscretizationParams& params,
                                   const std::string& body_name);

}  // namespace sg
