// The [compaction_box] builder (paper 000 §4): walls, lid history, grains, and the errors
// of its TOML section.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "geometry/polygon.h"
#include "model/kinematics.h"
#include "scenes/scenario_files.h"

namespace sg {
namespace {

const std::string kBase = R"(
[time]
duration = 1.0

[discretization]
node_spacing = 0.15

[[materials]]
name = "soft"
young = 10.0
poisson = 0.4

[[materials]]
name = "hard"
young = 1000.0
density = 2.0
)";

const std::string kBox = R"(
[compaction_box]
width = 4.0
grains = 12
grain_material = "soft"
wall_material = "hard"
lid_velocity = 0.2
lid_ramp_time = 0.5
final_height = 3.5
seed = 5

[[compaction_box.components]]
shape = "fourier"
fraction = 2.0
diameter = [0.8, 1.2]
elongation = 0.15
irregularity = 0.06
material = "hard"
rigid = true

[[compaction_box.components]]
shape = "disc"
fraction = 1.0
diameter = [0.8, 1.2]
)";

// Integral of a piecewise-linear history from 0 to its last knot (trapezoids, exact).
double travel_of(const PiecewiseLinear& v) {
  double sum = 0.0;
  for (std::size_t i = 1; i < v.times.size(); ++i)
    sum += 0.5 * (v.values[i] + v.values[i - 1]) * (v.times[i] - v.times[i - 1]);
  return sum;
}

TEST(CompactionBox, LidStopsExactlyAtTheFinalHeight) {
  CompactionBoxDef def;
  def.lid_velocity = 0.25;
  def.final_height = 7.0;
  for (const double ramp : {0.0, 0.5}) {
    SCOPED_TRACE(ramp);
    def.lid_ramp_time = ramp;
    double stop = 0.0, travelled = 0.0;
    const PiecewiseLinear v = lid_speed_history(def, 9.0, stop, travelled);
    EXPECT_DOUBLE_EQ(travelled, 2.0);
    EXPECT_NEAR(travel_of(v), 2.0, 1e-12);  // the history covers exactly H0 - H_final
    EXPECT_DOUBLE_EQ(v.times.back(), stop);
    EXPECT_EQ(v(stop + 1.0), 0.0);  // then holds
    EXPECT_EQ(v(0.0), ramp > 0.0 ? 0.0 : 0.25);
    EXPECT_DOUBLE_EQ(v(0.5 * stop), 0.25);
  }
  // A duration instead: travel = V (T - ramp).
  def.final_height = 0.0;
  def.compaction_time = 4.0;
  def.lid_ramp_time = 1.0;
  double stop = 0.0, travelled = 0.0;
  const PiecewiseLinear v = lid_speed_history(def, 9.0, stop, travelled);
  EXPECT_DOUBLE_EQ(stop, 4.0);
  EXPECT_NEAR(travel_of(v), 0.25 * 3.0, 1e-12);
  EXPECT_NEAR(travelled, 0.75, 1e-12);
  // Ramps longer than half the motion cannot fit.
  def.lid_ramp_time = 2.5;
  EXPECT_THROW(lid_speed_history(def, 9.0, stop, travelled), Error);
}

TEST(CompactionBox, FourNamedWallsThatNeverTouchAndGrainsInside) {
  const std::filesystem::path dir = scenes::process_temp_dir("compaction_box");
  const ScenarioDef s = load_scenario(scenes::write_text_file(dir / "box.toml", kBase + kBox));
  ASSERT_TRUE(s.compaction_box);
  const Model model = build_model(s);
  ASSERT_EQ(model.bodies.size(), 16u);
  const char* walls[] = {"bottom", "left", "right", "lid"};
  for (int k = 0; k < 4; ++k) {
    const Body& b = model.body(k);
    EXPECT_EQ(b.name, walls[k]);
    ASSERT_EQ(b.kind, BodyKind::rigid);
    const RigidDrive& d = model.rigid.drive[static_cast<std::size_t>(b.rigid_index)];
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(d.mode[c], DriveMode::velocity) << walls[k];
    // Only the lid moves, downwards, with the ramp: at rest at t = 0, -V mid-way.
    EXPECT_EQ(d.velocity[1](0.0), 0.0);
    EXPECT_EQ(d.velocity[1](2.0), k == 3 ? -0.2 : 0.0) << walls[k];
  }
  // 12 grains at 2 : 1: 8 rigid Fourier grains, 4 deformable discs, along x (packing.h
  // order_along_x: by the centroids of the packed contours; the bodies' contours are those
  // resampled, hence the margin), each named after its place in the drawn population.
  std::vector<Vec2> p;
  compute_contour_positions(model, p);
  int rigid = 0;
  std::set<std::string> names;
  double previous_x = -1e300;
  for (std::size_t b = 4; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    names.insert(body.name);
    rigid += body.kind == BodyKind::rigid;
    const double x =
        centroid(Polygon(p.begin() + body.contour_begin, p.begin() + body.contour_end)).x();
    EXPECT_GT(x, previous_x - 0.05) << body.name;
    previous_x = x;
  }
  EXPECT_EQ(rigid, 8);
  EXPECT_EQ(names.size(), 12u);
  for (int i = 0; i < 12; ++i)
    EXPECT_TRUE(names.count("grain_" + std::to_string(i))) << i;
  auto box_of = [&](std::size_t b) {
    Vec2 lo = p[static_cast<std::size_t>(model.bodies[b].contour_begin)], hi = lo;
    for (int i = model.bodies[b].contour_begin; i < model.bodies[b].contour_end; ++i) {
      lo = lo.cwiseMin(p[static_cast<std::size_t>(i)]);
      hi = hi.cwiseMax(p[static_cast<std::size_t>(i)]);
    }
    return std::pair{lo, hi};
  };
  const auto [bottom_lo, bottom_hi] = box_of(0);
  const auto [left_lo, left_hi] = box_of(1);
  const auto [right_lo, right_hi] = box_of(2);
  const auto [lid_lo, lid_hi] = box_of(3);
  const double h = 0.15;  // the clearance between walls is one node spacing
  EXPECT_NEAR(bottom_hi.y(), 0.0, 1e-12);
  EXPECT_NEAR(left_lo.y() - bottom_hi.y(), h, 1e-12);
  EXPECT_NEAR(right_lo.y() - bottom_hi.y(), h, 1e-12);
  EXPECT_NEAR(lid_lo.x() - left_hi.x(), h, 1e-12);
  EXPECT_NEAR(right_lo.x() - lid_hi.x(), h, 1e-12);
  EXPECT_NEAR(right_lo.x() - left_hi.x(), 4.0, 1e-12);
  // Every grain point inside the box, at least the packer's clearance (2% of the mean size
  // 1) from the walls; the lid 2% above the highest grain point.
  double top = 0.0;
  for (std::size_t b = 4; b < model.bodies.size(); ++b) {
    const auto [lo, hi] = box_of(b);
    EXPECT_GE(lo.x(), 0.02 - 1e-9);
    EXPECT_LE(hi.x(), 4.0 - 0.02 + 1e-9);
    EXPECT_GE(lo.y(), 0.02 - 1e-9);
    top = std::max(top, hi.y());
  }
  EXPECT_NEAR(lid_lo.y(), top + 0.02, 1e-9);
  EXPECT_GT(lid_lo.y(), 3.5);  // above the final height it is driven to
}

TEST(CompactionBox, ErrorsNameFileLineAndKey) {
  const std::filesystem::path dir = scenes::process_temp_dir("compaction_box_errors");
  auto error = [&](const std::string& from, const std::string& to) {
    return scenes::scenario_error(dir, kBase + scenes::replace_once(kBox, from, to));
  };
  auto expect_error = [](const std::string& message, const std::string& key,
                         const std::string& what) {
    EXPECT_NE(message.find("bad.toml:"), std::string::npos) << message;
    EXPECT_NE(message.find("key '" + key + "'"), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  expect_error(error("width = 4.0\n", ""), "compaction_box.width", "");
  expect_error(error("final_height = 3.5", "final_height = 3.5\ncompaction_time = 2.0"),
               "compaction_box.final_height", "exactly one of");
  expect_error(error("final_height = 3.5", ""), "compaction_box.final_height", "exactly one of");
  expect_error(error("lid_velocity = 0.2", "lid_velocity = -0.2"), "compaction_box.lid_velocity",
               "positive");
  expect_error(error("wall_material = \"hard\"", "wall_material = \"steel\""),
               "compaction_box.wall_material", "unknown material 'steel'");
  expect_error(error("shape = \"disc\"", "shape = \"disc\"\nelongation = 0.1"),
               "compaction_box.components[1].elongation", "fourier");
  expect_error(error("shape = \"fourier\"", "shape = \"star\""),
               "compaction_box.components[0].shape", "");
  expect_error(error("elongation = 0.15", "elongation = 0.45"),
               "compaction_box.components[0].elongation", "< 0.5");
  expect_error(error("seed = 5", "seed = 5\nheight = 3.0"), "compaction_box.final_height",
               "below the initial height");
  expect_error(error("seed = 5", "seed = 5\ncolour = 1"), "compaction_box.colour", "");
}

}  // namespace
}  // namespace sg
