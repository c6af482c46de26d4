#pragma once
// Shared scenes for tests and benchmarks (docs/architecture.md §Conventions 11): free deformable
// grains.
#include <string>

#include "geometry/shapes.h"
#include "model/model.h"

namespace sg::scenes {

inline MaterialDef elastic_material(MaterialLaw law = MaterialLaw::neo_hookean,
                                    double damping = 0.0, double poisson = 0.3,
                                    double young = 10.0) {
  MaterialDef m;
  m.name = "grain";
  m.law = law;
  m.young = young;
  m.poisson = poisson;
  m.density = 1.0;
  m.damping = damping;
  return m;
}

inline DiscretizationParams discretization(double spacing, int gauss_points = 3) {
  DiscretizationParams p;
  p.mesh.spacing = spacing;
  p.gauss_points = gauss_points;
  return p;
}

// Graded (issue #32): contour nodes at `spacing`, coarsening to `interior_spacing` at the
// body's deepest point (meshfree/domain_mesh.h).
inline DiscretizationParams graded_discretization(double spacing, double interior_spacing,
                                                  int gauss_points = 3) {
  DiscretizationParams p = discretization(spacing, gauss_points);
  p.mesh.interior_spacing = interior_spacing;
  return p;
}

inline Model single_graded_disc(const MaterialDef& material, double radius, double spacing,
                                double interior_spacing, int gauss_points = 3) {
  Model model;
  const MaterialId m = model.add_material(material);
  model.add_deformable_body("disc", make_disc(Vec2(0, 0), radius, spacing), m,
                            graded_discretization(spacing, interior_spacing, gauss_points));
  return model;
}

// One disc of `radius` centred at `center`, node spacing `spacing`.
inline BodyId add_disc(Model& model, MaterialId material, const Vec2& center, double radius,
                       double spacing, const std::string& name = "disc", int gauss_points = 3) {
  return model.add_deformable_body(name, make_disc(center, radius, spacing), material,
                                   discretization(spacing, gauss_points));
}

inline Model single_disc(const MaterialDef& material, double radius, double spacing,
                         int gauss_points = 3) {
  Model model;
  const MaterialId m = model.add_material(material);
  add_disc(model, m, Vec2(0, 0), radius, spacing, "disc", gauss_points);
  return model;
}

// A flat rubber strip (E = 100, nu = 0.3, Rayleigh alpha 0.01) below y = 0, back face at
// y = -1, periodic over [0, 10), node spacing 0.1: mass 10. Its back face has a node drive
// (Body::node_drive), free until the caller sets its modes.
inline BodyId add_flat_rubber_strip(Model& model) {
  model.periodic_x = true;
  model.x_min = 0.0;
  model.x_max = 10.0;
  MaterialDef rubber = elastic_material(MaterialLaw::neo_hookean, 0.01, 0.3, 100.0);
  rubber.name = "rubber";
  const MaterialId m = model.add_material(rubber);
  const double h = 0.1;
  Polygon surface;
  for (int k = 99; k >= 0; --k)
    surface.emplace_back(k * h, 0.0);
  return model.add_deformable_strip("strip", surface, -10.0, -1.0, m, discretization(h));
}

}  // namespace sg::scenes
