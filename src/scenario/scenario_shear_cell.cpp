// [shear_cell] of a scenario file and its [[shear_cell.components]] (scenario_readers.h).
#include <cstdint>
#include <string>

#include "scenario/scenario_readers.h"

namespace sg {

namespace {

// A size range [min, max] (length), 0 < min <= max.
SizeRangeDef read_size_range(const TomlReader& t, const char* key) {
  const Vec2 r = t.vec2(key);
  if (!(r.x() > 0 && r.y() >= r.x())) t.fail(key, "expected [min, max] with 0 < min <= max");
  return SizeRangeDef{r.x(), r.y(), SizeLaw::uniform};
}

// One [[shear_cell.components]]: a shape law, its number fraction, material and kind.
GrainComponentDef read_shear_cell_component(const TomlReader& t,
                                            const std::set<std::string>& material_names) {
  // node_spacing and interior_spacing: read by resolve_shear_cell_spacing, over the material's.
  t.reject_unknown_keys({"name", "shape", "fraction", "diameter", "major_axis", "minor_axis",
                         "material", "rigid", "node_spacing", "interior_spacing"});
  GrainComponentDef c;
  c.shape.kind = t.one_of("shape", {"disc", "ellipse"}, "disc") == "disc" ? GrainShapeKind::disc
                                                                          : GrainShapeKind::ellipse;
  c.name = t.string("name", c.shape.kind == GrainShapeKind::disc ? "discs" : "ellipses");
  c.number_fraction = t.positive("fraction");
  if (c.shape.kind == GrainShapeKind::disc) {
    c.shape.diameter = read_size_range(t, "diameter");
    for (const char* key : {"major_axis", "minor_axis"})
      if (t.has(key)) t.fail(key, "applies only to shape = \"ellipse\"");
  } else {
    // Full axis lengths; paper 003: long 1-2 um, short 0.6-1.2 um.
    c.shape.major_axis = read_size_range(t, "major_axis");
    c.shape.minor_axis = read_size_range(t, "minor_axis");
    if (c.shape.minor_axis.min > c.shape.major_axis.max)
      t.fail("minor_axis", "expected a short axis range that starts below the long axis range");
    if (t.has("diameter")) t.fail("diameter", "applies only to shape = \"disc\"");
  }
  c.material = t.string("material", "");
  if (!c.material.empty() && !material_names.count(c.material))
    t.fail("material", "unknown material '" + c.material + "'");
  c.rigid = t.boolean("rigid", false);
  return c;
}

// Gap or pressure loading, and the pressure loading's servo.
void read_normal_load(const TomlReader& t, ShearCellDef& c) {
  c.normal_load = t.one_of("normal_load", {"gap", "pressure"}, "gap") == "gap"
                      ? NormalLoad::gap
                      : NormalLoad::pressure;
  if (c.normal_load == NormalLoad::pressure) {
    c.pressure = t.positive("pressure");
    c.servo_damping = t.non_negative("servo_damping", 0.0);
    if (t.has("gap"))
      t.fail("gap", "the gap is an output under normal_load = \"pressure\" (remove it)");
  } else {
    for (const char* key : {"pressure", "servo_damping"})
      if (t.has(key)) t.fail(key, "applies only with normal_load = \"pressure\"");
  }
}

}  // namespace

ShearCellDef read_shear_cell(const TomlReader& t, const std::set<std::string>& material_names) {
  t.reject_unknown_keys({"length",
                         "grains",
                         "diameter",
                         "grain_material",
                         "first_body_material",
                         "roughness_rms",
                         "hurst",
                         "first_body_thickness",
                         "gap",
                         "compaction_time",
                         "velocity",
                         "seed",
                         "normal_load",
                         "pressure",
                         "servo_damping",
                         "components",
                         "first_bodies",
                         "bottom_profile",
                         "top_profile",
                         "bottom_drive",
                         "top_drive"});
  ShearCellDef c;
  c.length = t.positive("length", c.length);
  // At most 10^6 grains: a paper-size sample has 2000 to 3000; 10^6 deformable ones would
  // take over 10^8 nodes.
  c.grains = static_cast<int>(t.integer_in("grains", c.grains, 1, 1000000));
  const Vec2 d = t.vec2("diameter", Vec2(0.85, 1.15));
  if (!(d.x() > 0 && d.y() >= d.x())) t.fail("diameter", "expected [min, max] with 0 < min <= max");
  c.diameter.min = d.x();
  c.diameter.max = d.y();
  c.grain_material = t.string("grain_material");
  c.first_body_material = t.string("first_body_material");
  for (const char* key : {"grain_material", "first_body_material"})
    if (!material_names.count(t.string(key)))
      t.fail(key, "unknown material '" + t.string(key) + "'");
  c.roughness_rms = t.non_negative("roughness_rms", c.roughness_rms);
  c.hurst = t.number("hurst", c.hurst);
  if (!(c.hurst > 0 && c.hurst < 1)) t.fail("hurst", "expected a number in (0, 1)");
  c.first_body_thickness = t.positive("first_body_thickness", c.first_body_thickness);
  read_normal_load(t, c);
  c.first_bodies = t.one_of("first_bodies", {"rigid", "deformable"}, "rigid") == "rigid"
                       ? FirstBodyKind::rigid
                       : FirstBodyKind::deformable;
  for (const TomlReader& ct : t.array_of_tables("components")) {
    if (t.has("diameter"))
      t.fail("diameter", "give the sizes in [[shear_cell.components]], not both");
    c.components.push_back(read_shear_cell_component(ct, material_names));
  }
  c.gap = t.non_negative("gap", 0.0);
  c.compaction_time = t.positive("compaction_time", c.compaction_time);
  c.velocity = t.number("velocity", c.velocity);
  const long seed = t.integer("seed", 1);
  if (seed < 0) t.fail("seed", "expected an integer >= 0");
  c.seed = static_cast<std::uint64_t>(seed);
  const char* sides[2] = {"bottom", "top"};
  for (int k = 0; k < 2; ++k) {
    const std::string side = sides[k];
    if (auto p = t.table(side + "_profile")) {
      SurfaceProfileDef defaults;
      defaults.rms = c.roughness_rms;
      defaults.hurst = c.hurst;
      defaults.seed = c.seed * 2 + static_cast<std::uint64_t>(k + 1);
      (k == 0 ? c.bottom_profile : c.top_profile) = read_profile(*p, defaults);
      check_profile(*p, k == 0 ? *c.bottom_profile : *c.top_profile, 0.0, c.length);
    }
    if (auto drive = t.table(side + "_drive"))
      (k == 0 ? c.bottom_drive : c.top_drive) =
          read_drive(*drive, c.first_bodies == FirstBodyKind::rigid, true);
  }
  return c;
}

}  // namespace sg
