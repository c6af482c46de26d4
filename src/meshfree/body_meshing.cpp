#include "meshfree/body_discretization.h"

namespace sg {

// Kept apart from discretize_mesh so that code working on given meshes does not pull in
// the mesher.
BodyDiscretization discretize_body(const Polygon& boundary, const DiscretizationParams& params,
                                   const std::string& body_name) {
  return discretize_mesh(mesh_domain(boundary, params.mesh, body_name), params, body_name);
}

}  // namespace sg
