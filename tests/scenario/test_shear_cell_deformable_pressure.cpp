// The shear cell with deformable first bodies under pressure loading ([shear_cell]
// first_bodies = "deformable", normal_load = "pressure"): the top strip's back face moves as one
// in y under the servo load F = -p L and -c v_y (a NodeDrive in DriveMode::load) while it
// slides at +V/2. The time-averaged normal stress the layer exerts on the top strip matches p,
// the energy ledger closes with the load's work and the servo dissipation, and the run is
// bitwise the same on 1 and 2 threads and after a stop and resume.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/scenario_run.h"
#include "scenes/series_text.h"
#include "scenes/shear_cell_scenario.h"
#include "solver/stable_time_step.h"
#include "solver/stepper.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

constexpr double kLength = 8.0, kPressure = 0.5, kCompaction = 1.2;

// L = 8, 14 soft cohesive grains (c = 0.1, k_n = 2000), deformable first bodies 1 thick
// (E = 50, alpha = 0.02, mass 8 each), p = 0.5 (p L = 4, p / E = 0.05) ramped over 1.2, then
// V = 1. The servo damping is given: the critical estimate for the strip's mass (c = 35)
// assumes the stiffness of a solid slab, which this loose two-grain layer is far from, and
// lowers the top onto it at F / c = 0.11 only; c = 2 lets the top settle by t ~ 4,
// and keeps the servo's bias c v (v the vertical drift of the top while the layer dilates and
// compacts) small.
std::string cell_scenario(const std::string& name, double duration) {
  scenes::CohesiveShearCell c;
  c.name = name;
  c.duration = duration;
  c.series_period = 0.02;
  c.field_period = duration;
  c.checkpoint_period = 0.5 * duration;
  c.node_spacing = 0.25;
  c.length = kLength;
  c.grains = 14;
  c.roughness_rms = 0.15;
  c.compaction_time = kCompaction;
  c.seed = 2;
  std::string text = scenes::shear_cell_scenario(c);
  text = scenes::replace_once(text, "name = \"first_body\"\nyoung = 1000.0\n",
                              "name = \"first_body\"\nyoung = 50.0\npoisson = 0.3\n"
                              "damping = 0.02\n");
  std::ostringstream keys;
  keys << "[shear_cell]\nfirst_bodies = \"deformable\"\nfirst_body_thickness = 1.0\n"
       << "normal_load = \"pressure\"\npressure = " << kPressure << "\nservo_damping = 2.0\n";
  return scenes::replace_once(text, "[shear_cell]\n", keys.str());
}

BodyId body_named(const Model& model, const std::string& name) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].name == name) return static_cast<BodyId>(b);
  ADD_FAILURE() << "no body " << name;
  return 0;
}

// The force the contacts exert on `body` at the last evaluation: f = l (p_n n + p_t t) on each
// slave point, -f on the master segment (contact/contact_system.h).
Vec2 contact_force_on(const ContactSystem& contacts, BodyId body) {
  Vec2 sum(0, 0);
  for (const ContactRecord& r : contacts.records()) {
    const Vec2 f =
        r.length * (r.traction.normal * r.normal + r.traction.tangential * perp(r.normal));
    if (r.slave_body == body) sum += f;
    if (r.master_body == body) sum -= f;
  }
  return sum;
}

// The servo and energy tests for deformable first bodies: after the transient (second
// half of 40 time units) the mean normal force the layer exerts on the top strip through the
// contacts, over L, is p within 2% (measured -0.11%), and so is the load cell's (series.csv
// top_fy: measured -0.29%); the ledger closes within 1% of the external work (measured
// 0.03%). About 8 s on one unloaded core.
TEST(DeformablePressure, TopStripCarriesThePressureAndTheLedgerCloses) {
  const fs::path dir = scenes::process_temp_dir("strip_pressure");
  const ScenarioDef s =
      load_scenario(scenes::write_text_file(dir / "cell.toml", cell_scenario("cell", 40.0)));
  ASSERT_TRUE(s.shear_cell);
  EXPECT_EQ(s.shear_cell->first_bodies, FirstBodyKind::deformable);
  EXPECT_EQ(s.shear_cell->normal_load, NormalLoad::pressure);
  Model model = build_model(s);
  const BodyId top = body_named(model, "top");
  const Body& top_body = model.body(top);
  ASSERT_GE(top_body.node_drive, 0);
  const NodeDrive& drive = model.node_drives[static_cast<std::size_t>(top_body.node_drive)];
  EXPECT_EQ(drive.mode[0], DriveMode::velocity);
  EXPECT_EQ(drive.mode[1], DriveMode::load);
  EXPECT_DOUBLE_EQ(drive.load[1](100.0), -kPressure * kLength);
  EXPECT_DOUBLE_EQ(drive.load_damping[1], 2.0);
  const NodeDrive& bottom_drive = model.node_drives[static_cast<std::size_t>(
      model.body(body_named(model, "bottom")).node_drive)];
  EXPECT_EQ(bottom_drive.mode[1], DriveMode::velocity);  // held: only the top is loaded

  {
    // Without servo_damping: the critical estimate for the top's mass rho L thickness = 8, the
    // layer's packed height H (the back face is flat, 1 above the top's mean surface line; the
    // bottom's is at 0), k_n = 2000, h = 0.25 and grain size 1.
    std::string text = cell_scenario("cell", 20.0);
    text = scenes::replace_once(text, "servo_damping = 2.0\n", "");
    const Model by_default =
        build_model(load_scenario(scenes::write_text_file(dir / "default.toml", text)));
    const NodeDrive& d =
        by_default.node_drives[static_cast<std::size_t>(by_default.body(top).node_drive)];
    const double height = by_default.nodes.ref_y[static_cast<std::size_t>(d.nodes.front())] - 1.0;
    EXPECT_DOUBLE_EQ(d.load_damping[1],
                     servo_damping_estimate(10.0, 0.45, height, kLength, 2000.0, 0.25, 1.0, 8.0));
    std::printf("default servo damping %.4g (H = %.4g)\n", d.load_damping[1], height);
  }

  ContactSystem contacts(model, contact_law_table(s), contact_settings(s));
  const double dt =
      estimate_stable_time_step(model, s.time_step_safety, contacts.max_stiffness()).dt;
  Stepper solver(model, &contacts);
  const double window_start = 0.5 * s.duration;
  double contact_sum = 0.0, cell_sum = 0.0;  // layer on the top; the load cell -R_y (no gravity)
  long samples = 0;
  double top_y_start = 0.0;
  auto back_face_y = [&] {
    double y = 0.0;
    for (int i : drive.nodes)
      y += model.nodes.ref_y[static_cast<std::size_t>(i)] +
           model.nodes.uy[static_cast<std::size_t>(i)];
    return y / static_cast<double>(drive.nodes.size());
  };
  // The strip's vertical momentum: the layer's mean force on it differs from the load cell's
  // by its change over the window divided by the window's duration. The strip (mass 8) rides
  // the layer's dilation and compaction at up to ~0.1: hence a long window.
  auto strip_momentum = [&] {
    double p = 0.0;
    for (int i = top_body.node_begin; i < top_body.node_end; ++i)
      p += model.nodes.mass[static_cast<std::size_t>(i)] *
           model.nodes.vy[static_cast<std::size_t>(i)];
    return p;
  };
  double momentum_start = 0.0;
  while (solver.state().time < s.duration) {
    const double t = solver.state().time;
    if (samples == 0 && t >= window_start) {
      top_y_start = back_face_y();
      momentum_start = strip_momentum();
    }
    solver.step(dt);
    if (t >= window_start) {  // the forces of this step are those of the configuration at t
      contact_sum += contact_force_on(contacts, top).y();
      cell_sum += -drive.reaction.y();
      ++samples;
    }
  }
  ASSERT_GT(samples, 5000);
  const double layer_pressure = contact_sum / static_cast<double>(samples) / kLength;
  const double cell_pressure = cell_sum / static_cast<double>(samples) / kLength;
  const double inertia = (strip_momentum() - momentum_start) / (static_cast<double>(samples) * dt);
  // The servo's expected bias: c times the mean drift of the back face over the window (its
  // driven nodes all move by dt v_n+1/2 per step: the mean of v_n+1/2 over the samples).
  const double drift = (back_face_y() - top_y_start) / (static_cast<double>(samples) * dt);
  std::printf(
      "layer on the top strip: mean pressure %.5g (target %g, %+.2f%%); load cell "
      "%.5g; servo bias c v = %.3g, strip inertia M dv/dt = %.3g per length\n",
      layer_pressure, kPressure, 100.0 * (layer_pressure / kPressure - 1.0), cell_pressure,
      2.0 * drift / kLength, inertia / kLength);
  EXPECT_NEAR(layer_pressure, kPressure, 0.02 * kPressure);
  EXPECT_NEAR(cell_pressure, kPressure, 0.02 * kPressure);
  // The load cell reads -(F - c v_n+1/2) at every step, up to round-off: its mean is p plus
  // the bias.
  EXPECT_NEAR(cell_pressure, kPressure + 2.0 * drift / kLength, 1e-6 * kPressure);

  const EnergyLedger& e = solver.state().energy;
  std::printf("external work %.6g, servo dissipated %.6g, residual %.3g (%.3f%%)\n",
              e.external_work, e.servo_dissipated, e.residual(),
              100.0 * e.residual() / e.external_work);
  EXPECT_GT(e.servo_dissipated, 0.0);
  EXPECT_GT(e.external_work, 1.0);
  EXPECT_LT(std::abs(e.residual()), 0.01 * e.external_work);
  fs::remove_all(dir);
}

RunSummary run(const fs::path& dir, int threads, long stop_after = -1, bool resume = false) {
  return scenes::run_scenario_text(dir, "cell.toml", cell_scenario("cell", 4.0), threads,
                                   stop_after, resume);
}

// Through `softgrain run`'s engine (adaptive step, checkpoints): series.csv is byte-identical
// on 1 and 2 threads, and after a stop past the checkpoint at t = 2 (the top resting on the
// layer under the servo, sliding) and a resume.
TEST(DeformablePressure, RunIsThreadIndependentAndResumesBitwise) {
  const fs::path one_dir = scenes::process_temp_dir("strip_pressure_1");
  const RunSummary whole = run(one_dir, 1);
  const scenes::SeriesText one = scenes::read_series_text(one_dir / "out" / "cell" / "series.csv");
  ASSERT_GE(one.rows.size(), 200u);  // t = 0, 0.02, ... < 4
  // The servo is at work by the checkpoint: the top's load cell carries part of p L.
  double servo = 0.0, top_fy = 0.0;
  for (const auto& row : one.rows)
    if (std::abs(row[one.column("time")] - 2.0) < 0.01) {
      servo = row[one.column("servo_dissipation")];
      top_fy = row[one.column("top_fy")];
    }
  EXPECT_GT(servo, 0.0);
  EXPECT_GT(top_fy, 0.2 * kPressure * kLength);

  const fs::path two_dir = scenes::process_temp_dir("strip_pressure_2");
  run(two_dir, 2);
  const scenes::SeriesText two = scenes::read_series_text(two_dir / "out" / "cell" / "series.csv");
  EXPECT_TRUE(one.text == two.text) << "series.csv differs between 1 and 2 threads";

  const fs::path resumed_dir = scenes::process_temp_dir("strip_pressure_resumed");
  const RunSummary stopped = run(resumed_dir, 2, (whole.steps * 4) / 5);
  EXPECT_FALSE(stopped.completed);
  const RunSummary resumed = run(resumed_dir, 1, -1, true);
  EXPECT_GT(resumed.resumed_from_step, 0);
  const scenes::SeriesText again =
      scenes::read_series_text(resumed_dir / "out" / "cell" / "series.csv");
  EXPECT_TRUE(one.text == again.text) << "series.csv differs after a stop and resume";
  for (const fs::path& d : {one_dir, two_dir, resumed_dir})
    fs::remove_all(d);
}

}  // namespace
}  // namespace sg
