#include "scenario/scenario.h"

#include <set>

#include "core/error.h"
#include "geometry/shapes.h"
#include "model/kinematics.h"
#include "scenario/toml_reader.h"

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

GrainDef read_grain(const TomlReader& t, std::size_t index) {
  t.reject_unknown_keys({"name", "shape", "center", "radius", "semi_axes", "angle", "material",
                         "velocity", "spin", "stretch"});
  GrainDef g;
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
  return g;
}

}  // namespace

ScenarioDef load_scenario(const std::filesystem::path& file) {
  const TomlDocument document(file);
  const TomlReader root = document.root();
  root.reject_unknown_keys({"name", "time", "output", "discretization", "physics", "materials",
                            "grains"});
  ScenarioDef s;
  s.source = file;
  s.name = root.string("name", file.stem().string());
  if (auto t = root.table("time")) {
    t->reject_unknown_keys({"duration", "safety", "fixed_step"});
    s.duration = t->positive("duration");
    s.time_step_safety = t->positive("safety", 0.8);
    if (s.time_step_safety > 1.0) t->fail("safety", "expected a number in (0, 1]");
    s.fixed_time_step = t->non_negative("fixed_step", 0.0);
  } else {
    root.fail("time", "required table [time] with 'duration' is missing");
  }
  if (auto t = root.table("output")) {
    t->reject_unknown_keys({"directory", "series_period", "field_period"});
    s.output_root = t->string("directory", "out");
    s.series_period = t->non_negative("series_period", 0.0);
    s.field_period = t->non_negative("field_period", 0.0);
  }
  if (s.series_period == 0.0) s.series_period = s.duration / 200.0;
  if (s.field_period == 0.0) s.field_period = s.duration / 20.0;
  if (auto t = root.table("discretization")) {
    t->reject_unknown_keys({"node_spacing", "mls_neighbours", "mls_support_factor", "gauss_points",
                            "smoothing_iterations"});
    s.discretization.mesh.spacing = t->positive("node_spacing", 0.1);
    s.discretization.mesh.smoothing_iterations =
        static_cast<int>(t->integer("smoothing_iterations", 10));
    s.discretization.mls.neighbours = static_cast<int>(t->integer("mls_neighbours", 8));
    if (s.discretization.mls.neighbours < 3) t->fail("mls_neighbours", "expected an integer >= 3");
    s.discretization.mls.support_factor = t->number("mls_support_factor", 1.0);
    if (s.discretization.mls.support_factor < 1.0)
      t->fail("mls_support_factor", "expected a number >= 1");
    s.discretization.gauss_points = static_cast<int>(t->integer("gauss_points", 3));
    const int gp = s.discretization.gauss_points;
    if (gp != 1 && gp != 3 && gp != 6 && gp != 7) t->fail("gauss_points", "expected 1, 3, 6 or 7");
  }
  if (auto t = root.table("physics")) {
    t->reject_unknown_keys({"gravity"});
    s.gravity = t->vec2("gravity", Vec2::Zero());
  }
  std::set<std::string> material_names;
  for (const TomlReader& t : root.array_of_tables("materials")) {
    s.materials.push_back(read_material(t));
    if (!material_names.insert(s.materials.back().name).second)
      t.fail("name", "material '" + s.materials.back().name + "' is defined twice");
  }
  if (s.materials.empty()) root.fail("materials", "at least one [[materials]] table is required");
  const std::vector<TomlReader> grains = root.array_of_tables("grains");
  if (grains.empty()) root.fail("grains", "at least one [[grains]] table is required");
  std::set<std::string> grain_names;
  for (std::size_t i = 0; i < grains.size(); ++i) {
    s.grains.push_back(read_grain(grains[i], i));
    if (!material_names.count(s.grains.back().material))
      grains[i].fail("material", "unknown material '" + s.grains.back().material + "'");
    if (!grain_names.insert(s.grains.back().name).second)
      grains[i].fail("name", "grain name '" + s.grains.back().name + "' is used twice");
  }
  return s;
}

Model build_model(const ScenarioDef& scenario) {
  Model model;
  model.gravity = scenario.gravity;
  for (const MaterialDef& m : scenario.materials) model.add_material(m);
  auto material_id = [&](const std::string& name) {
    for (std::size_t i = 0; i < scenario.materials.size(); ++i)
      if (scenario.materials[i].name == name) return static_cast<MaterialId>(i);
    SG_THROW("unknown material '" << name << "'");
  };
  const double h = scenario.discretization.mesh.spacing;
  for (const GrainDef& g : scenario.grains) {
    const Polygon contour = g.shape == GrainShape::disc
                                ? make_disc(g.center, g.radius, h)
                                : make_ellipse(g.center, g.semi_axes.x(), g.semi_axes.y(), g.angle, h);
    const BodyId b =
        model.add_deformable_body(g.name, contour, material_id(g.material), scenario.discretization);
    if (g.stretch != Vec2(1.0, 1.0)) set_affine_deformation(model, b, g.stretch.asDiagonal());
    set_rigid_velocity(model, b, g.velocity, g.spin);
  }
  return model;
}

}  // namespace sg
