#include "scenario/scenario.h"

#include <algorithm>
#include <set>

#include "core/error.h"
#include "geometry/shapes.h"
#include "model/kinematics.h"
#include "scenario/geometry_checks.h"
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

ContactLawDef read_contact_law(const TomlReader& t) {
  t.reject_unknown_keys({"materials", "law", "normal_stiffness", "tangential_stiffness", "friction",
                         "adhesion", "shear_strength", "cohesion"});
  ContactLawDef d;
  const auto pair = t.string_pair("materials");
  d.material_a = pair.first;
  d.material_b = pair.second;
  const std::string law = t.one_of("law", {"frictionless", "coulomb", "cohesive"}, "frictionless");
  d.params.kind = law == "frictionless" ? ContactLawKind::frictionless
                  : law == "coulomb"    ? ContactLawKind::coulomb
                                        : ContactLawKind::cohesive;
  d.params.normal_stiffness = t.positive("normal_stiffness");
  if (d.params.kind != ContactLawKind::frictionless)
    d.params.tangential_stiffness = t.positive("tangential_stiffness", d.params.normal_stiffness);
  d.params.friction = t.non_negative("friction", 0.0);
  // cohesion = c sets sigma_c = tau_c = c (the papers' single parameter).
  const double cohesion = t.non_negative("cohesion", 0.0);
  d.params.adhesion = t.non_negative("adhesion", cohesion);
  d.params.shear_strength = t.non_negative("shear_strength", cohesion);
  try {
    validate(d.params,
             "contact law for materials '" + d.material_a + "' and '" + d.material_b + "'");
  } catch (const Error& e) {
    t.fail("law", e.what());
  }
  return d;
}

// A size range [min, max] (length), 0 < min <= max.
SizeRangeDef read_size_range(const TomlReader& t, const char* key) {
  const Vec2 r = t.vec2(key);
  if (!(r.x() > 0 && r.y() >= r.x())) t.fail(key, "expected [min, max] with 0 < min <= max");
  return SizeRangeDef{r.x(), r.y(), SizeLaw::uniform};
}

// One [[shear_cell.components]]: a shape law, its number fraction, material and kind.
GrainComponentDef read_shear_cell_component(const TomlReader& t,
                                            const std::set<std::string>& material_names) {
  t.reject_unknown_keys(
      {"name", "shape", "fraction", "diameter", "major_axis", "minor_axis", "material", "rigid"});
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

}  // namespace

ScenarioDef load_scenario(const std::filesystem::path& file) {
  const TomlDocument document(file);
  const TomlReader root = document.root();
  root.reject_unknown_keys({"name", "time", "output", "discretization", "physics", "materials",
                            "grains", "walls", "contact_laws", "contact", "periodic", "shear_cell",
                            "compaction_box"});
  ScenarioDef s;
  s.source = file;
  s.name = root.string("name", file.stem().string());
  if (auto t = root.table("time")) {
    t->reject_unknown_keys({"duration", "safety", "fixed_step", "reestimate_interval",
                            "step_tolerance", "mass_scaling_step"});
    s.duration = t->positive("duration");
    s.time_step_safety = t->positive("safety", 0.8);
    if (s.time_step_safety > 1.0) t->fail("safety", "expected a number in (0, 1]");
    s.fixed_time_step = t->non_negative("fixed_step", 0.0);
    s.reestimate_interval = t->integer("reestimate_interval", s.reestimate_interval);
    if (s.reestimate_interval < 0)
      t->fail("reestimate_interval", "expected a number of steps >= 0 (0: never)");
    s.step_tolerance = t->non_negative("step_tolerance", s.step_tolerance);
    s.mass_scaling_step = t->non_negative("mass_scaling_step", 0.0);
  } else {
    root.fail("time", "required table [time] with 'duration' is missing");
  }
  if (auto t = root.table("output")) {
    t->reject_unknown_keys({"directory", "series_period", "field_period", "checkpoint_period"});
    s.output_root = t->string("directory", "out");
    s.series_period = t->non_negative("series_period", 0.0);
    s.field_period = t->non_negative("field_period", 0.0);
    if (t->has("checkpoint_period"))
      s.checkpoint_period = t->non_negative("checkpoint_period", 0.0);
  }
  if (s.series_period == 0.0) s.series_period = s.duration / 200.0;
  if (s.field_period == 0.0) s.field_period = s.duration / 20.0;
  if (s.checkpoint_period < 0.0) s.checkpoint_period = s.duration / 10.0;  // key absent
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
  if (auto t = root.table("shear_cell")) {
    t->reject_unknown_keys({"length", "grains", "diameter", "grain_material", "first_body_material",
                            "roughness_rms", "hurst", "first_body_thickness", "gap",
                            "compaction_time", "velocity", "seed", "normal_load", "pressure",
                            "servo_damping", "components", "first_bodies"});
    ShearCellDef c;
    c.length = t->positive("length", c.length);
    c.grains = static_cast<int>(t->integer("grains", c.grains));
    if (c.grains < 1) t->fail("grains", "expected a positive integer");
    const Vec2 d = t->vec2("diameter", Vec2(0.85, 1.15));
    if (!(d.x() > 0 && d.y() >= d.x()))
      t->fail("diameter", "expected [min, max] with 0 < min <= max");
    c.diameter.min = d.x();
    c.diameter.max = d.y();
    c.grain_material = t->string("grain_material");
    c.first_body_material = t->string("first_body_material");
    for (const char* key : {"grain_material", "first_body_material"})
      if (!material_names.count(t->string(key)))
        t->fail(key, "unknown material '" + t->string(key) + "'");
    c.roughness_rms = t->non_negative("roughness_rms", c.roughness_rms);
    c.hurst = t->number("hurst", c.hurst);
    if (!(c.hurst > 0 && c.hurst < 1)) t->fail("hurst", "expected a number in (0, 1)");
    c.first_body_thickness = t->positive("first_body_thickness", c.first_body_thickness);
    c.normal_load = t->one_of("normal_load", {"gap", "pressure"}, "gap") == "gap"
                        ? NormalLoad::gap
                        : NormalLoad::pressure;
    c.first_bodies = t->one_of("first_bodies", {"rigid", "deformable"}, "rigid") == "rigid"
                         ? FirstBodyKind::rigid
                         : FirstBodyKind::deformable;
    if (c.normal_load == NormalLoad::pressure) {
      c.pressure = t->positive("pressure");
      c.servo_damping = t->non_negative("servo_damping", 0.0);
      if (t->has("gap"))
        t->fail("gap", "the gap is an output under normal_load = \"pressure\" (remove it)");
    } else {
      for (const char* key : {"pressure", "servo_damping"})
        if (t->has(key)) t->fail(key, "applies only with normal_load = \"pressure\"");
    }
    for (const TomlReader& ct : t->array_of_tables("components")) {
      if (t->has("diameter"))
        t->fail("diameter", "give the sizes in [[shear_cell.components]], not both");
      c.components.push_back(read_shear_cell_component(ct, material_names));
    }
    c.gap = t->non_negative("gap", 0.0);
    c.compaction_time = t->positive("compaction_time", c.compaction_time);
    c.velocity = t->number("velocity", c.velocity);
    const long seed = t->integer("seed", 1);
    if (seed < 0) t->fail("seed", "expected an integer >= 0");
    c.seed = static_cast<std::uint64_t>(seed);
    s.shear_cell = c;
  }
  if (auto t = root.table("compaction_box")) {
    if (s.shear_cell) t->fail("width", "a scenario holds a [shear_cell] or a [compaction_box]");
    s.compaction_box = read_compaction_box(*t, material_names);
  }
  const std::vector<TomlReader> grains = root.array_of_tables("grains");
  if (grains.empty() && !s.shear_cell && !s.compaction_box)
    root.fail("grains",
              "at least one [[grains]] table (or a [shear_cell] or [compaction_box]) is required");
  std::set<std::string> grain_names;
  for (std::size_t i = 0; i < grains.size(); ++i) {
    s.grains.push_back(read_grain(grains[i], i));
    if (!material_names.count(s.grains.back().material))
      grains[i].fail("material", "unknown material '" + s.grains.back().material + "'");
    if (!grain_names.insert(s.grains.back().name).second)
      grains[i].fail("name", "grain name '" + s.grains.back().name + "' is used twice");
  }
  const std::vector<TomlReader> walls = root.array_of_tables("walls");
  for (std::size_t i = 0; i < walls.size(); ++i) {
    s.walls.push_back(read_wall(walls[i], i));
    if (!material_names.count(s.walls.back().material))
      walls[i].fail("material", "unknown material '" + s.walls.back().material + "'");
    if (!grain_names.insert(s.walls.back().name).second)
      walls[i].fail("name", "body name '" + s.walls.back().name + "' is used twice");
  }
  double cohesive_reach = 0.0;
  for (const TomlReader& t : root.array_of_tables("contact_laws")) {
    s.contact_laws.push_back(read_contact_law(t));
    for (const std::string* m :
         {&s.contact_laws.back().material_a, &s.contact_laws.back().material_b})
      if (!material_names.count(*m)) t.fail("materials", "unknown material '" + *m + "'");
    const ContactLawParams& p = s.contact_laws.back().params;
    cohesive_reach = std::max(cohesive_reach, 0.5 * p.adhesion / p.normal_stiffness);
  }
  if (auto t = root.table("contact")) {
    t->reject_unknown_keys({"cutoff", "skin"});
    s.contact_cutoff = t->non_negative("cutoff", 0.0);
    s.contact_skin = t->non_negative("skin", 0.0);
    if (s.contact_cutoff > 0.0 && s.contact_cutoff < cohesive_reach)
      t->fail("cutoff", "must be at least the cohesive reach sigma_c / (2 k_n) = " +
                            std::to_string(cohesive_reach));
  }
  if (s.contact_cutoff == 0.0)
    s.contact_cutoff = std::max(0.25 * s.discretization.mesh.spacing, 1.5 * cohesive_reach);
  if (auto t = root.table("periodic")) {
    t->reject_unknown_keys({"x_min", "x_max"});
    s.periodic_x = true;
    s.x_min = t->number("x_min");
    s.x_max = t->number("x_max");
    if (!(s.x_max > s.x_min)) t->fail("x_max", "expected x_max > x_min");
  }
  if (!s.contact_laws.empty()) {
    // Every pair of materials in use needs a law: checked here, with the file, not mid-run.
    std::set<std::string> used;
    for (const GrainSpec& g : s.grains)
      used.insert(g.material);
    for (const WallDef& w : s.walls)
      used.insert(w.material);
    if (s.shear_cell) {
      used.insert(s.shear_cell->grain_material);
      used.insert(s.shear_cell->first_body_material);
      for (const GrainComponentDef& c : s.shear_cell->components)
        if (!c.material.empty()) used.insert(c.material);
    }
    if (const auto& box = s.compaction_box) {
      if (!box->grain_material.empty()) used.insert(box->grain_material);
      used.insert(box->wall_material);
      for (const GrainComponentDef& c : box->components)
        if (!c.material.empty()) used.insert(c.material);
    }
    try {
      MaterialPairTable table = contact_law_table(s);
      std::vector<int> ids;
      for (const std::string& m : used)
        ids.push_back(table.find_material(m));
      table.verify_covers(ids);
    } catch (const Error& e) {
      root.fail("contact_laws", e.what());
    }
  }
  check_scenario_geometry(s, root);  // name, periodic cell, node spacing (docs: "Safety")
  return s;
}

MaterialPairTable contact_law_table(const ScenarioDef& scenario) {
  std::vector<std::string> names;
  for (const MaterialDef& m : scenario.materials)
    names.push_back(m.name);
  MaterialPairTable table(names);
  for (const ContactLawDef& law : scenario.contact_laws)
    table.set(law.material_a, law.material_b, law.params);
  return table;
}

ContactSettings contact_settings(const ScenarioDef& scenario) {
  ContactSettings settings;
  settings.cutoff = scenario.contact_cutoff;
  settings.skin = scenario.contact_skin > 0.0 ? scenario.contact_skin : scenario.contact_cutoff;
  return settings;
}

Model build_model(const ScenarioDef& scenario) {
  Model model;
  model.gravity = scenario.gravity;
  for (const MaterialDef& m : scenario.materials)
    model.add_material(m);
  auto material_id = [&](const std::string& name) {
    for (std::size_t i = 0; i < scenario.materials.size(); ++i)
      if (scenario.materials[i].name == name) return static_cast<MaterialId>(i);
    SG_THROW("unknown material '" << name << "'");
  };
  const double h = scenario.discretization.mesh.spacing;
  model.periodic_x = scenario.periodic_x;
  model.x_min = scenario.x_min;
  model.x_max = scenario.x_max;
  for (const GrainSpec& g : scenario.grains) {
    const Polygon contour = g.shape == GrainShape::disc ? make_disc(g.center, g.radius, h)
                                                        : make_ellipse(g.center, g.semi_axes.x(),
                                                                       g.semi_axes.y(), g.angle, h);
    if (g.rigid) {
      const BodyId b = model.add_rigid_body(g.name, contour, material_id(g.material));
      const auto r =
          static_cast<std::size_t>(model.bodies[static_cast<std::size_t>(b)].rigid_index);
      model.rigid.vx[r] = g.velocity.x();
      model.rigid.vy[r] = g.velocity.y();
      model.rigid.omega[r] = g.spin;
      continue;
    }
    const BodyId b = model.add_deformable_body(g.name, contour, material_id(g.material),
                                               scenario.discretization);
    if (g.stretch != Vec2(1.0, 1.0)) set_affine_deformation(model, b, g.stretch.asDiagonal());
    set_rigid_velocity(model, b, g.velocity, g.spin);
  }
  if (scenario.shear_cell) {
    ShearCellDef cell = *scenario.shear_cell;
    // The servo estimate needs the grain / first-body penalty stiffness.
    if (!scenario.contact_laws.empty()) {
      const MaterialPairTable table = contact_law_table(scenario);
      const int a = table.find_material(cell.grain_material);
      const int b = table.find_material(cell.first_body_material);
      if (table.has(a, b)) cell.contact_stiffness = table.at(a, b).normal_stiffness;
    }
    add_shear_cell(model, cell, material_id(cell.grain_material),
                   material_id(cell.first_body_material), scenario.discretization);
  }
  if (const auto& box = scenario.compaction_box)
    add_compaction_box(model, *box,
                       box->grain_material.empty() ? 0 : material_id(box->grain_material),
                       material_id(box->wall_material), scenario.discretization);
  for (const WallDef& w : scenario.walls) {
    const BodyId b = model.add_rigid_body(w.name, make_rectangle(w.lower_left, w.upper_right, h),
                                          material_id(w.material));
    RigidDrive& drive =
        model.rigid
            .drive[static_cast<std::size_t>(model.bodies[static_cast<std::size_t>(b)].rigid_index)];
    const double v[3] = {w.velocity.x(), w.velocity.y(), 0.0};
    for (int d = 0; d < 3; ++d) {
      drive.mode[d] = DriveMode::velocity;
      drive.velocity[d] = PiecewiseLinear::constant(v[d]);
    }
  }
  return model;
}

}  // namespace sg
