// Bodies and first bodies from data (issue #13): grains listed in a CSV file land where the
// file says; a bad row names the file, the line and the column; explicit contours; periodic
// strips whose surface is a sum of sines (reproduced at every surface node) or a CSV profile
// (closed across the seam without a step).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "core/error.h"
#include "geometry/polygon.h"
#include "geometry/shapes.h"
#include "model/kinematics.h"
#include "model/model.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path dir() {
  return scenes::process_temp_dir("explicit_bodies");
}

fs::path write(const std::string& name, const std::string& text) {
  return scenes::write_text_file(dir() / name, text);
}

const std::string kHead = R"(
name = "explicit"
[time]
duration = 0.01
[discretization]
node_spacing = 0.1
[[materials]]
name = "soft"
young = 10.0
[[materials]]
name = "hard"
young = 1000.0
density = 2.0
)";

const BodyId kNone = -1;
BodyId body_named(const Model& m, const std::string& name) {
  for (std::size_t b = 0; b < m.bodies.size(); ++b)
    if (m.bodies[b].name == name) return static_cast<BodyId>(b);
  ADD_FAILURE() << "no body " << name;
  return kNone;
}

// The reference contour of a deformable body (its boundary nodes' reference positions).
Polygon reference_contour(const Model& m, const Body& b) {
  Polygon p;
  for (int i = b.node_begin; i < b.boundary_end; ++i)
    p.emplace_back(m.nodes.ref_x[static_cast<std::size_t>(i)],
                   m.nodes.ref_y[static_cast<std::size_t>(i)]);
  return p;
}

TEST(ExplicitBodies, GrainsFromCsvLandWhereTheFileSays) {
  write("grains.csv",
        "# three discs and an ellipse\n"
        "x, y, diameter, a, b, angle, material, rigid\n"
        "1.25, 2.5, 0.8, , , , soft, 0\n"
        "3.0, 2.75, 1.1, , , , hard, 1\n"
        "\n"
        "5.5, 1.0, 0.6, , , , , \n"
        "8.0, 3.0, , 0.6, 0.3, 0.5, soft, 0\n");
  const ScenarioDef s = load_scenario(write("g.toml", kHead + R"(
[[grains]]
grains_file = "grains.csv"
material = "soft"
)"));
  ASSERT_EQ(s.grains.size(), 4u);
  const Model m = build_model(s);
  const double h = 0.1;
  struct Expected {
    const char* name;
    Vec2 center;
    Polygon contour;
    bool rigid;
    double analytic_area;
  };
  const Expected expected[] = {
      {"grains_0", Vec2(1.25, 2.5), make_disc(Vec2(1.25, 2.5), 0.4, h), false,
       std::numbers::pi * 0.16},
      {"grains_1", Vec2(3.0, 2.75), make_disc(Vec2(3.0, 2.75), 0.55, h), true,
       std::numbers::pi * 0.3025},
      {"grains_2", Vec2(5.5, 1.0), make_disc(Vec2(5.5, 1.0), 0.3, h), false,
       std::numbers::pi * 0.09},
      {"grains_3", Vec2(8.0, 3.0), make_ellipse(Vec2(8.0, 3.0), 0.6, 0.3, 0.5, h), false,
       std::numbers::pi * 0.18}};
  for (const Expected& e : expected) {
    const Body& b = m.body(body_named(m, e.name));
    ASSERT_EQ(b.kind == BodyKind::rigid, e.rigid) << e.name;
    const double area = signed_area(e.contour);
    if (e.rigid) {
      const auto r = static_cast<std::size_t>(b.rigid_index);
      EXPECT_NEAR(m.rigid.x[r], centroid(e.contour).x(), 1e-12) << e.name;
      EXPECT_NEAR(m.rigid.y[r], centroid(e.contour).y(), 1e-12) << e.name;
      EXPECT_NEAR(m.rigid.mass[r], 2.0 * area, 1e-12) << e.name;  // density 2 ("hard")
    } else {
      const Polygon p = reference_contour(m, b);
      EXPECT_NEAR((centroid(p) - centroid(e.contour)).norm(), 0.0, 1e-12) << e.name;
      EXPECT_NEAR(signed_area(p), area, 1e-12) << e.name;
    }
    // The polygon is the file's grain: its centre within the resampling's asymmetry (a disc
    // is symmetric), its area within its discretization (3% at h / r = 1/3) of pi a b.
    EXPECT_NEAR((centroid(e.contour) - e.center).norm(), 0.0, 1e-6) << e.name;
    EXPECT_NEAR(area, e.analytic_area, 0.03 * e.analytic_area) << e.name;
  }
  // The row without a material takes the table's.
  EXPECT_EQ(m.body(body_named(m, "grains_2")).material, 0);
}

TEST(ExplicitBodies, ABadRowNamesTheFileLineAndColumn) {
  struct Case {
    const char* csv;
    const char* expected;
  };
  const Case cases[] = {
      {"x, y, diameter\n1, 1, 0.5\n# comment\n2, 1, abc\n",
       "bad.csv:4: column 3 'diameter': expected a number, got 'abc'"},
      {"x, y, diameter\n1, 1, -0.5\n",
       "bad.csv:2: column 3 'diameter': expected a positive number"},
      {"x, y, diameter\n1, 1, 0.5, 7\n", "bad.csv:2: column 4: expected 3 cells"},
      {"x, y, size\n1, 1, 0.5\n", "bad.csv:1: column 3 'size': unknown column"},
      {"x, y, a, b\n1, 1, 0.5, \n", "bad.csv:2: column 4 'b': required number is missing"},
      {"x, y, diameter, rigid\n1, 1, 0.5, yes\n",
       "bad.csv:2: column 4 'rigid': expected 0, 1, true or false"},
  };
  for (const Case& c : cases) {
    write("bad.csv", c.csv);
    const std::string what = scenes::scenario_error(dir(), kHead + R"(
[[grains]]
grains_file = "bad.csv"
material = "soft"
)");
    EXPECT_NE(what.find((dir() / c.expected).string()), std::string::npos)
        << "got: " << what << "\nexpected: " << c.expected;
  }
  // A missing file names the scenario's key.
  const std::string missing = scenes::scenario_error(dir(), kHead + R"(
[[grains]]
grains_file = "nowhere.csv"
material = "soft"
)");
  EXPECT_NE(missing.find("key 'grains[0].grains_file': file"), std::string::npos) << missing;
}

TEST(ExplicitBodies, ContoursInlineOrFromCsvRigidOrDeformable) {
  // A clockwise square from a file (made CCW), and an inline triangle.
  write("square.csv", "x, y\n0, 0\n0, 1\n1, 1\n1, 0\n");
  const ScenarioDef s = load_scenario(write("c.toml", kHead + R"(
[[grains]]
name = "square"
shape = "contour"
contour_file = "square.csv"
material = "hard"
rigid = true
[[grains]]
name = "triangle"
shape = "contour"
points = [[2.0, 0.0], [3.0, 0.0], [2.0, 1.5]]
material = "soft"
)"));
  const Model m = build_model(s);
  const Body& square = m.body(body_named(m, "square"));
  const auto r = static_cast<std::size_t>(square.rigid_index);
  EXPECT_NEAR(m.rigid.x[r], 0.5, 1e-12);
  EXPECT_NEAR(m.rigid.y[r], 0.5, 1e-12);
  EXPECT_NEAR(m.rigid.mass[r], 2.0, 1e-12);
  EXPECT_NEAR(m.rigid.inertia[r], 2.0 / 6.0, 1e-12);  // m (a^2 + b^2) / 12
  EXPECT_EQ(square.contour_count(), 40);              // edges subdivided at h = 0.1
  const Polygon triangle = reference_contour(m, m.body(body_named(m, "triangle")));
  EXPECT_NEAR(signed_area(triangle), 0.75, 1e-12);
  EXPECT_NEAR((centroid(triangle) - Vec2(7.0 / 3.0, 0.5)).norm(), 0.0, 1e-12);

  const std::string crossed = scenes::scenario_error(dir(), kHead + R"(
[[grains]]
shape = "contour"
points = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, -1.0]]
material = "soft"
)");
  EXPECT_NE(crossed.find("key 'grains[0].points': the contour intersects itself"),
            std::string::npos)
      << crossed;
}

// Two strips of a periodic cell L = 10: a rigid one below (two sines) and a deformable one
// above (a CSV profile).
std::string strips_scenario(const std::string& top_profile) {
  return kHead + R"(
[periodic]
x_min = -2.0
x_max = 8.0
[[strips]]
name = "bottom"
material = "hard"
surface_y = 0.5
back_y = -1.5
[strips.profile]
kind = "sines"
[[strips.profile.modes]]
amplitude = 0.2
wavelength = 5.0
phase = 0.3
[[strips.profile.modes]]
amplitude = 0.05
wavelength = 2.0
[[strips]]
name = "top"
material = "soft"
rigid = false
surface_y = 4.0
back_y = 5.0
)" + top_profile;
}

double expected_sines(double x) {  // the bottom strip's surface, written out
  const double s = x + 2.0;        // from the start of the period
  return 0.5 + 0.2 * std::sin(2.0 * std::numbers::pi * s / 5.0 + 0.3) +
         0.05 * std::sin(2.0 * std::numbers::pi * s / 2.0);
}

TEST(ExplicitBodies, SumOfSinesIsReproducedAtEverySurfaceNode) {
  for (const char* rigid : {"true", "false"}) {
    std::string text =
        scenes::replace_once(strips_scenario(R"(
[strips.profile]
kind = "sines"
[[strips.profile.modes]]
amplitude = 0.1
wavelength = 10.0
)"),
                             "back_y = -1.5", std::string("back_y = -1.5\nrigid = ") + rigid);
    const Model m = build_model(load_scenario(write("sines.toml", text)));
    const Body& bottom = m.body(body_named(m, "bottom"));
    std::vector<Vec2> points;
    compute_contour_positions(m, points);
    ASSERT_EQ(bottom.contour_count(), 100);  // L / h
    double worst = 0.0;
    for (int k = bottom.contour_begin; k < bottom.contour_end; ++k) {
      const Vec2& p = points[static_cast<std::size_t>(k)];
      worst = std::max(worst, std::abs(p.y() - expected_sines(p.x())));
      EXPECT_GE(p.x(), -2.0 - 1e-12);
      EXPECT_LT(p.x(), 8.0);
    }
    EXPECT_LT(worst, 1e-12) << "rigid = " << rigid;
    // The surface nodes are the deformable strip's boundary nodes: their reference positions.
    if (bottom.kind == BodyKind::deformable)
      for (int i = bottom.node_begin; i < bottom.boundary_end; ++i) {
        const auto n = static_cast<std::size_t>(i);
        EXPECT_NEAR(m.nodes.ref_y[n], expected_sines(m.nodes.ref_x[n]), 1e-12);
      }
  }
  // A wavelength that does not divide the period is refused.
  std::string bad = scenes::replace_once(strips_scenario(R"(
[strips.profile]
kind = "self_affine"
)"),
                                         "wavelength = 2.0", "wavelength = 3.0");
  try {
    build_model(load_scenario(write("bad_sines.toml", bad)));
    ADD_FAILURE() << "a wavelength of 3 in a period of 10 was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not divide the period"), std::string::npos)
        << e.what();
  }
}

TEST(ExplicitBodies, CsvProfileIsClosedAcrossTheSeamWithoutAStep) {
  // Coarse points over one period [-2, 8): the seam segment (7, 4.3) -> (-2 + 10, 4.1) is long,
  // and so is the first one; both are subdivided on their straight lines.
  write("top.csv", "x, y\n-1.5, 0.1\n1.0, -0.2\n3.0, 0.25\n5.5, 0.0\n7.0, 0.3\n");
  const std::string profile = R"(
[strips.profile]
kind = "points"
file = "top.csv"
)";
  const Model m = build_model(load_scenario(write("csv.toml", strips_scenario(profile))));
  const Body& top = m.body(body_named(m, "top"));
  ASSERT_EQ(top.kind, BodyKind::deformable);
  EXPECT_TRUE(top.open_contour);
  EXPECT_DOUBLE_EQ(top.closing_shift_x, 10.0);
  // The profile as a periodic piecewise-linear function of x, from the file.
  const std::vector<Vec2> file = {{-1.5, 0.1}, {1.0, -0.2}, {3.0, 0.25},
                                  {5.5, 0.0},  {7.0, 0.3},  {8.5, 0.1}};
  auto csv_height = [&](double x) {
    if (x < -1.5) x += 10.0;
    for (std::size_t i = 1; i < file.size(); ++i)
      if (x <= file[i].x())
        return file[i - 1].y() + (x - file[i - 1].x()) / (file[i].x() - file[i - 1].x()) *
                                     (file[i].y() - file[i - 1].y());
    return 0.0 / 0.0;
  };
  std::vector<Vec2> p;
  for (int i = top.node_begin; i < top.boundary_end; ++i)
    p.emplace_back(m.nodes.ref_x[static_cast<std::size_t>(i)],
                   m.nodes.ref_y[static_cast<std::size_t>(i)]);
  double worst = 0.0, widest = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    worst = std::max(worst, std::abs(p[k].y() - 4.0 - csv_height(p[k].x())));
    // Consecutive surface points, the seam pair (last -> first + L) included: x advances (no
    // vertical step) by at most 1.5 h.
    const Vec2 next = k + 1 < p.size() ? p[k + 1] : p[0] + Vec2(10.0, 0.0);
    EXPECT_GT(next.x() - p[k].x(), 0.0) << k;
    widest = std::max(widest, (next - p[k]).norm());
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_LE(widest, 0.15 + 1e-12);
  EXPECT_LT(p.front().x(), -1.5);  // seam points wrapped to the front of the period

  // The last point may repeat the first one at x_min + L (its periodic image), with its height.
  write("top.csv", "x, y\n-2.0, 0.1\n3.0, 0.25\n8.0, 0.1\n");
  EXPECT_NO_THROW(build_model(load_scenario(write("csv2.toml", strips_scenario(profile)))));
  write("top.csv", "x, y\n-2.0, 0.1\n3.0, 0.25\n8.0, 0.4\n");
  try {
    build_model(load_scenario(write("csv3.toml", strips_scenario(profile))));
    ADD_FAILURE() << "a step at the seam was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("a step at the seam"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("top.csv"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sg
