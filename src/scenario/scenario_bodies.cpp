// [[materials]], [[grains]] (inline, from a CSV list, or explicit contours) and [[walls]] of a
// scenario file (scenario_readers.h).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "core/error.h"
#include "geometry/polygon.h"
#include "scenario/csv_table.h"
#include "scenario/motion_limits.h"
#include "scenario/scenario_readers.h"

namespace sg {

namespace {

MaterialDef read_material(const TomlReader& t) {
  t.reject_unknown_keys({"name", "law", "young", "poisson", "density", "damping", "damping_model",
                         "volumetric", "node_spacing", "interior_spacing"});
  MaterialDef m;
  m.name = t.string("name");
  m.law = t.named_value("law", kMaterialLaws, MaterialLaw::neo_hookean);
  m.young = t.positive("young");
  m.poisson = t.number("poisson", 0.3);
  if (!(m.poisson > -1.0 && m.poisson < 0.5))
    t.fail("poisson", "expected a number in (-1, 0.5), got " + std::to_string(m.poisson));
  m.density = t.positive("density", 1.0);
  m.damping = t.non_negative("damping", 0.0);
  m.damping_model = t.named_value("damping_model", kDampingModels, DampingModel::objective);
  m.volumetric =
      t.named_value("volumetric", kVolumetricFormulations, VolumetricFormulation::standard);
  return m;
}

// A contour's vertices: inline `points` or a CSV `contour_file` (columns x, y); returned CCW.
Polygon read_contour(const TomlReader& t) {
  if (t.has("points") == t.has("contour_file"))
    t.fail("points",
           "shape = \"contour\" needs exactly one of points = [[x, y], ...] or "
           "contour_file = \"file.csv\"");
  Polygon contour;
  const char* key = t.has("points") ? "points" : "contour_file";
  if (t.has("points")) {
    contour = t.pairs("points", 3);
  } else {
    const CsvTable csv(t.file_path("contour_file"), {"x", "y"}, {"x", "y"});
    for (const CsvTable::Row& row : csv.rows()) {
      const double x = csv.number(row, "x");  // x first: the message names the first bad cell
      contour.emplace_back(x, csv.number(row, "y"));
    }
    if (contour.size() < 3) t.fail(key, "a contour needs at least 3 points");
  }
  if (signed_area(contour) < 0.0) std::reverse(contour.begin(), contour.end());
  if (!(signed_area(contour) > 0.0)) t.fail(key, "the contour encloses no area");
  if (is_self_intersecting(contour)) t.fail(key, "the contour intersects itself");
  return contour;
}

GrainSpec read_grain(const TomlReader& t, std::size_t index) {
  t.reject_unknown_keys({"name", "shape", "center", "radius", "semi_axes", "angle", "material",
                         "velocity", "spin", "stretch", "rigid", "points", "contour_file",
                         "drive"});
  GrainSpec g;
  g.name = t.string("name", "grain_" + std::to_string(index));
  const std::string shape = t.one_of("shape", {"disc", "ellipse", "contour"}, "disc");
  g.shape = shape == "disc"      ? GrainShape::disc
            : shape == "ellipse" ? GrainShape::ellipse
                                 : GrainShape::contour;
  if (g.shape == GrainShape::contour) {
    for (const char* key : {"center", "radius", "semi_axes", "angle"})
      if (t.has(key)) t.fail(key, "does not apply to shape = \"contour\" (give its points)");
    g.contour = read_contour(t);
    g.center = centroid(g.contour);
  } else {
    for (const char* key : {"points", "contour_file"})
      if (t.has(key)) t.fail(key, "applies only to shape = \"contour\"");
    g.center = t.vec2("center");
  }
  if (g.shape == GrainShape::disc) {
    g.radius = t.positive("radius");
  } else if (g.shape == GrainShape::ellipse) {
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
  if (auto d = t.table("drive")) {
    if (!g.rigid) t.fail("drive", "only a rigid grain can be driven (set rigid = true)");
    g.drive = read_drive(*d, true, false);
  }
  return g;
}

// A [[grains]] table with grains_file: one disc (x, y, diameter) or ellipse (x, y, a, b,
// angle) per row; optional columns material, rigid, vx, vy, spin override the table's
// material and rigid. Grain names: "<name>_<row>" (name: the file's stem by default).
void read_grains_file(const TomlReader& t, std::vector<GrainSpec>& out) {
  t.reject_unknown_keys({"grains_file", "name", "material", "rigid"});
  const std::filesystem::path path = t.file_path("grains_file");
  const CsvTable csv(
      path,
      {"name", "x", "y", "diameter", "a", "b", "angle", "material", "rigid", "vx", "vy", "spin"},
      {"x", "y"});
  if (!csv.has_column("diameter") && !(csv.has_column("a") && csv.has_column("b")))
    t.fail("grains_file",
           "'" + path.string() + "' needs a column diameter, or columns a and b (semi-axes)");
  const std::string prefix = t.string("name", path.stem().string());
  const std::string material = t.string("material", "");
  const bool rigid = t.boolean("rigid", false);
  for (std::size_t i = 0; i < csv.rows().size(); ++i) {
    const CsvTable::Row& row = csv.rows()[i];
    GrainSpec g;
    g.name = csv.text(row, "name", prefix + "_" + std::to_string(i));
    // One cell at a time, left to right: an error names the row's first bad cell (the
    // arguments of one call are evaluated in no fixed order).
    const double x = csv.number(row, "x");
    g.center = Vec2(x, csv.number(row, "y"));
    const bool disc = csv.has(row, "diameter");
    const bool ellipse = csv.has(row, "a") || csv.has(row, "b");
    if (disc && ellipse) csv.fail(row, "a", "give a diameter or semi-axes a and b, not both");
    if (!disc && !ellipse)
      csv.fail(row, csv.has_column("diameter") ? "diameter" : "a",
               "a grain needs a diameter, or semi-axes a and b; the row gives neither" +
                   csv.short_row_note(row));
    if (disc) {
      g.radius = 0.5 * csv.positive(row, "diameter");
    } else {
      g.shape = GrainShape::ellipse;
      const double a = csv.positive(row, "a");
      g.semi_axes = Vec2(a, csv.positive(row, "b"));
      g.angle = csv.number(row, "angle", 0.0);
    }
    g.material = csv.text(row, "material", material);
    if (g.material.empty())
      csv.fail(row, "material", "no material (give the column, or material in the table)");
    g.rigid = csv.boolean(row, "rigid", rigid);
    const double vx = csv.number(row, "vx", 0.0);
    g.velocity = Vec2(vx, csv.number(row, "vy", 0.0));
    g.spin = csv.number(row, "spin", 0.0);
    out.push_back(g);
  }
}

// The radius of the disc of the grain's area (an ellipse: its smaller semi-axis).
double inner_radius(const GrainSpec& g) {
  switch (g.shape) {
    case GrainShape::disc:
      return g.radius;
    case GrainShape::ellipse:
      return std::min(g.semi_axes.x(), g.semi_axes.y());
    case GrainShape::contour:
      return std::sqrt(signed_area(g.contour) / std::numbers::pi);
  }
  return 0.0;
}

// Two grains at the same place (a row of a grains file, or a [[grains]] table, given twice)
// are refused: their contours coincide, so the overlap check of the built model, which looks
// for contour points strictly inside another body, does not see them (issue #26). "The same
// place": centres closer than 10^-6 of the smaller grain's inner radius. `tables[k]` is the
// [[grains]] table that gave grain k.
void refuse_coincident_grains(const std::vector<GrainSpec>& grains,
                              const std::vector<const TomlReader*>& tables) {
  std::vector<std::size_t> order(grains.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return grains[a].center.x() < grains[b].center.x();
  });
  double largest = 0.0;
  for (const GrainSpec& g : grains)
    largest = std::max(largest, inner_radius(g));
  for (std::size_t i = 0; i < order.size(); ++i) {
    const GrainSpec& a = grains[order[i]];
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const GrainSpec& b = grains[order[j]];
      if (b.center.x() - a.center.x() > 1e-6 * largest) break;
      const double tolerance = 1e-6 * std::min(inner_radius(a), inner_radius(b));
      if ((a.center - b.center).norm() > tolerance) continue;
      const std::size_t later = std::max(order[i], order[j]),
                        earlier = std::min(order[i], order[j]);
      const TomlReader& t = *tables[later];
      std::ostringstream message;
      message << "grains '" << grains[earlier].name << "' and '" << grains[later].name
              << "' are at the same place (centre " << grains[later].center.x() << ", "
              << grains[later].center.y() << "): coincident grains (a row or table given "
              << "twice?); expected every grain at its own place";
      t.fail(t.has("grains_file") ? "grains_file" : "center", message.str());
    }
  }
}

WallDef read_wall(const TomlReader& t, std::size_t index) {
  t.reject_unknown_keys({"name", "lower_left", "upper_right", "material", "velocity", "drive"});
  WallDef w;
  w.name = t.string("name", "wall_" + std::to_string(index));
  w.lower_left = t.vec2("lower_left");
  w.upper_right = t.vec2("upper_right");
  if (!(w.upper_right.x() > w.lower_left.x() && w.upper_right.y() > w.lower_left.y()))
    t.fail("upper_right", "expected a corner above and to the right of lower_left");
  w.material = t.string("material");
  w.velocity = t.vec2("velocity", Vec2::Zero());
  if (auto d = t.table("drive")) {
    if (t.has("velocity")) t.fail("velocity", "give the wall's motion in velocity or in drive");
    w.drive = read_drive(*d, true, false);
  }
  return w;
}

}  // namespace

std::set<std::string> read_materials(const TomlReader& root, ScenarioDef& s) {
  std::set<std::string> material_names;
  for (const TomlReader& t : root.array_of_tables("materials")) {
    s.materials.push_back(read_material(t));
    s.material_spacing.push_back(read_node_spacing(
        t, NodeSpacing{s.discretization.mesh.spacing, s.discretization.mesh.interior_spacing}));
    check_material_frequency(t, s.materials.back(), s.material_spacing.back().contour);
    if (!material_names.insert(s.materials.back().name).second)
      t.fail("name", "material '" + s.materials.back().name + "' is defined twice");
  }
  if (s.materials.empty()) root.fail("materials", "at least one [[materials]] table is required");
  return material_names;
}

void read_grains(const TomlReader& root, ScenarioDef& s,
                 const std::set<std::string>& material_names, std::set<std::string>& body_names) {
  const std::vector<TomlReader> grains = root.array_of_tables("grains");
  if (grains.empty() && !s.shear_cell && !s.compaction_box && s.strips.empty())
    root.fail("grains",
              "at least one [[grains]] table (or a [shear_cell] or [compaction_box]) is required");
  std::vector<const TomlReader*> tables;  // of each grain
  const TravelLimit travel(s);
  for (std::size_t i = 0; i < grains.size(); ++i) {
    const std::size_t first = s.grains.size();
    if (grains[i].has("grains_file")) {
      read_grains_file(grains[i], s.grains);
      for (std::size_t k = first; k < s.grains.size(); ++k)
        travel.check_speed(grains[i], "grains_file", s.grains[k].velocity.norm(),
                           "grain '" + s.grains[k].name + "' (columns vx, vy)");
    } else {
      s.grains.push_back(read_grain(grains[i], i));
      const GrainSpec& g = s.grains.back();
      travel.check_speed(grains[i], "velocity", g.velocity.norm(), "grain '" + g.name + "'");
      if (auto d = grains[i].table("drive"))
        travel.check_drive(*d, g.drive, "grain '" + g.name + "'");
    }
    for (std::size_t k = first; k < s.grains.size(); ++k) {
      if (!material_names.count(s.grains[k].material))
        grains[i].fail(
            grains[i].has("grains_file") ? "grains_file" : "material",
            "unknown material '" + s.grains[k].material + "' (grain '" + s.grains[k].name + "')");
      if (!body_names.insert(s.grains[k].name).second)
        grains[i].fail("name", "grain name '" + s.grains[k].name + "' is used twice");
      s.grains[k].spacing = material_spacing(s, s.grains[k].material);
      tables.push_back(&grains[i]);
    }
  }
  refuse_coincident_grains(s.grains, tables);
}

void read_walls(const TomlReader& root, ScenarioDef& s, const std::set<std::string>& material_names,
                std::set<std::string>& body_names) {
  const std::vector<TomlReader> walls = root.array_of_tables("walls");
  const TravelLimit travel(s);
  for (std::size_t i = 0; i < walls.size(); ++i) {
    s.walls.push_back(read_wall(walls[i], i));
    const WallDef& w = s.walls.back();
    travel.check_speed(walls[i], "velocity", w.velocity.norm(), "wall '" + w.name + "'");
    if (auto d = walls[i].table("drive")) travel.check_drive(*d, w.drive, "wall '" + w.name + "'");
    if (!material_names.count(s.walls.back().material))
      walls[i].fail("material", "unknown material '" + s.walls.back().material + "'");
    if (!body_names.insert(s.walls.back().name).second)
      walls[i].fail("name", "body name '" + s.walls.back().name + "' is used twice");
    s.walls.back().spacing = material_spacing(s, s.walls.back().material);
  }
}

}  // namespace sg
