#pragma once
// The benchmarks' set of ~100-node soft discs (the papers' grains), stretched and spinning:
// 103 field nodes and 519 Gauss points per disc of radius 0.5 at h = 0.1 (3 Gauss points per
// triangle), neo-Hookean, nu = 0.495, objective damping alpha = 0.02; standard or F-bar
// (material.h VolumetricFormulation).
#include <cmath>
#include <string>

#include "geometry/shapes.h"
#include "model/kinematics.h"
#include "model/model.h"

namespace sg::bench {

inline Model disc_set(int discs,
                      VolumetricFormulation volumetric = VolumetricFormulation::standard) {
  MaterialDef m;
  m.name = "soft";
  m.young = 10.0;
  m.poisson = 0.495;
  m.damping = 0.02;
  m.volumetric = volumetric;
  DiscretizationParams p;
  p.mesh.spacing = 0.1;  // 117 field nodes per disc of radius 0.5 (the papers: 100-150)
  const BodyDiscretization disc =
      discretize_body(make_disc(Vec2(0, 0), 0.5, p.mesh.spacing), p, "disc");
  Model model;
  const MaterialId id = model.add_material(m);
  const int side = static_cast<int>(std::ceil(std::sqrt(discs)));
  for (int k = 0; k < discs; ++k) {
    BodyDiscretization shifted = disc;
    for (Vec2& x : shifted.mesh.nodes)
      x += Vec2(1.1 * (k % side), 1.1 * (k / side));
    const BodyId b = model.add_deformable_body("d" + std::to_string(k), shifted, id);
    Mat2 f = Mat2::Identity();
    f(0, 0) = 1.0 + 0.01 * (k % 7);
    set_affine_deformation(model, b, f);
    set_rigid_velocity(model, b, Vec2(0.1, 0.0), 0.5);
  }
  return model;
}

}  // namespace sg::bench
