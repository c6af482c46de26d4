#include "scenario/compaction_box.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "geometry/shapes.h"
#include "scenario/toml_reader.h"

namespace sg {

namespace {

MaterialId material_by_name(const Model& model, const std::string& name) {
  for (std::size_t i = 0; i < model.material_defs.size(); ++i)
    if (model.material_defs[i].name == name) return static_cast<MaterialId>(i);
  SG_THROW("compaction box: unknown material '" << name << "'");
}

// A wall: a rectangle driven at an imposed velocity (x, y, theta), zero but for the lid's y.
BodyId add_wall(Model& model, const std::string& name, const Vec2& lower_left,
                const Vec2& upper_right, MaterialId material, double spacing,
                const PiecewiseLinear& vy) {
  const BodyId b =
      model.add_rigid_body(name, make_rectangle(lower_left, upper_right, spacing), material);
  const auto r = static_cast<std::size_t>(model.body(b).rigid_index);
  RigidDrive& drive = model.rigid.drive[r];
  for (int d = 0; d < 3; ++d) {
    drive.mode[d] = DriveMode::velocity;
    drive.velocity[d] = PiecewiseLinear::constant(0.0);
  }
  drive.velocity[1] = vy;
  model.rigid.vy[r] = vy(0.0);
  return b;
}

SizeRangeDef read_size_range(const TomlReader& t, const char* key, SizeLaw law) {
  const Vec2 r = t.vec2(key);
  if (!(r.x() > 0 && r.y() >= r.x())) t.fail(key, "expected [min, max] with 0 < min <= max");
  return SizeRangeDef{r.x(), r.y(), law};
}

}  // namespace

double compaction_box_grain_size(const CompactionBoxDef& def) {
  return mixture_grain_size(def.components, "compaction box");
}

MixtureDef compaction_box_mixture(const CompactionBoxDef& def, double spacing) {
  MixtureDef mixture;
  mixture.components = def.components;
  for (GrainComponentDef& c : mixture.components)
    c.shape.contour_spacing = spacing;
  return mixture;
}

PiecewiseLinear lid_speed_history(const CompactionBoxDef& def, double initial_height,
                                  double& stop_time, double& travelled) {
  const double v = def.lid_velocity, ramp = def.lid_ramp_time;
  SG_VERIFY(v > 0.0, "compaction box: lid_velocity must be positive (downwards), got " << v);
  SG_VERIFY((def.final_height > 0.0) != (def.compaction_time > 0.0),
            "compaction box: give exactly one of final_height and compaction_time");
  // Trapezoid 0 -> V over the ramp, V, V -> 0 over the ramp: travel = V (T - ramp). Without a
  // ramp the lid starts at V and stops over a short 1e-3 T (a jump would be one step of
  // infinite deceleration; the travel stays exact through the formula).
  if (def.final_height > 0.0) {
    SG_VERIFY(def.final_height < initial_height,
              "compaction box: final_height "
                  << def.final_height << " must be below the initial height " << initial_height);
    travelled = initial_height - def.final_height;
    if (ramp > 0.0) {
      stop_time = travelled / v + ramp;
    } else {
      stop_time = travelled / v / (1.0 - 0.5e-3);
    }
  } else {
    stop_time = def.compaction_time;
    travelled = v * (ramp > 0.0 ? stop_time - ramp : stop_time * (1.0 - 0.5e-3));
    SG_VERIFY(travelled < initial_height, "compaction box: the lid would travel "
                                              << travelled << " in compaction_time " << stop_time
                                              << ", through the whole box of height "
                                              << initial_height);
  }
  if (ramp > 0.0) {
    SG_VERIFY(stop_time >= 2.0 * ramp, "compaction box: lid_ramp_time "
                                           << ramp << " is too long: the motion lasts only "
                                           << stop_time << " (it needs two ramps)");
    if (stop_time == 2.0 * ramp) return PiecewiseLinear{{0.0, ramp, stop_time}, {0.0, v, 0.0}};
    return PiecewiseLinear{{0.0, ramp, stop_time - ramp, stop_time}, {0.0, v, v, 0.0}};
  }
  return PiecewiseLinear{{0.0, stop_time * (1.0 - 1e-3), stop_time}, {v, v, 0.0}};
}

CompactionBoxInfo add_compaction_box(Model& model, const CompactionBoxDef& def,
                                     MaterialId grain_material, MaterialId wall_material,
                                     const DiscretizationParams& params) {
  SG_VERIFY(!model.periodic_x, "compaction box: the model must not be periodic");
  SG_VERIFY(def.width > 0.0 && def.grains > 0,
            "compaction box: width and grains must be positive (width = "
                << def.width << ", grains = " << def.grains << ")");
  SG_VERIFY(def.settle || def.height > 0.0,
            "compaction box: settle = false needs the initial height (height = 0 means 'above "
            "the settled grains')");
  const double h = params.mesh.spacing;
  const double grain_size = compaction_box_grain_size(def);
  CompactionBoxInfo info;
  info.clearance = h;
  SG_VERIFY(h < 0.5 * grain_size, "compaction box: node spacing "
                                      << h << " must be below half the grain size " << grain_size
                                      << " (the walls' clearance is one node spacing)");

  info.grains = generate_grains(compaction_box_mixture(def, h), def.grains, def.seed);
  for (const GrainDef& g : info.grains) {
    info.grain_area += signed_area(g.contour);
    ++(g.rigid ? info.rigid_grains : info.deformable_grains);
  }

  // Placement: RSA in the box (the given height, or a loose region of solid fraction 0.3
  // when the lid is to sit on the deposit), then Monte Carlo settling onto the floor.
  PackingDef packing;
  packing.container.kind = ContainerKind::box;
  packing.container.x_min = 0.0;
  packing.container.x_max = def.width;
  packing.container.y_min = 0.0;
  double max_radius = 0.0;
  for (const GrainDef& g : info.grains)
    max_radius = std::max(max_radius, g.bounding_radius);
  packing.container.y_max =
      def.height > 0.0 ? def.height : info.grain_area / (0.3 * def.width) + 2.0 * max_radius;
  packing.min_gap = 0.02 * grain_size;
  packing.compact = def.settle;
  const PackingResult packed = pack_grains(info.grains, packing, def.seed);
  info.packed_top = packed.top;
  info.height = def.height > 0.0 ? def.height : packed.top + 0.02 * grain_size;
  info.solid_fraction = info.grain_area / (def.width * info.height);
  SG_VERIFY(def.final_height == 0.0 || def.final_height * def.width > info.grain_area,
            "compaction box: final_height "
                << def.final_height << " leaves less area than the grains' " << info.grain_area
                << " (solid fraction " << info.grain_area / (def.final_height * def.width)
                << " > 1)");
  double travelled = 0.0;
  const PiecewiseLinear speed = lid_speed_history(def, info.height, info.stop_time, travelled);
  info.final_height = info.height - travelled;
  PiecewiseLinear lid_vy = speed;
  for (double& value : lid_vy.values)
    value = -value;

  // Walls first ("bottom", "left", "right", "lid"), then the grains along x (order_along_x),
  // each named grain_<i> after its place in the drawn population.
  const double t = def.wall_thickness > 0.0 ? def.wall_thickness : grain_size;
  const double c = info.clearance, w = def.width, top = info.height + t;
  const PiecewiseLinear still = PiecewiseLinear::constant(0.0);
  add_wall(model, "bottom", Vec2(-t, -t), Vec2(w + t, 0.0), wall_material, h, still);
  add_wall(model, "left", Vec2(-t, c), Vec2(0.0, top), wall_material, h, still);
  add_wall(model, "right", Vec2(w, c), Vec2(w + t, top), wall_material, h, still);
  add_wall(model, "lid", Vec2(c, info.height), Vec2(w - c, info.height + t), wall_material, h,
           lid_vy);

  for (const std::size_t i : order_along_x(packed)) {
    const GrainDef& g = info.grains[i];
    const MaterialId material =
        g.material.empty() ? grain_material : material_by_name(model, g.material);
    const std::string name = "grain_" + std::to_string(i);
    if (g.rigid)
      model.add_rigid_body(name, packed.contours[i], material);
    else
      model.add_deformable_body(name, packed.contours[i], material, params);
  }
  return info;
}

GrainComponentDef read_grain_component(const TomlReader& t,
                                       const std::set<std::string>& materials) {
  t.reject_unknown_keys({"name", "shape", "fraction", "diameter", "size_law", "major_axis",
                         "minor_axis", "elongation", "irregularity", "roughness", "max_mode",
                         "amplitude_scatter", "material", "rigid"});
  GrainComponentDef c;
  const std::string shape = t.one_of("shape", {"disc", "ellipse", "fourier"}, "disc");
  c.shape.kind = shape == "disc"      ? GrainShapeKind::disc
                 : shape == "ellipse" ? GrainShapeKind::ellipse
                                      : GrainShapeKind::fourier;
  c.name = t.string("name", shape == "disc"      ? "discs"
                            : shape == "ellipse" ? "ellipses"
                                                 : "fourier");
  c.number_fraction = t.positive("fraction");
  const std::string law_name =
      t.one_of("size_law", {"uniform", "uniform_area", "log_uniform"}, "uniform");
  const SizeLaw law = law_name == "uniform"        ? SizeLaw::uniform
                      : law_name == "uniform_area" ? SizeLaw::uniform_area
                                                   : SizeLaw::log_uniform;
  if (c.shape.kind != GrainShapeKind::ellipse) {
    // Disc: the diameter; Fourier: twice the mean radius r_mean.
    c.shape.diameter = read_size_range(t, "diameter", law);
    for (const char* key : {"major_axis", "minor_axis"})
      if (t.has(key)) t.fail(key, "applies only to shape = \"ellipse\"");
  } else {
    c.shape.major_axis = read_size_range(t, "major_axis", law);
    c.shape.minor_axis = read_size_range(t, "minor_axis", law);
    if (c.shape.minor_axis.min > c.shape.major_axis.max)
      t.fail("minor_axis", "expected a short axis range that starts below the long axis range");
    if (t.has("diameter")) t.fail("diameter", "applies only to shape = \"disc\" or \"fourier\"");
  }
  if (c.shape.kind == GrainShapeKind::fourier) {
    // Mollon & Zhao 2012 descriptors D_2, D_3, D_8, relative to the mean radius.
    FourierSpectrumDef& s = c.shape.spectrum;
    s.elongation = t.non_negative("elongation", 0.0);
    s.irregularity = t.non_negative("irregularity", 0.0);
    s.roughness = t.non_negative("roughness", 0.0);
    const long max_mode = t.integer("max_mode", s.max_mode);
    if (max_mode < 2 || max_mode > 64) t.fail("max_mode", "expected an integer in [2, 64]");
    s.max_mode = static_cast<int>(max_mode);
    s.amplitude_scatter = t.non_negative("amplitude_scatter", 0.0);
    if (s.amplitude_scatter >= 1.0) t.fail("amplitude_scatter", "expected a number in [0, 1)");
    if (s.elongation + s.irregularity + s.roughness >= 0.5)
      t.fail("elongation",
             "expected D_2 + D_3 + D_8 < 0.5 (larger amplitudes give grains "
             "with a non-positive radius)");
  } else {
    for (const char* key :
         {"elongation", "irregularity", "roughness", "max_mode", "amplitude_scatter"})
      if (t.has(key)) t.fail(key, "applies only to shape = \"fourier\"");
  }
  c.material = t.string("material", "");
  if (!c.material.empty() && !materials.count(c.material))
    t.fail("material", "unknown material '" + c.material + "'");
  c.rigid = t.boolean("rigid", false);
  return c;
}

CompactionBoxDef read_compaction_box(const TomlReader& t, const std::set<std::string>& materials) {
  t.reject_unknown_keys({"width", "height", "grains", "components", "grain_material",
                         "wall_material", "wall_thickness", "settle", "lid_velocity",
                         "lid_ramp_time", "final_height", "compaction_time", "seed"});
  CompactionBoxDef b;
  b.width = t.positive("width");
  b.height = t.non_negative("height", 0.0);
  // At most 10^6 grains: a paper-size sample has 2000 to 3000; 10^6 deformable ones would
  // take over 10^8 nodes.
  b.grains = static_cast<int>(t.integer_in("grains", b.grains, 1, 1000000));
  for (const TomlReader& ct : t.array_of_tables("components"))
    b.components.push_back(read_grain_component(ct, materials));
  if (b.components.empty())
    t.fail("components", "expected at least one [[compaction_box.components]] table");
  b.grain_material = t.string("grain_material", "");
  if (b.grain_material.empty()) {
    for (const GrainComponentDef& c : b.components)
      if (c.material.empty())
        t.fail("grain_material", "required when a component gives no material");
  } else if (!materials.count(b.grain_material)) {
    t.fail("grain_material", "unknown material '" + b.grain_material + "'");
  }
  b.wall_material = t.string("wall_material");
  if (!materials.count(b.wall_material))
    t.fail("wall_material", "unknown material '" + b.wall_material + "'");
  b.wall_thickness = t.non_negative("wall_thickness", 0.0);
  b.settle = t.boolean("settle", true);
  if (!b.settle && b.height == 0.0)
    t.fail("height", "settle = false needs the initial height (the grains fill the box)");
  b.lid_velocity = t.positive("lid_velocity");
  b.lid_ramp_time = t.non_negative("lid_ramp_time", 0.0);
  b.final_height = t.non_negative("final_height", 0.0);
  b.compaction_time = t.non_negative("compaction_time", 0.0);
  if ((b.final_height > 0.0) == (b.compaction_time > 0.0))
    t.fail("final_height", "give exactly one of final_height (length) and compaction_time (time)");
  if (b.height > 0.0 && b.final_height >= b.height)
    t.fail("final_height",
           "expected a final height below the initial height " + std::to_string(b.height));
  if (b.compaction_time > 0.0 && b.compaction_time < 2.0 * b.lid_ramp_time)
    t.fail("lid_ramp_time", "expected at most half of compaction_time (a ramp up and one down)");
  const long seed = t.integer("seed", 1);
  if (seed < 0) t.fail("seed", "expected an integer >= 0");
  b.seed = static_cast<std::uint64_t>(seed);
  return b;
}

}  // namespace sg
