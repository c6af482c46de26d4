// [[materials]], [[grains]] and [[walls]] of a scenario file (scenario_readers.h).
#include <string>

#include "core/error.h"
#include "scenario/scenario_readers.h"

namespace sg {

namespace {

MaterialDef read_material(const TomlReader& t) {
  t.reject_unknown_keys({"name", "law", "young", "poisson", "density", "damping"});
  MaterialDef m;
  m.name = t.string("name");
  const std::string law = t.one_of("law", {"neo_hookean", "saint_venant_kirchhoff"}, "neo_hookean");
  m.law = law == "neo_hookean" ? MaterialLaw::neo_hookean : MaterialLaw::saint_venant_kirchhoff;
  m.young = t.positive("young");
  m.poisson = t.number("poisson", 0.3);
  if (!(m.poisson > -1.0 && m.poisson < 0.5))
    t.fail("poisson", "expected a number in (-1, 0.5), got " + std::to_string(m.poisson));
  m.density = t.positive("density", 1.0);
  m.damping = t.non_negative("damping", 0.0);
  return m;
}

GrainSpec read_grain(const TomlReader& t, std::size_t index) {
  t.reject_unknown_keys({"name", "shape", "center", "radius", "semi_axes", "angle", "material",
                         "velocity", "spin", "stretch", "rigid"});
  GrainSpec g;
  g.name = t.string("name", "grain_" + std::to_string(index));
  g.shape = t.one_of("shape", {"disc", "ellipse"}, "disc") == "disc" ? GrainShape::disc
                                                                     : GrainShape::ellipse;
  g.center = t.vec2("center");
  if (g.shape == GrainShape::disc) {
    g.radius = t.positive("radius");
  } else {
    g.semi_axes = t.vec2("semi_axes");
    if (!(g.semi_axes.x() > 0 && g.semi_axes.y() > 0))
      t.fail("semi_axes", "expected two positive semi-axes [a, b]");
    g.angle = t.number("angle", 0.0);
  }
  g.material = t.string("material");
  g.velocity = t.vec2("velocity", Vec2::Zero());
  g.spin = t.number("spin", 0.0);
  g.stretch = t.vec2("stretch", Vec2(1.0, 1.0));
  if (!(g.stretch.x() > 0 && g.stretch.y() > 0))
    t.fail("stretch", "expected two positive stretch ratios [sx, sy]");
  g.rigid = t.boolean("rigid", false);
  if (g.rigid && g.stretch != Vec2(1.0, 1.0))
    t.fail("stretch", "a rigid grain cannot be stretched");
  return g;
}

WallDef read_wall(const TomlReader& t, std::size_t index) {
  t.reject_unknown_keys({"name", "lower_left", "upper_right", "material", "velocity"});
  WallDef w;
  w.name = t.string("name", "wall_" + std::to_string(index));
  w.lower_left = t.vec2("lower_left");
  w.upper_right = t.vec2("upper_right");
  if (!(w.upper_right.x() > w.lower_left.x() && w.upper_right.y() > w.lower_left.y()))
    t.fail("upper_right", "expected a corner above and to the right of lower_left");
  w.material = t.string("material");
  w.velocity = t.vec2("velocity", Vec2::Zero());
  return w;
}

}  // namespace

std::set<std::string> read_materials(const TomlReader& root, ScenarioDef& s) {
  std::set<std::string> material_names;
  for (const TomlReader& t : root.array_of_tables("materials")) {
    s.materials.push_back(read_material(t));
    if (!material_names.insert(s.materials.back().name).second)
      t.fail("name", "material '" + s.materials.back().name + "' is defined twice");
  }
  if (s.materials.empty()) root.fail("materials", "at least one [[materials]] table is required");
  return material_names;
}

void read_grains(const TomlReader& root, ScenarioDef& s,
                 const std::set<std::string>& material_names, std::set<std::string>& body_names) {
  const std::vector<TomlReader> grains = root.array_of_tables("grains");
  if (grains.empty() && !s.shear_cell && !s.compaction_box)
    root.fail("grains",
              "at least one [[grains]] table (or a [shear_cell] or [compaction_box]) is required");
  for (std::size_t i = 0; i < grains.size(); ++i) {
    s.grains.push_back(read_grain(grains[i], i));
    if (!material_names.count(s.grains.back().material))
      grains[i].fail("material", "unknown material '" + s.grains.back().material + "'");
    if (!body_names.insert(s.grains.back().name).second)
      grains[i].fail("name", "grain name '" + s.grains.back().name + "' is used twice");
  }
}

void read_walls(const TomlReader& root, ScenarioDef& s, const std::set<std::string>& material_names,
                std::set<std::string>& body_names) {
  const std::vector<TomlReader> walls = root.array_of_tables("walls");
  for (std::size_t i = 0; i < walls.size(); ++i) {
    s.walls.push_back(read_wall(walls[i], i));
    if (!material_names.count(s.walls.back().material))
      walls[i].fail("material", "unknown material '" + s.walls.back().material + "'");
    if (!body_names.insert(s.walls.back().name).second)
      walls[i].fail("name", "body name '" + s.walls.back().name + "' is used twice");
  }
}

}  // namespace sg
