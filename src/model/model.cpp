#include "model/model.h"

#include "core/error.h"

namespace sg {

void NodeState::resize(std::size_t n) {
  for (auto* a : {&ref_x, &ref_y, &ux, &uy, &vx, &vy, &fx, &fy, &mass, &inverse_mass})
    a->resize(n, 0.0);
}

MaterialId Model::add_material(const MaterialDef& def) {
  for (const MaterialDef& m : material_defs)
    SG_VERIFY(m.name != def.name, "material '" << def.name << "' is defined twice");
  materials.push_back(make_material_params(def));
  material_defs.push_back(def);
  return static_cast<MaterialId>(materials.size() - 1);
}

BodyId Model::add_deformable_body(const std::string& name, const Polygon& contour,
                                  MaterialId material, const DiscretizationParams& params) {
  return add_deformable_body(name, discretize_body(contour, params, name), material);
}

BodyId Model::add_deformable_body(const std::string& name, const BodyDiscretization& d,
                                  MaterialId material) {
  SG_VERIFY(material >= 0 && static_cast<std::size_t>(material) < materials.size(),
            "body '" << name << "': unknown material index " << material);
  for (const Body& b : bodies) SG_VERIFY(b.name != name, "body name '" << name << "' is used twice");
  Body body;
  body.name = name;
  body.kind = BodyKind::deformable;
  body.material = material;
  body.node_begin = static_cast<int>(nodes.size());
  body.node_end = body.node_begin + static_cast<int>(d.mesh.nodes.size());
  body.boundary_end = body.node_begin + d.mesh.boundary_count;
  body.gauss_begin = static_cast<int>(gauss_weight.size());
  body.gauss_end = body.gauss_begin + static_cast<int>(d.gauss_weight.size());
  body.triangle_begin = static_cast<int>(triangles.size());
  body.triangle_end = body.triangle_begin + static_cast<int>(d.mesh.triangles.size());
  for (double w : d.gauss_weight) body.reference_area += w;

  const double density = materials[static_cast<std::size_t>(material)].density;
  nodes.resize(static_cast<std::size_t>(body.node_end));
  for (std::size_t i = 0; i < d.mesh.nodes.size(); ++i) {
    const std::size_t g = static_cast<std::size_t>(body.node_begin) + i;
    nodes.ref_x[g] = d.mesh.nodes[i].x();
    nodes.ref_y[g] = d.mesh.nodes[i].y();
    nodes.mass[g] = density * d.lumped_volume[i];
    nodes.inverse_mass[g] = 1.0 / nodes.mass[g];
  }
  gauss_rows.append(d.gauss_rows);
  gauss_weight.insert(gauss_weight.end(), d.gauss_weight.begin(), d.gauss_weight.end());
  node_rows.append(d.node_rows);
  for (const auto& t : d.mesh.triangles)
    triangles.push_back({t[0] + body.node_begin, t[1] + body.node_begin, t[2] + body.node_begin});
  bodies.push_back(body);
  return static_cast<BodyId>(bodies.size() - 1);
}

}  // namespace sg
