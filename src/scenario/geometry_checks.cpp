#include "scenario/geometry_checks.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "core/file_name.h"
#include "geometry/polygon.h"
#include "model/kinematics.h"

namespace sg {

namespace {

// Half the x extent of a grain at t = 0 (after its stretch, applied about its centre).
double half_width_x(const GrainSpec& g) {
  if (g.shape == GrainShape::disc) return g.radius * g.stretch.x();
  const double c = std::cos(g.angle), s = std::sin(g.angle);
  const double a = g.semi_axes.x(), b = g.semi_axes.y();
  return std::sqrt(a * a * c * c + b * b * s * s) * g.stretch.x();
}

double equivalent_diameter(const GrainSpec& g) {
  return g.shape == GrainShape::disc ? 2.0 * g.radius
                                     : 2.0 * std::sqrt(g.semi_axes.x() * g.semi_axes.y());
}

const char* size_key(const GrainSpec& g) {
  return g.shape == GrainShape::disc ? "radius" : "semi_axes";
}

std::string number(double v) {
  std::ostringstream s;
  s << std::setprecision(6) << v;
  return s.str();
}

std::string cell_text(const ScenarioDef& s) {
  return "the periodic cell [" + number(s.x_min) + ", " + number(s.x_max) + ") of width " +
         number(s.x_max - s.x_min);
}

void check_periodic_bodies(const ScenarioDef& s, const TomlReader& root) {
  const double period = s.x_max - s.x_min;
  const std::vector<TomlReader> grains = root.array_of_tables("grains");
  for (std::size_t i = 0; i < s.grains.size() && i < grains.size(); ++i) {
    const GrainSpec& g = s.grains[i];
    const double width = 2.0 * half_width_x(g);
    if (!(width < period))
      grains[i].fail(size_key(g), "grain '" + g.name + "' is " + number(width) +
                                      " wide in x, not narrower than " + cell_text(s));
    if (!(g.center.x() >= s.x_min && g.center.x() < s.x_max))
      grains[i].fail("center", "grain '" + g.name + "' has its centre at x = " +
                                   number(g.center.x()) + ", outside " + cell_text(s));
  }
  const std::vector<TomlReader> walls = root.array_of_tables("walls");
  for (std::size_t i = 0; i < s.walls.size() && i < walls.size(); ++i) {
    const WallDef& w = s.walls[i];
    const double width = w.upper_right.x() - w.lower_left.x();
    if (!(width < period))
      walls[i].fail("upper_right", "wall '" + w.name + "' is " + number(width) +
                                       " wide in x, not narrower than " + cell_text(s));
    const double middle = 0.5 * (w.lower_left.x() + w.upper_right.x());
    if (!(middle >= s.x_min && middle < s.x_max))
      walls[i].fail("lower_left", "wall '" + w.name + "' has its middle at x = " + number(middle) +
                                      ", outside " + cell_text(s));
  }
}

// Grains with a node spacing of their own (from their material or component, issue #32) are
// checked against it when it is read (resolve_shear_cell_spacing), not against node_spacing.
bool own_spacing(const ScenarioDef& s, const NodeSpacing& spacing) {
  return spacing.contour > 0.0 && spacing.contour != s.discretization.mesh.spacing;
}

// The largest grain size a [shear_cell] or [compaction_box] may generate (0: none).
double largest_generated_diameter(const ScenarioDef& s) {
  double d = 0.0;
  auto add_components = [&](const std::vector<GrainComponentDef>& components) {
    for (const GrainComponentDef& c : components)
      if (!own_spacing(s, c.spacing))
        d = std::max(d, c.shape.kind == GrainShapeKind::ellipse ? c.shape.major_axis.max
                                                                : c.shape.diameter.max);
  };
  if (s.shear_cell) {
    if (s.shear_cell->components.empty() && !own_spacing(s, s.shear_cell->grain_spacing))
      d = s.shear_cell->diameter.max;
    add_components(s.shear_cell->components);
  }
  if (s.compaction_box) add_components(s.compaction_box->components);
  return d;
}

// Coordinates beyond kMaxCoordinateInSpacings node spacings from the origin: positions
// there have a resolution coarser than 1e-8 h in double precision.
constexpr double kMaxCoordinateInSpacings = 1e8;

void check_coordinates(const ScenarioDef& s, const TomlReader& root) {
  const double limit = kMaxCoordinateInSpacings * s.discretization.mesh.spacing;
  auto check = [&](const TomlReader& t, const char* key, const Vec2& p) {
    if (!(std::abs(p.x()) <= limit && std::abs(p.y()) <= limit))
      t.fail(key, "[" + number(p.x()) + ", " + number(p.y()) +
                      "] is too far from the origin for the node spacing " +
                      number(s.discretization.mesh.spacing) + ": expected coordinates within " +
                      number(kMaxCoordinateInSpacings) +
                      " node spacings, |x|, |y| <= " + number(limit));
  };
  const std::vector<TomlReader> grains = root.array_of_tables("grains");
  for (std::size_t i = 0; i < s.grains.size() && i < grains.size(); ++i)
    check(grains[i], "center", s.grains[i].center);
  const std::vector<TomlReader> walls = root.array_of_tables("walls");
  for (std::size_t i = 0; i < s.walls.size() && i < walls.size(); ++i) {
    check(walls[i], "lower_left", s.walls[i].lower_left);
    check(walls[i], "upper_right", s.walls[i].upper_right);
  }
}

// A surface rougher than its period (RMS height above the cell length) is no shear cell; at
// 1e300 its generation did not end (issue #15's fuzzer).
void check_shear_cell(const ScenarioDef& s, const TomlReader& root) {
  const ShearCellDef& c = *s.shear_cell;
  const double limit = kMaxCoordinateInSpacings * s.discretization.mesh.spacing;
  if (!(c.length <= limit))
    root.table("shear_cell")
        ->fail("length", "expected at most " + number(kMaxCoordinateInSpacings) +
                             " node spacings (" + number(limit) + "), got " + number(c.length));
  if (!(c.roughness_rms <= c.length))
    root.table("shear_cell")
        ->fail("roughness_rms", "expected at most the cell length " + number(c.length) + ", got " +
                                    number(c.roughness_rms));
}

// The smallest deformable disc a [shear_cell] or [compaction_box] may generate (0: none known;
// ellipses and Fourier shapes are left to the meshing's own check).
double smallest_generated_disc(const ScenarioDef& s) {
  double d = 0.0;
  auto take = [&](double v) { d = d == 0.0 ? v : std::min(d, v); };
  auto add_components = [&](const std::vector<GrainComponentDef>& components) {
    for (const GrainComponentDef& c : components)
      if (!c.rigid && c.shape.kind == GrainShapeKind::disc && !own_spacing(s, c.spacing))
        take(c.shape.diameter.min);
  };
  if (s.shear_cell) {
    if (s.shear_cell->components.empty() && !own_spacing(s, s.shear_cell->grain_spacing))
      take(s.shear_cell->diameter.min);
    add_components(s.shear_cell->components);
  }
  if (s.compaction_box) add_components(s.compaction_box->components);
  return d;
}

void check_node_spacing(const ScenarioDef& s, const TomlReader& root) {
  const double h = s.discretization.mesh.spacing;
  const std::optional<TomlReader> discretization = root.table("discretization");
  const bool spacing_given = discretization && discretization->has("node_spacing");
  // Too large: the mesher's own check named two contour points that "coincide" (issue #26).
  if (const double d = smallest_generated_disc(s); d > 0.0 && h > 0.5 * d) {
    const std::string message = "node spacing " + number(h) +
                                " is too large for the generated grains of diameter down to " +
                                number(d) +
                                ": need node_spacing <= diameter / 2 = " + number(0.5 * d);
    if (spacing_given) discretization->fail("node_spacing", message);
    root.fail(s.shear_cell ? "shear_cell" : "compaction_box", message);
  }
  if (const double d = largest_generated_diameter(s); h < d / kMaxDiameterPerSpacing) {
    const std::string message =
        "node spacing " + number(h) + " is too small for the generated grains of diameter up to " +
        number(d) + ": need node_spacing >= diameter / " + number(kMaxDiameterPerSpacing) + " = " +
        number(d / kMaxDiameterPerSpacing);
    if (spacing_given) discretization->fail("node_spacing", message);
    root.fail(s.shear_cell ? "shear_cell" : "compaction_box", message);
  }
  const std::vector<TomlReader> grains = root.array_of_tables("grains");
  for (std::size_t i = 0; i < s.grains.size() && i < grains.size(); ++i) {
    const GrainSpec& g = s.grains[i];
    if (own_spacing(s, g.spacing)) continue;  // left to the mesher, which names the grain
    const double d = equivalent_diameter(g);
    if (!g.rigid && g.shape != GrainShape::contour && h > 0.5 * d) {
      const std::string message = "node spacing " + number(h) + " is too large for grain '" +
                                  g.name + "' of diameter " + number(d) +
                                  ": need node_spacing <= diameter / 2 = " + number(0.5 * d);
      if (spacing_given) discretization->fail("node_spacing", message);
      grains[i].fail(size_key(g), message);
    }
    if (g.rigid || h >= d / kMaxDiameterPerSpacing) continue;
    const std::string message =
        "node spacing " + number(h) + " is too small for grain '" + g.name + "' of diameter " +
        number(d) + ": it would take about " + number(std::numbers::pi / 4.0 * d * d / (h * h)) +
        " nodes; need node_spacing >= diameter / " + number(kMaxDiameterPerSpacing) + " = " +
        number(d / kMaxDiameterPerSpacing);
    if (spacing_given) discretization->fail("node_spacing", message);
    grains[i].fail(size_key(g), message);
  }
}

struct BodyOutline {
  BodyId body = -1;
  Polygon contour;
  double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
};

// Depth of the overlap of a and b shifted by (shift, 0): the largest distance of a contour
// point of one inside the other to the other's contour (0: disjoint or touching).
double overlap_depth(const BodyOutline& a, const BodyOutline& b, double shift) {
  Polygon moved = b.contour;
  for (Vec2& p : moved)
    p.x() += shift;
  double depth = 0.0;
  for (const Vec2& p : a.contour)
    if (contains(moved, p)) depth = std::max(depth, distance_to_contour(moved, p));
  for (const Vec2& p : moved)
    if (contains(a.contour, p)) depth = std::max(depth, distance_to_contour(a.contour, p));
  return depth;
}

struct Overlap {
  BodyId a, b;
  double depth;
};

// Overlapping pairs of closed bodies at least one of which is deformable (sweep in x).
std::vector<Overlap> find_overlaps(const Model& model, std::vector<BodyOutline> outlines) {
  const double period = model.periodic_x ? model.x_max - model.x_min : 0.0;
  std::sort(outlines.begin(), outlines.end(),
            [](const BodyOutline& p, const BodyOutline& q) { return p.x_lo < q.x_lo; });
  std::vector<Overlap> found;
  auto test = [&](const BodyOutline& a, const BodyOutline& b, double shift) {
    if (a.y_hi < b.y_lo || b.y_hi < a.y_lo || a.x_hi < b.x_lo + shift || b.x_hi + shift < a.x_lo)
      return;
    if (model.body(a.body).kind == BodyKind::rigid && model.body(b.body).kind == BodyKind::rigid)
      return;
    const double depth = overlap_depth(a, b, shift);
    if (depth > 0.0) found.push_back({std::min(a.body, b.body), std::max(a.body, b.body), depth});
  };
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    for (std::size_t j = i + 1; j < outlines.size() && outlines[j].x_lo <= outlines[i].x_hi; ++j)
      test(outlines[i], outlines[j], 0.0);
    if (period > 0.0)  // images across the seam
      for (std::size_t j = 0; j < outlines.size(); ++j)
        if (j != i) test(outlines[i], outlines[j], period);
  }
  std::sort(found.begin(), found.end(),
            [](const Overlap& p, const Overlap& q) { return p.depth > q.depth; });
  return found;
}

std::vector<BodyOutline> closed_outlines(const Model& model) {
  std::vector<Vec2> positions;
  compute_contour_positions(model, positions);
  const double period = model.x_max - model.x_min;
  std::vector<BodyOutline> outlines;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.open_contour) {
      SG_VERIFY(!model.periodic_x || std::abs(std::abs(body.closing_shift_x) - period) <=
                                         1e-9 * std::max(1.0, std::abs(period)),
                "first body '" << body.name << "' spans " << std::abs(body.closing_shift_x)
                               << " in x, not exactly the period " << period);
      continue;
    }
    BodyOutline o;
    o.body = static_cast<BodyId>(b);
    o.contour.assign(positions.begin() + body.contour_begin, positions.begin() + body.contour_end);
    o.x_lo = o.y_lo = std::numeric_limits<double>::infinity();
    o.x_hi = o.y_hi = -std::numeric_limits<double>::infinity();
    for (const Vec2& p : o.contour) {
      o.x_lo = std::min(o.x_lo, p.x());
      o.x_hi = std::max(o.x_hi, p.x());
      o.y_lo = std::min(o.y_lo, p.y());
      o.y_hi = std::max(o.y_hi, p.y());
    }
    if (model.periodic_x) {
      SG_VERIFY(o.x_hi - o.x_lo < period,
                "body '" << body.name << "' is " << o.x_hi - o.x_lo
                         << " wide in x, not narrower than the periodic cell [" << model.x_min
                         << ", " << model.x_max << ") of width " << period);
      const double middle = 0.5 * (o.x_lo + o.x_hi);
      SG_VERIFY(middle >= model.x_min && middle < model.x_max,
                "body '" << body.name << "' has its middle at x = " << middle
                         << ", outside the periodic cell [" << model.x_min << ", " << model.x_max
                         << ")");
    }
    outlines.push_back(std::move(o));
  }
  return outlines;
}

}  // namespace

void check_scenario_geometry(const ScenarioDef& scenario, const TomlReader& root) {
  if (const std::string why = plain_file_name_problem(scenario.name); !why.empty())
    root.fail("name", "the run name becomes the run folder <output>/<name>/: " + why);
  // The spacing first: the coordinate bound is in spacings (a grain's size is bounded by
  // the spacing check, at most kMaxDiameterPerSpacing spacings).
  check_node_spacing(scenario, root);
  check_coordinates(scenario, root);
  if (scenario.periodic_x) check_periodic_bodies(scenario, root);
  if (scenario.shear_cell) check_shear_cell(scenario, root);
}

std::string check_initial_state(const ScenarioDef& scenario, const Model& model, bool contacts_on,
                                std::ostream* progress) {
  std::vector<std::string> warnings;
  const std::vector<BodyOutline> outlines = closed_outlines(model);
  if (contacts_on) {
    const std::vector<Overlap> overlaps = find_overlaps(model, outlines);
    const std::size_t shown = std::min<std::size_t>(overlaps.size(), 5);
    for (std::size_t k = 0; k < shown; ++k)
      warnings.push_back("bodies '" + model.body(overlaps[k].a).name + "' and '" +
                         model.body(overlaps[k].b).name + "' overlap at t = 0 by " +
                         number(overlaps[k].depth) +
                         " (the contact pushes them apart violently on the first step)");
    if (overlaps.size() > shown)
      warnings.push_back(std::to_string(overlaps.size()) +
                         " overlapping pairs at t = 0 in all (the deepest listed above)");
  }
  for (const GrainSpec& g : scenario.grains) {
    const double most =
        std::max({g.stretch.x(), g.stretch.y(), 1.0 / g.stretch.x(), 1.0 / g.stretch.y()});
    if (most > kMaxInitialStretch)
      warnings.push_back("grain '" + g.name + "': initial stretch [" + number(g.stretch.x()) +
                         ", " + number(g.stretch.y()) + "] is beyond [" +
                         number(1.0 / kMaxInitialStretch) + ", " + number(kMaxInitialStretch) +
                         "]: an extreme initial state, the stiffened grain makes the stable "
                         "step small and the run slow");
  }
  std::string note;
  for (const std::string& w : warnings) {
    note += "# warning: " + w + "\n";
    if (progress) *progress << "softgrain: warning: " << w << "\n";
  }
  return note;
}

std::string describe_step_collapse(const Model& model, const StableStep& now, double first_dt) {
  std::ostringstream s;
  s << std::setprecision(4) << "the stable step fell to " << now.dt << ", below 1/"
    << kStepCollapseFactor << " of the first estimate " << first_dt;
  if (now.limiting_body >= 0)
    s << ": body '" << model.body(now.limiting_body).name << "' sets it (highest frequency "
      << now.omega_max << ", "
      << (now.damping_limited ? "its damping" : "its stiffened, strongly deformed elements")
      << "); the run will be slow: check its material, loading and initial state";
  return s.str();
}

}  // namespace sg
