#include "scenario/shear_cell.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "geometry/packing.h"
#include "geometry/rough_surface.h"
#include "model/kinematics.h"

namespace sg {

namespace {

// Velocity history: `before` until t1, then `after` (a short linear switch of 1e-3 t1).
PiecewiseLinear switch_at(double t1, double before, double after) {
  return PiecewiseLinear{{0.0, t1, t1 * 1.001}, {before, before, after}};
}

}  // namespace

ShearCellInfo add_shear_cell(Model& model, const ShearCellDef& def, MaterialId grain_material,
                             MaterialId first_body_material, const DiscretizationParams& params) {
  SG_VERIFY(def.length > 0.0 && def.grains > 0, "shear cell: length and grains must be positive");
  SG_VERIFY(def.compaction_time > 0.0, "shear cell: compaction_time must be positive");
  const double h = params.mesh.spacing;
  const double period = def.length;
  model.periodic_x = true;
  model.x_min = 0.0;
  model.x_max = period;

  // Rough surfaces, sampled at about the node spacing (independent seeds).
  RoughSurfaceDef rough;
  rough.length = period;
  rough.points = std::max(8, static_cast<int>(std::lround(period / h)));
  rough.hurst = def.hurst;
  rough.rms = def.roughness_rms;
  const RoughProfile bottom_profile = make_rough_profile(rough, def.seed * 2 + 1);
  const RoughProfile top_profile = make_rough_profile(rough, def.seed * 2 + 2);
  const double bottom_peak =
      *std::max_element(bottom_profile.heights.begin(), bottom_profile.heights.end());
  const double top_valley =
      *std::min_element(top_profile.heights.begin(), top_profile.heights.end());

  // Grains packed in a periodic strip above the bottom surface's peaks.
  MixtureDef mixture;
  GrainComponentDef component;
  component.shape.kind = GrainShapeKind::disc;
  component.shape.diameter = def.diameter;
  component.shape.contour_spacing = h;
  mixture.components.push_back(component);
  const std::vector<GrainDef> grains = generate_grains(mixture, def.grains, def.seed);
  PackingDef packing;
  packing.container.kind = ContainerKind::periodic_strip;
  packing.container.x_min = 0.0;
  packing.container.x_max = period;
  packing.container.y_min = bottom_peak + 0.05;
  packing.min_gap = 0.02;
  const PackingResult packed = pack_grains(grains, packing, def.seed);

  ShearCellInfo info;
  info.bottom_mean_y = 0.0;
  info.top_mean_y = packed.top + 0.05 - top_valley;
  info.packed_solid_fraction = packed.solid_fraction;
  info.gap = def.gap > 0.0 ? def.gap : 0.9 * (info.top_mean_y - info.bottom_mean_y);
  SG_VERIFY(info.gap < info.top_mean_y - info.bottom_mean_y,
            "shear cell: gap " << info.gap << " is not smaller than the packed height "
                               << info.top_mean_y - info.bottom_mean_y
                               << " (compaction closes the gap; it cannot open it)");

  // First bodies: the bottom surface runs right to left (material below), the top one left
  // to right (material above), each closed across the seam by one period.
  const double density = model.materials[static_cast<std::size_t>(first_body_material)].density;
  const double mass = density * period * def.first_body_thickness;
  const double inertia =
      mass * (period * period + def.first_body_thickness * def.first_body_thickness) / 12.0;
  const std::size_t n = bottom_profile.heights.size();
  Polygon bottom, top;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = n - 1 - j;
    bottom.emplace_back(static_cast<double>(k) * bottom_profile.spacing(),
                        bottom_profile.heights[k]);
    top.emplace_back(static_cast<double>(j) * top_profile.spacing(),
                     info.top_mean_y + top_profile.heights[j]);
  }
  const BodyId bottom_id =
      model.add_rigid_strip("bottom", bottom, first_body_material, -period, mass, inertia);
  const BodyId top_id =
      model.add_rigid_strip("top", top, first_body_material, period, mass, inertia);
  const double closing_speed =
      (info.top_mean_y - info.bottom_mean_y - info.gap) / def.compaction_time;
  for (BodyId b : {bottom_id, top_id}) {
    RigidDrive& d =
        model.rigid
            .drive[static_cast<std::size_t>(model.bodies[static_cast<std::size_t>(b)].rigid_index)];
    const double sign = b == top_id ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k)
      d.mode[k] = DriveMode::velocity;
    d.velocity[0] = switch_at(def.compaction_time, 0.0, sign * 0.5 * def.velocity);
    d.velocity[1] = b == top_id ? switch_at(def.compaction_time, -closing_speed, 0.0)
                                : PiecewiseLinear::constant(0.0);
    d.velocity[2] = PiecewiseLinear::constant(0.0);
  }

  for (std::size_t i = 0; i < grains.size(); ++i)
    model.add_deformable_body("grain_" + std::to_string(i), packed.contours[i], grain_material,
                              params);
  return info;
}

}  // namespace sg
