// Model's handles (body, material_of) and its one definition of a damped body, is_damped:
// a deformable body whose material has bulk damping alpha > 0, whatever the damping model;
// never a rigid body, and never an undamped one.
#include <gtest/gtest.h>

#include "geometry/shapes.h"
#include "material/material.h"
#include "scenes/free_grains.h"

namespace sg {
namespace {

MaterialDef grain_material(const std::string& name, double alpha, DampingModel damping_model) {
  MaterialDef m = scenes::elastic_material(MaterialLaw::neo_hookean, alpha);
  m.name = name;
  m.damping_model = damping_model;
  return m;
}

TEST(ModelHandles, BodyAndMaterialOfAreTheIndexedOnes) {
  Model model;
  const MaterialId soft = model.add_material(grain_material("soft", 0.0, DampingModel::objective));
  const MaterialId hard = model.add_material(grain_material("hard", 0.2, DampingModel::objective));
  const BodyId a = scenes::add_disc(model, soft, Vec2(0, 0), 1.0, 0.3, "a");
  const BodyId b = scenes::add_disc(model, hard, Vec2(3, 0), 1.0, 0.3, "b");
  EXPECT_EQ(&model.body(a), &model.bodies[0]);
  EXPECT_EQ(&model.body(b), &model.bodies[1]);
  EXPECT_EQ(model.body(b).name, "b");
  EXPECT_EQ(&model.material(hard), &model.materials[1]);
  EXPECT_EQ(&model.material_of(a), &model.materials[0]);
  EXPECT_EQ(&model.material_of(b), &model.materials[1]);
  EXPECT_EQ(model.material_of(b).damping, 0.2);
}

TEST(ModelHandles, IsDampedForEveryDampingModelOnlyWithPositiveAlphaOnADeformableBody) {
  for (const DampingModel damping_model : kDampingModels) {
    Model model;
    const MaterialId damped = model.add_material(grain_material("damped", 0.05, damping_model));
    const MaterialId undamped = model.add_material(grain_material("undamped", 0.0, damping_model));
    const BodyId grain = scenes::add_disc(model, damped, Vec2(0, 0), 1.0, 0.3, "grain");
    const BodyId still = scenes::add_disc(model, undamped, Vec2(3, 0), 1.0, 0.3, "still");
    // A rigid body of the damped material: no viscous force acts on it.
    const BodyId plate =
        model.add_rigid_body("plate", make_rectangle(Vec2(-2, -3), Vec2(5, -2), 1.0), damped);
    EXPECT_TRUE(model.is_damped(grain)) << to_string(damping_model);
    EXPECT_FALSE(model.is_damped(still)) << to_string(damping_model);
    EXPECT_FALSE(model.is_damped(plate)) << to_string(damping_model);
  }
}

TEST(ModelHandles, ADrivenDeformableStripIsDampedToo) {
  // The back face's drive changes how the integrator treats the viscosity
  // (solver/implicit_viscosity.h), not whether the body is damped.
  Model model;
  const BodyId strip = scenes::add_flat_rubber_strip(model);
  ASSERT_GE(model.body(strip).node_drive, 0);
  EXPECT_TRUE(model.is_damped(strip));
}

}  // namespace
}  // namespace sg
