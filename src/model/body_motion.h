#pragma once
// A body's centre of mass and its velocity: the rigid state of a rigid body, the mass-weighted
// mean of the lumped node parameters of a deformable one (exact for the discrete system). What
// grains/NNNNNN.csv records, and what the Python module's bodies() returns.
#include "model/model.h"

namespace sg {

struct BodyMotion {
  Vec2 centre;
  Vec2 velocity;
};

BodyMotion body_motion(const Model& model, const Body& body);

}  // namespace sg
