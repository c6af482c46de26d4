// Node spacings per body (issue #32): the keys node_spacing and interior_spacing of
// [discretization], [[materials]] and [[shear_cell.components]], good and bad.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "model/model.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/shear_cell_scenario.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

const std::string kTiny = std::string(R"(
name = "tiny"
[time]
duration = 0.05
)") + scenes::kTinyScenarioBody;

ScenarioDef load(const std::string& text) {
  return load_scenario(
      scenes::write_text_file(scenes::process_temp_dir("node_spacing") / "good.toml", text));
}

std::string error_of(const std::string& text) {
  return scenes::scenario_error(scenes::process_temp_dir("node_spacing"), text);
}

// Shortest and longest contour edge of a deformable body.
std::pair<double, double> contour_edges(const Model& model, BodyId b) {
  const Body& body = model.body(b);
  double shortest = 1e300, longest = 0.0;
  const int n = body.boundary_end - body.node_begin;
  for (int i = 0; i < n; ++i) {
    const auto p = static_cast<std::size_t>(body.node_begin + i);
    const auto q = static_cast<std::size_t>(body.node_begin + (i + 1) % n);
    const double edge = std::hypot(model.nodes.ref_x[q] - model.nodes.ref_x[p],
                                   model.nodes.ref_y[q] - model.nodes.ref_y[p]);
    shortest = std::min(shortest, edge);
    longest = std::max(longest, edge);
  }
  return {shortest, longest};
}

int node_count(const Model& model, BodyId b) {
  return model.body(b).node_end - model.body(b).node_begin;
}

TEST(NodeSpacing, UniformByDefault) {
  const ScenarioDef s = load(kTiny);
  EXPECT_EQ(s.discretization.mesh.spacing, 0.15);
  EXPECT_EQ(s.discretization.mesh.interior_spacing, 0.0);
  ASSERT_EQ(s.material_spacing.size(), 2u);
  EXPECT_EQ(s.material_spacing[0].contour, 0.15);
  EXPECT_FALSE(s.material_spacing[0].graded());
  EXPECT_EQ(s.contact_cutoff, std::max(0.25 * 0.15, 1.5 * 0.5 / (2.0 * 1000.0)));
}

// A material with its own spacings: its grain has contour nodes at that spacing, fewer nodes
// than the same grain uniform, and the default contact cutoff follows the finest spacing.
TEST(NodeSpacing, MaterialSpacingsGradeItsGrains) {
  const std::string graded_text = scenes::replace_once(
      kTiny, "damping = 0.01\n", "damping = 0.01\nnode_spacing = 0.05\ninterior_spacing = 0.15\n");
  const std::string uniform_text =
      scenes::replace_once(kTiny, "damping = 0.01\n", "damping = 0.01\nnode_spacing = 0.05\n");
  const ScenarioDef graded = load(graded_text);
  const ScenarioDef uniform = load(uniform_text);
  EXPECT_EQ(graded.material_spacing[0].contour, 0.05);
  EXPECT_EQ(graded.material_spacing[0].interior, 0.15);
  EXPECT_EQ(graded.material_spacing[1].contour, 0.15);  // "hard" keeps [discretization]'s
  EXPECT_EQ(graded.grains[0].spacing.interior, 0.15);
  EXPECT_EQ(graded.contact_cutoff, 0.25 * 0.05);
  const Model g = build_model(graded);
  const Model u = build_model(uniform);
  ASSERT_EQ(g.body(0).name, "grain_0");  // the soft disc; the grains come first
  const auto [shortest, longest] = contour_edges(g, 0);
  EXPECT_GT(shortest, 0.95 * 0.05);
  EXPECT_LT(longest, 1.05 * 0.05);
  EXPECT_LT(node_count(g, 0), node_count(u, 0));
  EXPECT_EQ(g.body(0).boundary_end - g.body(0).node_begin,
            u.body(0).boundary_end - u.body(0).node_begin);
}

// [[shear_cell.components]]: circles and ellipses with spacings of their own (paper 003's
// 30 / 90 nm and 60 / 170 nm, here in units of the test's grains).
TEST(NodeSpacing, ShearCellComponentsHaveTheirOwnSpacings) {
  scenes::CohesiveShearCell c;
  c.grains = 6;
  std::string text = scenes::shear_cell_scenario(c);
  text = scenes::replace_once(text, "diameter = [0.85, 1.15]\n", "");
  text += R"([[shear_cell.components]]
shape = "disc"
fraction = 1
diameter = [0.8, 1.0]
node_spacing = 0.06
interior_spacing = 0.18
[[shear_cell.components]]
shape = "ellipse"
fraction = 1
major_axis = [1.2, 1.6]
minor_axis = [0.7, 0.9]
node_spacing = 0.1
interior_spacing = 0.28
)";
  const ScenarioDef s = load(text);
  ASSERT_EQ(s.shear_cell->components.size(), 2u);
  EXPECT_EQ(s.shear_cell->components[0].spacing.contour, 0.06);
  EXPECT_EQ(s.shear_cell->components[1].spacing.interior, 0.28);
  EXPECT_EQ(s.shear_cell->first_body_spacing.contour, 0.25);
  EXPECT_EQ(s.contact_cutoff, std::max(0.25 * 0.06, 1.5 * 0.1 / (2.0 * 2000.0)));
  const Model model = build_model(s);
  int discs = 0, ellipses = 0;
  for (BodyId b = 2; b < static_cast<BodyId>(model.bodies.size()); ++b) {
    const auto [shortest, longest] = contour_edges(model, b);
    const bool fine = longest < 0.08;
    (fine ? discs : ellipses) += 1;
    const double h = fine ? 0.06 : 0.1;
    EXPECT_GT(shortest, 0.9 * h) << model.body(b).name;
    EXPECT_LT(longest, 1.1 * h) << model.body(b).name;
  }
  EXPECT_EQ(discs, 3);
  EXPECT_EQ(ellipses, 3);
}

TEST(NodeSpacing, BadValuesNameFileKeyAndExpectation) {
  struct Case {
    std::string from, to, expected;
  };
  const Case cases[] = {
      {"node_spacing = 0.15", "node_spacing = 0.15\ninterior_spacing = 0.1",
       "key 'discretization.interior_spacing': expected a spacing >= the contour spacing "
       "node_spacing = 0.15"},
      {"node_spacing = 0.15", "node_spacing = 0.15\ninterior_spacing = -1",
       "key 'discretization.interior_spacing': expected a positive number"},
      {"damping = 0.01\n", "damping = 0.01\nnode_spacing = 0.1\ninterior_spacing = 0.05\n",
       "key 'materials[0].interior_spacing': expected a spacing >= the contour spacing "
       "node_spacing = 0.1"},
      {"damping = 0.01\n", "damping = 0.01\ninterior_spacing = 0.1\n",
       "key 'materials[0].interior_spacing': expected a spacing >= the contour spacing "
       "node_spacing = 0.15"},
      {"damping = 0.01\n", "damping = 0.01\nnode_spacing = 0\n",
       "key 'materials[0].node_spacing': expected a positive number"},
      {"damping = 0.01\n", "damping = 0.01\nnode_spacing = \"fine\"\n",
       "key 'materials[0].node_spacing': expected a number"},
      {"damping = 0.01\n", "damping = 0.01\ninterior_spacings = 0.3\n",
       "key 'materials[0].interior_spacings': unknown key"},
  };
  for (const Case& c : cases) {
    const std::string what = error_of(scenes::replace_once(kTiny, c.from, c.to));
    EXPECT_NE(what.find(c.expected), std::string::npos) << "got: " << what;
    EXPECT_NE(what.find("bad.toml"), std::string::npos) << "got: " << what;
  }
}

TEST(NodeSpacing, BadComponentSpacingsAreRefused) {
  scenes::CohesiveShearCell c;
  std::string text = scenes::shear_cell_scenario(c);
  text = scenes::replace_once(text, "diameter = [0.85, 1.15]\n", "");
  const std::string component = R"([[shear_cell.components]]
shape = "disc"
fraction = 1
diameter = [0.8, 1.0]
)";
  std::string what = error_of(text + component + "node_spacing = 0.1\ninterior_spacing = 0.08\n");
  EXPECT_NE(what.find("key 'shear_cell.components[0].interior_spacing': expected a spacing >= "
                      "the contour spacing node_spacing = 0.1"),
            std::string::npos)
      << what;
  what = error_of(text + component + "node_spacing = 0.6\n");
  EXPECT_NE(what.find("key 'shear_cell.components[0].node_spacing': node spacing 0.6 is too "
                      "large for the grains of width down to 0.8"),
            std::string::npos)
      << what;
}

TEST(NodeSpacing, CompactionBoxRefusesMaterialSpacings) {
  const std::string text = std::string(R"(
name = "box"
[time]
duration = 0.05
[compaction_box]
width = 4.0
grains = 4
grain_material = "soft"
wall_material = "hard"
lid_velocity = 0.1
final_height = 3.0
lid_ramp_time = 0.5
[[compaction_box.components]]
shape = "disc"
fraction = 1.0
diameter = [0.8, 1.0]
)") + scenes::replace_once(scenes::kSoftHardCoulomb, "damping = 0.01\n",
                           "damping = 0.01\nnode_spacing = 0.1\n");
  const std::string what = error_of(text);
  EXPECT_NE(what.find("key 'materials[0].node_spacing': a [compaction_box] takes its node "
                      "spacings from [discretization]"),
            std::string::npos)
      << what;
}

}  // namespace
}  // namespace sg
