#include "model/body_motion.h"

namespace sg {

BodyMotion body_motion(const Model& model, const Body& body) {
  Vec2 x(0, 0), v(0, 0);
  if (body.kind == BodyKind::rigid) {
    const auto r = static_cast<std::size_t>(body.rigid_index);
    return {Vec2(model.rigid.x[r], model.rigid.y[r]), Vec2(model.rigid.vx[r], model.rigid.vy[r])};
  }
  double m = 0.0;
  for (int i = body.node_begin; i < body.node_end; ++i) {
    const auto k = static_cast<std::size_t>(i);
    m += model.nodes.mass[k];
    x += model.nodes.mass[k] *
         Vec2(model.nodes.ref_x[k] + model.nodes.ux[k], model.nodes.ref_y[k] + model.nodes.uy[k]);
    v += model.nodes.mass[k] * Vec2(model.nodes.vx[k], model.nodes.vy[k]);
  }
  return {x / m, v / m};
}

}  // namespace sg
