#include "scenario/body_builders.h"

#include <cmath>

#include "core/error.h"
#include "geometry/shapes.h"
#include "model/kinematics.h"

namespace sg {

namespace {

// A drive's velocity at t = 0 on the axes it drives by velocity, `fallback` on the others.
double initial_velocity(const RigidDrive& drive, int axis, double fallback) {
  return drive.mode[axis] == DriveMode::velocity ? drive.velocity[axis](0.0) : fallback;
}

}  // namespace

Polygon grain_contour(const GrainSpec& g, double h) {
  switch (g.shape) {
    case GrainShape::disc:
      return make_disc(g.center, g.radius, h);
    case GrainShape::ellipse:
      return make_ellipse(g.center, g.semi_axes.x(), g.semi_axes.y(), g.angle, h);
    case GrainShape::contour:
      break;
  }
  Polygon out;
  for (std::size_t i = 0; i < g.contour.size(); ++i) {
    const Vec2 a = g.contour[i], b = g.contour[(i + 1) % g.contour.size()];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / h)));
    for (int k = 0; k < pieces; ++k)
      out.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
  }
  return out;
}

void add_rigid_grain(Model& model, const GrainSpec& g, MaterialId material, double h) {
  const BodyId b = model.add_rigid_body(g.name, grain_contour(g, h), material);
  const auto r = static_cast<std::size_t>(model.body(b).rigid_index);
  apply_drive(g.drive, model.rigid.drive[r], 0.0);
  const RigidDrive& d = model.rigid.drive[r];
  model.rigid.vx[r] = initial_velocity(d, 0, g.velocity.x());
  model.rigid.vy[r] = initial_velocity(d, 1, g.velocity.y());
  model.rigid.omega[r] = initial_velocity(d, 2, g.spin);
}

void add_wall(Model& model, const WallDef& w, MaterialId material, double h) {
  const BodyId b =
      model.add_rigid_body(w.name, make_rectangle(w.lower_left, w.upper_right, h), material);
  const auto r = static_cast<std::size_t>(model.body(b).rigid_index);
  RigidDrive& drive = model.rigid.drive[r];
  const double v[3] = {w.velocity.x(), w.velocity.y(), 0.0};
  for (int d = 0; d < 3; ++d) {
    drive.mode[d] = DriveMode::velocity;
    drive.velocity[d] = PiecewiseLinear::constant(v[d]);
  }
  if (!w.drive.any()) return;
  apply_drive(w.drive, drive, 0.0);
  model.rigid.vx[r] = initial_velocity(drive, 0, 0.0);
  model.rigid.vy[r] = initial_velocity(drive, 1, 0.0);
  model.rigid.omega[r] = initial_velocity(drive, 2, 0.0);
}

void add_strip(Model& model, const StripDef& strip, MaterialId material, double x_min, double x_max,
               const DiscretizationParams& params) {
  const double period = x_max - x_min;
  const double h = params.mesh.spacing;
  const std::string what = "strip '" + strip.name + "'";
  const std::vector<Vec2> profile = sample_profile(strip.profile, x_min, period, h, what);
  // The material on the left of the direction of travel: a strip above the gap runs left to
  // right, one below it right to left (Model::add_rigid_strip).
  const bool above = strip.above();
  Polygon surface;
  for (std::size_t j = 0; j < profile.size(); ++j) {
    const Vec2& p = profile[above ? j : profile.size() - 1 - j];
    surface.emplace_back(p.x(), strip.surface_y + p.y());
    SG_VERIFY(above ? strip.back_y > surface.back().y() : strip.back_y < surface.back().y(),
              what << ": the back face y = " << strip.back_y << " cuts the surface at x = " << p.x()
                   << " (y = " << surface.back().y() << ")");
  }
  const double shift = above ? period : -period;
  // Pressure on the back face pushes the strip towards the gap.
  const double pressure_force = above ? -period : period;
  if (strip.rigid) {
    const double thickness = std::abs(strip.back_y - strip.surface_y);
    const double mass = model.material(material).density * period * thickness;
    const double inertia = mass * (period * period + thickness * thickness) / 12.0;
    const BodyId b = model.add_rigid_strip(strip.name, surface, material, shift, mass, inertia);
    RigidDrive& d = model.rigid.drive[static_cast<std::size_t>(model.body(b).rigid_index)];
    for (int k = 0; k < 3; ++k) {
      d.mode[k] = DriveMode::velocity;
      d.velocity[k] = PiecewiseLinear::constant(0.0);
    }
    apply_drive(strip.drive, d, pressure_force);
    const auto r = static_cast<std::size_t>(model.body(b).rigid_index);
    model.rigid.vx[r] = initial_velocity(d, 0, 0.0);
    model.rigid.vy[r] = initial_velocity(d, 1, 0.0);
    return;
  }
  const BodyId b =
      model.add_deformable_strip(strip.name, surface, shift, strip.back_y, material, params);
  NodeDrive& d = model.node_drives[static_cast<std::size_t>(model.body(b).node_drive)];
  for (int k = 0; k < 2; ++k) {
    d.mode[k] = DriveMode::velocity;
    d.velocity[k] = PiecewiseLinear::constant(0.0);
  }
  apply_drive(strip.drive, d, pressure_force);
  // The whole strip starts at its back face's velocity (as the shear cell's strips).
  auto v0 = [&](int k) { return d.mode[k] == DriveMode::velocity ? d.velocity[k](0.0) : 0.0; };
  set_rigid_velocity(model, b, Vec2(v0(0), v0(1)), 0.0);
}

}  // namespace sg
