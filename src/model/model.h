#pragma once
// The Model owns everything the solver advances: bodies (cold descriptions), node state
// (hot structure-of-arrays), and the precomputed discretization (streamed rows).
//
//   Body        cold: name, kind, material, index ranges. Never touched per node.
//   NodeState   hot: one entry per field node, all bodies concatenated, each body a
//               contiguous range [node_begin, node_end) whose first nodes are its contour.
//   gauss_rows  streamed: per Gauss point, the MLS row (local node index, N, dN/dX, dN/dY);
//               body b owns Gauss points [gauss_begin, gauss_end).
//
// Node indices inside rows are local to their body, so a body's kernel works on pointers
// to its own slice of the node arrays (and the same kernel runs on scratch copies, e.g. in
// the stable-step estimate). Bodies refer to materials by index (ids, not pointers).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "material/material.h"
#include "meshfree/body_discretization.h"
#include "meshfree/shape_rows.h"

namespace sg {

using BodyId = int;
using MaterialId = int;

enum class BodyKind : std::uint8_t { deformable, rigid };

struct Body {
  std::string name;
  BodyKind kind = BodyKind::deformable;
  MaterialId material = 0;
  int node_begin = 0, node_end = 0;  // global node range
  int boundary_end = 0;              // [node_begin, boundary_end): contour nodes, CCW
  int gauss_begin = 0, gauss_end = 0;
  int triangle_begin = 0, triangle_end = 0;
  double reference_area = 0.0;

  int node_count() const { return node_end - node_begin; }
  int boundary_count() const { return boundary_end - node_begin; }
};

// Hot per-node arrays (structure of arrays). u and v are the MLS *parameters*: the physical
// displacement at X is sum_J N_J(X) u_J, not u_I at X_I.
struct NodeState {
  std::vector<double> ref_x, ref_y;  // reference position X
  std::vector<double> ux, uy;        // displacement parameters (checkpointed)
  std::vector<double> vx, vy;        // velocity parameters (checkpointed)
  std::vector<double> fx, fy;        // total force on each parameter (recomputed each step)
  std::vector<double> mass;          // lumped mass rho * integral of N_I
  std::vector<double> inverse_mass;

  std::size_t size() const { return ref_x.size(); }
  void resize(std::size_t n);
};

struct Model {
  std::vector<Body> bodies;
  std::vector<MaterialDef> material_defs;
  std::vector<MaterialParams> materials;
  NodeState nodes;
  ShapeRows gauss_rows;               // local node numbering per body
  std::vector<double> gauss_weight;   // reference area of each Gauss point
  ShapeRows node_rows;                // row of each node at its own reference position
  std::vector<std::array<int, 3>> triangles;  // global node numbering
  Vec2 gravity = Vec2::Zero();        // acceleration (length / time^2)

  MaterialId add_material(const MaterialDef& def);
  // Discretizes `contour` (CCW, simple; sampled at about the node spacing) and appends the
  // body. Errors name the body.
  BodyId add_deformable_body(const std::string& name, const Polygon& contour,
                             MaterialId material, const DiscretizationParams& params);
  // Appends an already discretized body (tests, imported meshes).
  BodyId add_deformable_body(const std::string& name, const BodyDiscretization& d,
                             MaterialId material);

  std::size_t node_count() const { return nodes.size(); }
  std::size_t gauss_point_count() const { return gauss_weight.size(); }
};

}  // namespace sg
