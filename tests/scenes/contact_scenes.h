#pragma once
// Shared contact scenes: rigid blocks and planes, contact-law tables.
#include <string>
#include <vector>

#include "contact/contact_system.h"
#include "geometry/shapes.h"
#include "model/model.h"

namespace sg::scenes {

inline MaterialDef rigid_material(const std::string& name = "steel", double density = 1.0) {
  MaterialDef m;
  m.name = name;
  m.young = 1000.0;  // unused by rigid bodies, validated all the same
  m.poisson = 0.3;
  m.density = density;
  return m;
}

inline MaterialPairTable single_law(const Model& model, const ContactLawParams& law) {
  std::vector<std::string> names;
  for (const MaterialDef& m : model.material_defs)
    names.push_back(m.name);
  MaterialPairTable table(names);
  for (int a = 0; a < table.material_count(); ++a)
    for (int b = a; b < table.material_count(); ++b)
      table.set(a, b, law);
  return table;
}

// Fixes every degree of freedom of a rigid body (velocity 0).
inline void fix_rigid(Model& model, BodyId body) {
  RigidDrive& d = model.rigid.drive[static_cast<std::size_t>(model.body(body).rigid_index)];
  for (int k = 0; k < 3; ++k) {
    d.mode[k] = DriveMode::velocity;
    d.velocity[k] = PiecewiseLinear::constant(0.0);
  }
}

inline RigidDrive& drive_of(Model& model, BodyId body) {
  return model.rigid.drive[static_cast<std::size_t>(model.body(body).rigid_index)];
}

}  // namespace sg::scenes
