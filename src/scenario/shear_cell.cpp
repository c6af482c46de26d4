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

MaterialId material_by_name(const Model& model, const std::string& name) {
  for (std::size_t i = 0; i < model.material_defs.size(); ++i)
    if (model.material_defs[i].name == name) return static_cast<MaterialId>(i);
  SG_THROW("shear cell: unknown grain material '" << name << "'");
}

// The grains, after the two first bodies ("bottom", "top", then "grain_<i>").
void add_grains(Model& model, const std::vector<GrainDef>& grains, const PackingResult& packed,
                const MixtureDef& mixture, MaterialId grain_material,
                const DiscretizationParams& params) {
  // Along the cell (order_along_x); each keeps the name of its place in the drawn population.
  for (const std::size_t i : order_along_x(packed)) {
    const std::string& name =
        mixture.components[static_cast<std::size_t>(grains[i].component)].material;
    const MaterialId material = name.empty() ? grain_material : material_by_name(model, name);
    const std::string body_name = "grain_" + std::to_string(i);
    const NodeSpacing& own =
        mixture.components[static_cast<std::size_t>(grains[i].component)].spacing;
    if (grains[i].rigid)
      model.add_rigid_body(body_name, packed.contours[i], material);
    else
      model.add_deformable_body(body_name, packed.contours[i], material, with_spacing(params, own));
  }
}

// The surfaces of both first bodies about their mean lines, sampled at about the node
// spacing: one period each, (x, height) with x increasing from 0.
struct FirstBodyProfiles {
  std::vector<Vec2> bottom, top;
};
FirstBodyProfiles first_body_profiles(const ShearCellDef& def, double node_spacing) {
  auto profile = [&](const std::optional<SurfaceProfileDef>& given, std::uint64_t seed,
                     const char* name) {
    SurfaceProfileDef self_affine;
    self_affine.rms = def.roughness_rms;
    self_affine.hurst = def.hurst;
    self_affine.seed = seed;
    return sample_profile(given ? *given : self_affine, 0.0, def.length, node_spacing, name);
  };
  return {profile(def.bottom_profile, def.seed * 2 + 1, "shear cell: bottom profile"),
          profile(def.top_profile, def.seed * 2 + 2, "shear cell: top profile")};
}

double lowest(const std::vector<Vec2>& points) {
  return std::min_element(points.begin(), points.end(),
                          [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); })
      ->y();
}
double highest(const std::vector<Vec2>& points) {
  return std::max_element(points.begin(), points.end(),
                          [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); })
      ->y();
}

// The first bodies' contact surfaces: the bottom one runs right to left (material below), the
// top one left to right (material above), each closed across the seam by one period.
struct FirstBodySurfaces {
  Polygon bottom, top;
};
FirstBodySurfaces first_body_surfaces(const FirstBodyProfiles& profiles, double top_mean_y) {
  FirstBodySurfaces s;
  for (auto p = profiles.bottom.rbegin(); p != profiles.bottom.rend(); ++p)
    s.bottom.emplace_back(p->x(), p->y());
  for (const Vec2& p : profiles.top)
    s.top.emplace_back(p.x(), top_mean_y + p.y());
  return s;
}

// Pressure loading: F = -p L on the top's y, ramped up over the compaction time (a load
// applied at once would drop the top onto the grains), with the servo's viscous force c. The
// critical damping is that of the whole top (rigid, or a strip of the same mass: its area
// between the mean surface line and the back face is L times the thickness) on the layer.
struct ServoLoad {
  PiecewiseLinear load;
  double damping = 0.0;
};
ServoLoad servo_load(const Model& model, const ShearCellDef& def, MaterialId grain_material,
                     double packed_height, double node_spacing, double grain_size, double mass,
                     ShearCellInfo& info) {
  info.normal_force = def.pressure * def.length;
  const MaterialDef& grain = model.material_def(grain_material);
  info.servo_damping =
      def.servo_damping > 0.0
          ? def.servo_damping
          : servo_damping_estimate(grain.young, grain.poisson, packed_height, def.length,
                                   def.contact_stiffness, node_spacing, grain_size, mass);
  return {PiecewiseLinear{{0.0, def.compaction_time}, {0.0, -info.normal_force}},
          info.servo_damping};
}

// Deformable first bodies: strips from the mean surface to a flat back face at the
// thickness, the back faces driven as the rigid bodies of add_rigid_first_bodies (their
// reactions are the forces in series.csv).
void add_deformable_first_bodies(Model& model, const ShearCellDef& def,
                                 const FirstBodyProfiles& profiles,
                                 const FirstBodySurfaces& surfaces, const ShearCellInfo& info,
                                 double closing_speed, const ServoLoad& servo,
                                 MaterialId first_body_material,
                                 const DiscretizationParams& params) {
  const double period = def.length;
  const double bottom_valley = lowest(profiles.bottom);
  const double top_peak = highest(profiles.top);
  SG_VERIFY(def.first_body_thickness > std::max(-bottom_valley, top_peak),
            "shear cell: first_body_thickness " << def.first_body_thickness
                                                << " must exceed the deepest valley / highest "
                                                   "peak of the rough surfaces ("
                                                << std::max(-bottom_valley, top_peak) << ")");
  const BodyId ids[2] = {model.add_deformable_strip("bottom", surfaces.bottom, -period,
                                                    info.bottom_mean_y - def.first_body_thickness,
                                                    first_body_material, params),
                         model.add_deformable_strip("top", surfaces.top, period,
                                                    info.top_mean_y + def.first_body_thickness,
                                                    first_body_material, params)};
  // The back faces switch from closing to sliding with a linear ramp centred on the end of
  // the compaction (so the travel is that of the rigid bodies' sharp switch) and lasting the
  // strip's fundamental shear period T_s = 4 H / c_s (a layer of thickness H fixed at its
  // back, free at its surface): a ramp of one period leaves that mode no residual vibration
  // (the response to a ramp of duration tau rings with amplitude ~ |sin(omega tau / 2)|), where
  // the sharp switch makes a strip ring with a force amplitude of M V omega / 2, larger than
  // the friction force it carries.
  const MaterialDef& fb = model.material_def(first_body_material);
  const double shear_speed = std::sqrt(fb.young / (2.0 * (1.0 + fb.poisson) * fb.density));
  const double ramp = std::min(4.0 * def.first_body_thickness / shear_speed, def.compaction_time);
  const double t0 = def.compaction_time - 0.5 * ramp, t1 = def.compaction_time + 0.5 * ramp;
  auto ramp_between = [&](double before, double after) {
    return PiecewiseLinear{{0.0, t0, t1}, {before, before, after}};
  };
  for (BodyId b : ids) {
    NodeDrive& d = model.node_drives[static_cast<std::size_t>(model.body(b).node_drive)];
    const bool is_top = b == ids[1];
    d.mode[0] = d.mode[1] = DriveMode::velocity;
    d.velocity[0] = ramp_between(0.0, (is_top ? 0.5 : -0.5) * def.velocity);
    d.velocity[1] = is_top ? ramp_between(-closing_speed, 0.0) : PiecewiseLinear::constant(0.0);
    if (is_top && def.normal_load == NormalLoad::pressure) {
      // The back face moves as one in y (a carrier of the back-face nodes' mass, NodeDrive)
      // under the servo load, and slides at +V/2 in x.
      d.mode[1] = DriveMode::load;
      d.load[1] = servo.load;
      d.load_damping[1] = servo.damping;
      d.velocity[1] = PiecewiseLinear::constant(0.0);
    }
    apply_drive(is_top ? def.top_drive : def.bottom_drive, d, is_top ? -period : period);
    // The whole strip starts at its back face's velocity (a rigid strip would): no wave
    // sent through it by a back face set in motion alone at t = 0.
    set_rigid_velocity(model, b, Vec2(d.velocity[0](0.0), d.velocity[1](0.0)), 0.0);
  }
}

// Rigid first bodies: the bottom slides at -V/2 after the compaction, the top closes the gap
// (or is servo-loaded) and then slides at +V/2.
void add_rigid_first_bodies(Model& model, const ShearCellDef& def,
                            const FirstBodySurfaces& surfaces, double closing_speed,
                            const ServoLoad& servo, MaterialId first_body_material) {
  const double period = def.length;
  const double density = model.material(first_body_material).density;
  const double mass = density * period * def.first_body_thickness;
  const double inertia =
      mass * (period * period + def.first_body_thickness * def.first_body_thickness) / 12.0;
  const BodyId bottom_id =
      model.add_rigid_strip("bottom", surfaces.bottom, first_body_material, -period, mass, inertia);
  const BodyId top_id =
      model.add_rigid_strip("top", surfaces.top, first_body_material, period, mass, inertia);
  for (BodyId b : {bottom_id, top_id}) {
    RigidDrive& d = model.rigid.drive[static_cast<std::size_t>(model.body(b).rigid_index)];
    const double sign = b == top_id ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k)
      d.mode[k] = DriveMode::velocity;
    d.velocity[0] = switch_at(def.compaction_time, 0.0, sign * 0.5 * def.velocity);
    d.velocity[1] = b == top_id ? switch_at(def.compaction_time, -closing_speed, 0.0)
                                : PiecewiseLinear::constant(0.0);
    d.velocity[2] = PiecewiseLinear::constant(0.0);
    if (b == top_id && def.normal_load == NormalLoad::pressure) {
      // Servo-controlled confining pressure.
      d.mode[1] = DriveMode::load;
      d.load[1] = servo.load;
      d.load_damping[1] = servo.damping;
      d.velocity[1] = PiecewiseLinear::constant(0.0);
    }
    apply_drive(b == top_id ? def.top_drive : def.bottom_drive, d, b == top_id ? -period : period);
  }
}

}  // namespace

MixtureDef shear_cell_mixture(const ShearCellDef& def, double contour_spacing) {
  MixtureDef mixture;
  if (def.components.empty()) {
    GrainComponentDef component;
    component.shape.kind = GrainShapeKind::disc;
    component.shape.diameter = def.diameter;
    component.material.clear();
    component.spacing = def.grain_spacing;
    mixture.components.push_back(component);
  } else {
    mixture.components = def.components;
  }
  for (GrainComponentDef& c : mixture.components)
    c.shape.contour_spacing = c.spacing.contour > 0.0 ? c.spacing.contour : contour_spacing;
  return mixture;
}

double shear_cell_grain_size(const ShearCellDef& def) {
  if (def.components.empty()) return 0.5 * (def.diameter.min + def.diameter.max);
  return mixture_grain_size(def.components, "shear cell");
}

double servo_damping_estimate(double young, double poisson, double height, double length,
                              double contact_stiffness, double node_spacing, double grain_size,
                              double mass) {
  SG_VERIFY(young > 0.0 && height > 0.0 && length > 0.0 && mass > 0.0,
            "servo damping estimate: E, H, L and m must be positive (E = "
                << young << ", H = " << height << ", L = " << length << ", m = " << mass << ")");
  const double k_layer = young / (1.0 - poisson * poisson) * length / height;
  double k_eff = k_layer;
  if (contact_stiffness > 0.0) {
    const double k_contacts = contact_stiffness * node_spacing * length / grain_size;
    k_eff = 1.0 / (1.0 / k_layer + 1.0 / k_contacts);  // springs in series
  }
  const double zeta = 1.0;  // critical
  return 2.0 * zeta * std::sqrt(k_eff * mass);
}

ShearCellInfo add_shear_cell(Model& model, const ShearCellDef& def, MaterialId grain_material,
                             MaterialId first_body_material, const DiscretizationParams& params,
                             ShearCellParts parts) {
  SG_VERIFY(def.length > 0.0 && def.grains > 0, "shear cell: length and grains must be positive");
  SG_VERIFY(def.compaction_time > 0.0, "shear cell: compaction_time must be positive");
  SG_VERIFY(def.normal_load == NormalLoad::gap || def.pressure > 0.0,
            "shear cell: pressure loading needs a positive pressure, got " << def.pressure);
  SG_VERIFY(def.servo_damping >= 0.0,
            "shear cell: servo_damping must be >= 0, got " << def.servo_damping);
  const double h = params.mesh.spacing;
  // Clearances of the packing scale with the grains (1 for papers 001/002; paper 003 is in
  // metres, with grains of a few 1e-7 m).
  const double grain_size = shear_cell_grain_size(def);
  const double period = def.length;
  model.periodic_x = true;
  model.x_min = 0.0;
  model.x_max = period;

  const double first_body_h =
      def.first_body_spacing.contour > 0.0 ? def.first_body_spacing.contour : h;
  const FirstBodyProfiles profiles = first_body_profiles(def, first_body_h);
  const double bottom_peak = highest(profiles.bottom);
  const double top_valley = lowest(profiles.top);

  // Grains packed in a periodic strip above the bottom surface's peaks.
  const MixtureDef mixture = shear_cell_mixture(def, h);
  const std::vector<GrainDef> grains = generate_grains(mixture, def.grains, def.seed);
  PackingDef packing;
  packing.container.kind = ContainerKind::periodic_strip;
  packing.container.x_min = 0.0;
  packing.container.x_max = period;
  packing.container.y_min = bottom_peak + 0.05 * grain_size;
  packing.min_gap = 0.02 * grain_size;
  const PackingResult packed = pack_grains(grains, packing, def.seed);

  ShearCellInfo info;
  info.bottom_mean_y = 0.0;
  info.top_mean_y = packed.top + 0.05 * grain_size - top_valley;
  info.packed_solid_fraction = packed.solid_fraction;
  const double packed_height = info.top_mean_y - info.bottom_mean_y;
  info.gap = def.normal_load == NormalLoad::pressure ? packed_height
             : def.gap > 0.0                         ? def.gap
                                                     : 0.9 * packed_height;
  SG_VERIFY(def.normal_load == NormalLoad::pressure || info.gap < packed_height,
            "shear cell: gap " << info.gap << " is not smaller than the packed height "
                               << info.top_mean_y - info.bottom_mean_y
                               << " (compaction closes the gap; it cannot open it)");

  const FirstBodySurfaces surfaces = first_body_surfaces(profiles, info.top_mean_y);
  const double closing_speed = (packed_height - info.gap) / def.compaction_time;
  ServoLoad servo;
  if (def.normal_load == NormalLoad::pressure) {
    const double density = model.material(first_body_material).density;
    const double mass = density * period * def.first_body_thickness;
    servo = servo_load(model, def, grain_material, packed_height, h, grain_size, mass, info);
  }
  if (def.first_bodies == FirstBodyKind::deformable)
    add_deformable_first_bodies(model, def, profiles, surfaces, info, closing_speed, servo,
                                first_body_material, with_spacing(params, def.first_body_spacing));
  else
    add_rigid_first_bodies(model, def, surfaces, closing_speed, servo, first_body_material);
  if (parts == ShearCellParts::whole)
    add_grains(model, grains, packed, mixture, grain_material, params);
  return info;
}

}  // namespace sg
