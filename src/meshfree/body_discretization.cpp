#include "meshfree/body_discretization.h"

#include "core/error.h"
#include "meshfree/contour_rows.h"
#include "meshfree/triangle_quadrature.h"

namespace sg {

DiscretizationParams with_spacing(DiscretizationParams params, const NodeSpacing& own) {
  if (own.contour > 0.0) {
    params.mesh.spacing = own.contour;
    params.mesh.interior_spacing = own.interior;
  }
  return params;
}

int nearest_vertex(const std::array<int, 3>& triangle, const std::array<double, 3>& point) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (point[i] > point[best] || (point[i] == point[best] && triangle[i] < triangle[best]))
      best = i;
  return triangle[best];
}

BodyDiscretization discretize_mesh(DomainMesh mesh, const DiscretizationParams& params,
                                   const std::string& body_name) {
  BodyDiscretization d;
  d.mesh = std::move(mesh);
  const std::vector<Vec2>& nodes = d.mesh.nodes;
  const MlsShapeFunctions mls(nodes, params.mls, body_name);
  d.support_radius = mls.support_radius();

  const TriangleRule& rule = triangle_rule(params.gauss_points);
  for (const auto& tri : d.mesh.triangles) {
    const Vec2 &a = nodes[static_cast<std::size_t>(tri[0])],
               &b = nodes[static_cast<std::size_t>(tri[1])],
               &c = nodes[static_cast<std::size_t>(tri[2])];
    const double area = 0.5 * cross(b - a, c - a);
    SG_VERIFY(area > 0.0, "body '" << body_name << "': triangle (" << tri[0] << ", " << tri[1]
                                   << ", " << tri[2] << ") has non-positive area " << area);
    for (std::size_t q = 0; q < rule.weight.size(); ++q) {
      const auto& l = rule.barycentric[q];
      const Vec2 x = l[0] * a + l[1] * b + l[2] * c;
      mls.evaluate(x, d.gauss_rows);
      d.gauss_weight.push_back(rule.weight[q] * area);
      d.gauss_position.push_back(x);
      d.gauss_node.push_back(nearest_vertex(tri, l));
    }
  }
  // Contour nodes get the contact-consistent row of meshfree/contour_rows.h, the others
  // the MLS row at their own position.
  const auto boundary = static_cast<std::size_t>(d.mesh.boundary_count);
  ShapeRows at_hat;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (i >= boundary) {
      mls.evaluate(nodes[i], d.node_rows);
      continue;
    }
    const HatQuadrature hat =
        hat_quadrature(nodes[i], nodes[(i + boundary - 1) % boundary], nodes[(i + 1) % boundary]);
    at_hat = ShapeRows{};
    for (const Vec2& x : hat.point)
      mls.evaluate(x, at_hat);
    append_contour_row(at_hat, {}, hat, d.node_rows, nullptr);
    d.contour_offset.push_back(nodes[i] - hat.centroid);
  }

  d.lumped_volume.assign(nodes.size(), 0.0);
  for (std::size_t g = 0; g < d.gauss_rows.points(); ++g)
    for (auto k = d.gauss_rows.offset[g]; k < d.gauss_rows.offset[g + 1]; ++k)
      d.lumped_volume[static_cast<std::size_t>(d.gauss_rows.node[static_cast<std::size_t>(k)])] +=
          d.gauss_weight[g] * d.gauss_rows.value[static_cast<std::size_t>(k)];
  for (std::size_t i = 0; i < nodes.size(); ++i)
    SG_VERIFY(d.lumped_volume[i] > 0.0,
              "body '" << body_name << "': node " << i << " at (" << nodes[i].x() << ", "
                       << nodes[i].y() << ") gets a non-positive lumped mass ("
                       << d.lumped_volume[i]
                       << " x density); refine the node spacing or increase the MLS support");
  return d;
}

}  // namespace sg
