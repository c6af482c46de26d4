#include "scenario/scenario.h"

#include <algorithm>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.h"
#include "model/kinematics.h"
#include "scenario/body_builders.h"
#include "scenario/geometry_checks.h"
#include "scenario/motion_limits.h"
#include "scenario/scenario_readers.h"
#include "scenario/toml_reader.h"

namespace sg {

namespace {

// Every pair of materials in use needs a law: checked here, with the file, not mid-run.
void check_contact_laws_cover_materials(const TomlReader& root, const ScenarioDef& s) {
  std::set<std::string> used;
  for (const GrainSpec& g : s.grains)
    used.insert(g.material);
  for (const WallDef& w : s.walls)
    used.insert(w.material);
  for (const StripDef& strip : s.strips)
    used.insert(strip.material);
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

// A contact reach (cutoff + skin) of half the periodic cell or more: the broad phase would
// stop the run at step 0 naming no input ("the periodic cell (length 20) must be longer than
// 2 (cutoff + skin) + the widest segment = 1.5e+57" for a cohesion of 1e60; issue #26).
// `reach_law`: the [[contact_laws]] table whose tensile reach is the largest (none: -1).
void check_contact_reach(const TomlReader& root, const ScenarioDef& s,
                         const std::vector<TomlReader>& laws, int reach_law,
                         double cohesive_reach) {
  const double period = s.periodic_x   ? s.x_max - s.x_min
                        : s.shear_cell ? s.shear_cell->length
                                       : 0.0;
  if (s.contact_laws.empty() || !(period > 0.0)) return;
  const ContactSettings c = contact_settings(s);
  const double reach = c.cutoff + c.skin;
  if (2.0 * reach < period) return;
  std::ostringstream message;
  message << "the contact cutoff + skin = " << reach
          << " is not below half the periodic cell (length " << period << ")";
  const std::optional<TomlReader> contact = root.table("contact");
  if (contact && contact->has("cutoff")) contact->fail("cutoff", message.str());
  if (contact && contact->has("skin")) contact->fail("skin", message.str());
  // The default cutoff: max(h / 4, 1.5 x the largest tensile reach) (read_contact_settings).
  if (reach_law < 0 || 0.25 * finest_contour_spacing(s) >= 1.5 * cohesive_reach) {
    const std::optional<TomlReader> d = root.table("discretization");
    message << ": it follows the node spacing (cutoff = node_spacing / 4)";
    if (d && d->has("node_spacing")) d->fail("node_spacing", message.str());
    root.fail("contact_laws", message.str());
  }
  const TomlReader& law = laws[static_cast<std::size_t>(reach_law)];
  message << ": it follows this law's tensile reach " << cohesive_reach
          << " (from its cohesion or adhesion and normal_stiffness, its critical_opening or "
             "bond_gap); expected a reach below the period / 6 = "
          << period / 6.0;
  for (const char* key :
       {"cohesion", "adhesion", "critical_opening", "bond_gap", "normal_stiffness"})
    if (law.has(key)) law.fail(key, message.str());
  law.fail("law", message.str());
}

// The shear cell's first bodies: the sliding velocity and the drive tables.
void check_first_body_drives(const TomlReader& t, const ShearCellDef& c,
                             const TravelLimit& travel) {
  travel.check_speed(t, "velocity", c.velocity, "the shear cell's first bodies");
  for (const char* side : {"bottom", "top"})
    if (auto d = t.table(std::string(side) + "_drive"))
      travel.check_drive(*d, std::string(side) == "bottom" ? c.bottom_drive : c.top_drive,
                         std::string("the ") + side + " first body");
}

// The scenario `document` holds, checked (`file` names it in messages).
ScenarioDef read_scenario(const TomlDocument& document, const std::filesystem::path& file) {
  const TomlReader root = document.root();
  root.reject_unknown_keys({"name", "time", "output", "discretization", "physics", "materials",
                            "grains", "walls", "strips", "contact_laws", "contact", "periodic",
                            "shear_cell", "compaction_box"});
  ScenarioDef s;
  s.source = file;
  s.name = root.string("name", file.stem().string());
  read_time(root, s);
  read_output(root, s);
  read_discretization(root, s);
  read_physics(root, s);
  read_periodic(root, s);
  const std::set<std::string> material_names = read_materials(root, s);
  if (auto t = root.table("shear_cell")) {
    s.shear_cell = read_shear_cell(*t, material_names);
    resolve_shear_cell_spacing(*t, s);
    check_first_body_drives(*t, *s.shear_cell, TravelLimit(s));
  }
  if (auto t = root.table("compaction_box")) {
    if (s.shear_cell) t->fail("width", "a scenario holds a [shear_cell] or a [compaction_box]");
    s.compaction_box = read_compaction_box(*t, material_names);
    refuse_material_spacing_in_compaction_box(root, s);
    TravelLimit(s).check_speed(*t, "lid_velocity", s.compaction_box->lid_velocity,
                               "the compaction box's lid");
  }
  std::set<std::string> body_names;
  read_strips(root, s, material_names, body_names);
  read_grains(root, s, material_names, body_names);
  read_walls(root, s, material_names, body_names);
  double cohesive_reach = 0.0;
  int reach_law = -1;  // the law of the largest tensile reach
  const std::vector<TomlReader> laws = root.array_of_tables("contact_laws");
  for (const TomlReader& t : laws) {
    s.contact_laws.push_back(read_contact_law(t));
    for (const std::string* m :
         {&s.contact_laws.back().material_a, &s.contact_laws.back().material_b})
      if (!material_names.count(*m)) t.fail("materials", "unknown material '" + *m + "'");
    const ContactLawParams& p = s.contact_laws.back().params;
    if (tensile_reach(p) > cohesive_reach) {
      cohesive_reach = tensile_reach(p);
      reach_law = static_cast<int>(s.contact_laws.size()) - 1;
    }
  }
  read_contact_settings(root, s, cohesive_reach);
  if (!s.contact_laws.empty()) check_contact_laws_cover_materials(root, s);
  check_scenario_geometry(s, root);  // name, periodic cell, node spacing (docs: "Safety")
  check_contact_reach(root, s, laws, reach_law, cohesive_reach);
  return s;
}

}  // namespace

ScenarioDef load_scenario(const std::filesystem::path& file) {
  return read_scenario(TomlDocument(file), file);
}

ScenarioDef load_scenario_text(std::string_view text, const std::filesystem::path& file) {
  return read_scenario(TomlDocument(text, file), file);
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

IntegratorParams imex_integrator(const ScenarioDef& scenario) {
  return IntegratorParams::imex(
      scenario.imex_tolerance, scenario.imex_refactor_threshold,
      scenario.imex_dense_factors ? IntegratorParams::kDefaultDenseFactorLimit : 0,
      scenario.imex_objective_split);
}

IntegratorChoice resolve_integrator(const ScenarioDef& scenario, const Model& model,
                                    double contact_stiffness) {
  const IntegratorParams imex = imex_integrator(scenario);
  if (scenario.integrator == ScenarioIntegrator::automatic)
    return choose_default_integrator(model, scenario.time_step_safety, contact_stiffness, imex,
                                     scenario.fixed_time_step, scenario.step_tolerance);
  // As written: exactly what the key has always meant.
  IntegratorChoice written;
  written.params = scenario.integrator == ScenarioIntegrator::imex
                       ? imex
                       : IntegratorParams::explicit_integrator();
  written.step_tolerance = std::max(0.0, scenario.step_tolerance);
  return written;
}

Model build_model(const ScenarioDef& scenario, ShearCellParts parts) {
  Model model;
  model.gravity = scenario.gravity;
  for (const MaterialDef& m : scenario.materials)
    model.add_material(m);
  auto material_id = [&](const std::string& name) {
    for (std::size_t i = 0; i < scenario.materials.size(); ++i)
      if (scenario.materials[i].name == name) return static_cast<MaterialId>(i);
    SG_THROW("unknown material '" << name << "'");
  };
  // A body's contour spacing: its own (NodeSpacing, from its material), else the scenario's.
  auto contour_spacing = [&](const NodeSpacing& own) {
    return own.contour > 0.0 ? own.contour : scenario.discretization.mesh.spacing;
  };
  model.periodic_x = scenario.periodic_x;
  model.x_min = scenario.x_min;
  model.x_max = scenario.x_max;
  for (const GrainSpec& g : scenario.grains) {
    const double h = contour_spacing(g.spacing);
    if (g.rigid) {
      add_rigid_grain(model, g, material_id(g.material), h);
      continue;
    }
    const BodyId b = model.add_deformable_body(g.name, grain_contour(g, h), material_id(g.material),
                                               with_spacing(scenario.discretization, g.spacing));
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
                   material_id(cell.first_body_material), scenario.discretization, parts);
  }
  if (const auto& box = scenario.compaction_box)
    add_compaction_box(model, *box,
                       box->grain_material.empty() ? 0 : material_id(box->grain_material),
                       material_id(box->wall_material), scenario.discretization);
  for (const WallDef& w : scenario.walls)
    add_wall(model, w, material_id(w.material), contour_spacing(w.spacing));
  for (const StripDef& strip : scenario.strips)
    add_strip(model, strip, material_id(strip.material), scenario.x_min, scenario.x_max,
              with_spacing(scenario.discretization, strip.spacing));
  return model;
}

}  // namespace sg
