#pragma once
// The bodies whose forces and positions series.csv reports: rigid bodies with an imposed
// velocity or force on x or y, and deformable first bodies (strips) whose back face is driven
// (NodeDrive).
//
// The force columns have the rigid bodies' meaning: the force the body receives from the
// layer. A rigid body: the contact forces it received. A driven strip: minus the drive's
// reaction R and minus the strip's weight W, i.e. the force the strip transmits to its driven
// back face (what a load cell there measures), which balances the layer's force on the strip
// up to the strip's inertia (zero on average in a steady state). The position columns: the
// rigid body's reference point, or the mean physical position of the strip's back-face nodes.
#include <vector>

#include "geometry/vec2.h"
#include "model/model.h"

namespace sg {

class DrivenBodies {
 public:
  explicit DrivenBodies(const Model& model);

  const std::vector<BodyId>& bodies() const { return bodies_; }
  // Shear cells: the body named "top" (-1: none), whose friction the run summarises.
  BodyId top() const { return top_; }
  // At the last force evaluation.
  Vec2 force(BodyId body) const;
  // Now.
  Vec2 position(BodyId body) const;

 private:
  const Model& model_;
  std::vector<BodyId> bodies_;
  BodyId top_ = -1;
  // Weights of the driven strips (physical mass: gravity acts on it, solver/mass_scaling.h),
  // fixed for the run; zero for the other bodies.
  std::vector<Vec2> strip_weight_;
};

}  // namespace sg
