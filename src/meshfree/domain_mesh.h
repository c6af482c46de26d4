#pragma once
// PROVISIONAL interface (the meshing engineer replaces this file with the implementation's).
#include <array>
#include <string>
#include <vector>

#include "geometry/polygon.h"

namespace sg {

struct DomainMeshParams {
  double spacing = 0.1;
  int smoothing_iterations = 10;
  double boundary_grading = 1.0;
};

struct DomainMesh {
  std::vector<Vec2> nodes;
  int boundary_count = 0;
  std::vector<std::array<int, 3>> triangles;
};

DomainMesh mesh_domain(const Polygon& boundary, const DomainMeshParams& params,
                       const std::string& body_name);

}  // namespace sg
