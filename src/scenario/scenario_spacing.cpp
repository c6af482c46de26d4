// Node spacings per body (issue #32): the node_spacing / interior_spacing keys of
// [discretization], [[materials]] and [[shear_cell.components]], resolved from the most
// general to the most specific (scenario_readers.h).
#include <algorithm>
#include <sstream>
#include <string>

#include "core/error.h"
#include "meshfree/domain_mesh.h"
#include "scenario/scenario_readers.h"

namespace sg {

namespace {

std::string spacing_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

NodeSpacing read_node_spacing(const TomlReader& t, const NodeSpacing& inherited) {
  NodeSpacing s = inherited;
  if (t.has("node_spacing")) {
    s.contour = t.positive("node_spacing");
    s.interior = 0.0;  // a table that sets the contour spacing alone is uniform at it
  }
  if (t.has("interior_spacing")) {
    s.interior = t.positive("interior_spacing");
    if (s.interior < s.contour)
      t.fail("interior_spacing",
             "expected a spacing >= the contour spacing node_spacing = " + spacing_text(s.contour) +
                 " (a graded body coarsens inwards; equal: uniform), got " +
                 spacing_text(s.interior));
  }
  return s;
}

NodeSpacing material_spacing(const ScenarioDef& s, const std::string& material) {
  for (std::size_t i = 0; i < s.materials.size() && i < s.material_spacing.size(); ++i)
    if (s.materials[i].name == material) return s.material_spacing[i];
  return {};
}

namespace {

// A grain component's contour spacing against its sizes (as check_node_spacing does for the
// [discretization] spacing): at most half its smallest width (the mesher refuses a coarser
// one, naming only a body), at least its largest size / kMaxDiameterPerSpacing. `t`: the table
// to name (the component's, or [shear_cell] for its default discs).
void check_component_spacing(const TomlReader& t, const char* material_key, double spacing,
                             double smallest_width, double largest_size) {
  // The spacing is the component's own, or its material's.
  const char* key = t.has("node_spacing") ? "node_spacing" : material_key;
  if (spacing > 0.5 * smallest_width)
    t.fail(key, "node spacing " + spacing_text(spacing) +
                    " is too large for the grains of width down to " +
                    spacing_text(smallest_width) +
                    ": expected node_spacing <= width / 2 = " + spacing_text(0.5 * smallest_width));
  if (spacing < largest_size / kMaxDiameterPerSpacing)
    t.fail(key, "node spacing " + spacing_text(spacing) +
                    " is too small for the grains of size up to " + spacing_text(largest_size) +
                    ": expected node_spacing >= size / " + spacing_text(kMaxDiameterPerSpacing) +
                    " = " + spacing_text(largest_size / kMaxDiameterPerSpacing));
}

}  // namespace

void resolve_shear_cell_spacing(const TomlReader& t, ScenarioDef& s) {
  ShearCellDef& c = *s.shear_cell;
  c.grain_spacing = material_spacing(s, c.grain_material);
  c.first_body_spacing = material_spacing(s, c.first_body_material);
  const double h = s.discretization.mesh.spacing;
  if (c.components.empty() && c.grain_spacing.contour != h)
    check_component_spacing(t, "grain_material", c.grain_spacing.contour, c.diameter.min,
                            c.diameter.max);
  const std::vector<TomlReader> tables = t.array_of_tables("components");
  for (std::size_t i = 0; i < c.components.size() && i < tables.size(); ++i) {
    GrainComponentDef& component = c.components[i];
    component.spacing = read_node_spacing(
        tables[i],
        material_spacing(s, component.material.empty() ? c.grain_material : component.material));
    if (component.spacing.contour == h || component.rigid) continue;
    const GrainShapeDef& shape = component.shape;
    if (shape.kind == GrainShapeKind::ellipse)
      check_component_spacing(tables[i], "material", component.spacing.contour,
                              shape.minor_axis.min, shape.major_axis.max);
    else
      check_component_spacing(tables[i], "material", component.spacing.contour, shape.diameter.min,
                              shape.diameter.max);
  }
}

void refuse_material_spacing_in_compaction_box(const TomlReader& root, const ScenarioDef& s) {
  const CompactionBoxDef& box = *s.compaction_box;
  std::vector<std::string> used = {box.grain_material, box.wall_material};
  for (const GrainComponentDef& c : box.components)
    used.push_back(c.material);
  const std::vector<TomlReader> tables = root.array_of_tables("materials");
  for (std::size_t i = 0; i < s.materials.size() && i < tables.size(); ++i) {
    if (std::find(used.begin(), used.end(), s.materials[i].name) == used.end()) continue;
    for (const char* key : {"node_spacing", "interior_spacing"})
      if (tables[i].has(key))
        tables[i].fail(key,
                       "a [compaction_box] takes its node spacings from [discretization]; "
                       "expected no node spacing on its materials (they apply to [[grains]], "
                       "[[walls]], [[strips]] and [shear_cell])");
  }
}

double finest_contour_spacing(const ScenarioDef& s) {
  double finest = s.discretization.mesh.spacing;
  for (const NodeSpacing& m : s.material_spacing)
    if (m.contour > 0.0) finest = std::min(finest, m.contour);
  if (s.shear_cell)
    for (const GrainComponentDef& c : s.shear_cell->components)
      if (c.spacing.contour > 0.0) finest = std::min(finest, c.spacing.contour);
  return finest;
}

}  // namespace sg
