// Drive histories (issue #13): a piecewise-linear velocity table is followed exactly by a
// driven rigid body (its position is the integral of the table, to round-off at the knots),
// a force history acts as the force it says, and the built-in drives are special cases of the
// tables: a wall's `velocity` and the shear cell's ramp give the same runs, bit for bit, as
// the equivalent drive tables (and a different table does not).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "model/model.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/scenario_run.h"
#include "scenes/series_text.h"
#include "scenes/shear_cell_scenario.h"
#include "solver/stepper.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path dir() {
  return scenes::process_temp_dir("drive_histories");
}

const std::string kHead = R"(
name = "drive"
[time]
duration = 1.0
[discretization]
node_spacing = 0.1
[[materials]]
name = "hard"
young = 1000.0
)";

// The integral of a piecewise-linear table, constant outside its knots, from 0 to t (two
// knots at one time: a jump).
double integral(const PiecewiseLinear& f, double t) {
  double sum = f.values.front() * std::min(t, f.times.front());
  for (std::size_t i = 1; i < f.times.size(); ++i) {
    const double a = f.times[i - 1];
    if (t <= a) break;
    if (f.times[i] == a) continue;  // a jump
    const double b = std::min(f.times[i], t);
    const double fb =
        f.values[i - 1] + (b - a) / (f.times[i] - a) * (f.values[i] - f.values[i - 1]);
    sum += 0.5 * (f.values[i - 1] + fb) * (b - a);
  }
  if (t > f.times.back()) sum += f.values.back() * (t - f.times.back());
  return sum;
}

TEST(DriveHistories, ARigidBodyFollowsItsVelocityTableExactly) {
  omp_set_num_threads(1);  // one rigid body: no work to share
  // Knots and the step are binary fractions, so the steps end on the knots exactly: the
  // midpoint velocity integrates each linear piece exactly, and the jumps (two points at one
  // time) fall between steps.
  const fs::path file = scenes::write_text_file(dir() / "body.toml", kHead + R"(
[[grains]]
name = "body"
center = [0.25, -0.5]
radius = 0.5
material = "hard"
rigid = true
velocity = [3.0, 4.0]
[grains.drive]
x = { velocity = [[0.125, 0.0], [0.375, 2.0], [0.375, -1.0], [0.75, 0.5]] }
theta = { velocity = [[0.0, 1.0], [0.5, -3.0]] }
)");
  Model m = build_model(load_scenario(file));
  const RigidDrive& d = m.rigid.drive[0];
  ASSERT_EQ(d.mode[0], DriveMode::velocity);
  ASSERT_EQ(d.mode[1], DriveMode::free);  // unset: free, with its initial velocity
  ASSERT_EQ(d.mode[2], DriveMode::velocity);
  EXPECT_EQ(m.rigid.vx[0], 0.0);  // a driven axis starts at its history's value
  EXPECT_EQ(m.rigid.vy[0], 4.0);
  const PiecewiseLinear vx = d.velocity[0], omega = d.velocity[2];
  Stepper solver(m);
  const double dt = 1.0 / 64.0;
  int knots_checked = 0;
  for (int n = 1; n <= 64; ++n) {
    solver.step(dt);
    const double t = n * dt;
    ASSERT_EQ(solver.state().time, t);
    // At every step end (knots included): position = x0 + integral of the table.
    EXPECT_NEAR(m.rigid.x[0], 0.25 + integral(vx, t), 1e-13) << "t = " << t;
    EXPECT_NEAR(m.rigid.theta[0], integral(omega, t), 1e-13) << "t = " << t;
    EXPECT_NEAR(m.rigid.y[0], -0.5 + 4.0 * t, 1e-13) << "t = " << t;  // free, no force
    for (double knot : {0.125, 0.375, 0.5, 0.75})
      if (t == knot) ++knots_checked;
  }
  EXPECT_EQ(knots_checked, 4);
  // x(1) by hand: 0 until 1/8, ramp to 2 (area 1/4), jump to -1, ramp to 0.5 over 3/8 (area
  // -3/32), then 0.5 for 1/4 (1/8).
  EXPECT_NEAR(m.rigid.x[0], 0.25 + 0.25 - 3.0 / 32.0 + 0.125, 1e-13);
}

TEST(DriveHistories, AForceHistoryActsAsTheForceItSays) {
  omp_set_num_threads(1);
  // A free body under F_y(t) = 2 t from t = 0 (a ramp, c = 0): v_y = t^2 / m, y = t^3 / (3 m);
  // the leapfrog update is second order, so y is within O(dt^2) of it.
  const fs::path file = scenes::write_text_file(dir() / "force.toml", kHead + R"(
[[grains]]
name = "body"
center = [0.0, 0.0]
radius = 0.5
material = "hard"
rigid = true
[grains.drive]
y = { force = [[0.0, 0.0], [10.0, 20.0]] }
)");
  Model m = build_model(load_scenario(file));
  ASSERT_EQ(m.rigid.drive[0].mode[1], DriveMode::load);
  const double mass = m.rigid.mass[0], x0 = m.rigid.x[0];
  Stepper solver(m);
  const double dt = 1.0 / 64.0;
  for (int n = 0; n < 64; ++n)
    solver.step(dt);
  EXPECT_NEAR(m.rigid.vy[0], 1.0 / mass, 0.05 / mass);
  EXPECT_NEAR(m.rigid.y[0], 1.0 / (3.0 * mass), 0.05 / (3.0 * mass));
  EXPECT_NEAR(m.rigid.x[0], x0, 1e-15);
}

std::string series_of(const std::string& name, const std::string& text) {
  const fs::path run = dir() / name;
  fs::create_directories(run);
  scenes::run_scenario_text(run, name + ".toml", text, 1);
  const std::string series = scenes::read_series_text(run / "out" / "cell" / "series.csv").text;
  EXPECT_GT(series.size(), 1000u) << name;
  return series;
}

std::string short_cell() {
  scenes::CohesiveShearCell c;
  c.duration = 1.5;
  c.series_period = 0.05;
  c.field_period = 1.5;
  c.compaction_time = 1.0;
  return scenes::shear_cell_scenario(c);
}

TEST(DriveHistories, BuiltInDrivesAreSpecialCasesOfTheTables) {
  // The shear cell's built-in top x history: 0, then +V/2 over a switch of 1e-3 of the
  // compaction time (scenario/shear_cell.cpp), written as a table; and the bottom's as a
  // table with its -V/2 switch, the y axis as a constant.
  const std::string builtin = series_of("builtin", short_cell());
  const std::string table = series_of("table", short_cell() + R"(
[shear_cell.top_drive]
x = { velocity = [[0.0, 0.0], [1.0, 0.0], [1.001, 0.5]] }
[shear_cell.bottom_drive]
x = { velocity = [[0.0, 0.0], [1.0, 0.0], [1.001, -0.5]] }
y = { velocity = 0.0 }
)");
  EXPECT_TRUE(builtin == table) << "the equivalent tables changed the run";
  // A table that differs (the switch 5% later) changes the series: the comparison can fail.
  const std::string later = series_of("later", short_cell() + R"(
[shear_cell.top_drive]
x = { velocity = [[0.0, 0.0], [1.05, 0.0], [1.051, 0.5]] }
)");
  EXPECT_FALSE(builtin == later);
}

}  // namespace
}  // namespace sg
