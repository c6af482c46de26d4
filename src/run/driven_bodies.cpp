#include "run/driven_bodies.h"

#include "model/kinematics.h"

namespace sg {

namespace {

bool is_driven(const Model& model, const Body& body) {
  if (body.kind != BodyKind::rigid)
    return body.node_drive >= 0 &&
           model.node_drives[static_cast<std::size_t>(body.node_drive)].drives_any();
  const RigidDrive& d = model.rigid.drive[static_cast<std::size_t>(body.rigid_index)];
  return d.mode[0] != DriveMode::free || d.mode[1] != DriveMode::free;
}

}  // namespace

DrivenBodies::DrivenBodies(const Model& model)
    : model_(model), strip_weight_(model.bodies.size(), Vec2::Zero()) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (!is_driven(model, body)) continue;
    const auto id = static_cast<BodyId>(b);
    bodies_.push_back(id);
    if (body.name == "top") top_ = id;
    if (body.kind == BodyKind::rigid) continue;
    double mass = 0.0;
    for (int i = body.node_begin; i < body.node_end; ++i)
      mass += model.nodes.mass[static_cast<std::size_t>(i)];
    strip_weight_[b] = mass / body.mass_scale * model.gravity;
  }
}

Vec2 DrivenBodies::force(BodyId b) const {
  const Body& body = model_.body(b);
  if (body.kind == BodyKind::rigid) {
    const auto r = static_cast<std::size_t>(body.rigid_index);
    return Vec2(model_.rigid.fx[r], model_.rigid.fy[r]);
  }
  return -model_.node_drives[static_cast<std::size_t>(body.node_drive)].reaction -
         strip_weight_[static_cast<std::size_t>(b)];
}

Vec2 DrivenBodies::position(BodyId b) const {
  const Body& body = model_.body(b);
  if (body.kind == BodyKind::rigid) {
    const auto r = static_cast<std::size_t>(body.rigid_index);
    return Vec2(model_.rigid.x[r], model_.rigid.y[r]);
  }
  const NodeDrive& d = model_.node_drives[static_cast<std::size_t>(body.node_drive)];
  Vec2 sum(0, 0);
  for (int i : d.nodes)
    sum += node_position(model_, i);
  return sum / static_cast<double>(d.nodes.size());
}

}  // namespace sg
