// The strain-rate nodal fields of fields/*.vtu (io/vtk_writer.h), written by the writer and
// read back as `render` reads it: strain_rate_instant d|E|/dt over the global rate, and
// strain_rate the increment of |E| over the output interval, written by the run's snapshot
// output (run/snapshot_output.h) from the last committed snapshot, through rollbacks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>

#include "core/error.h"
#include "io/vtk_writer.h"
#include "model/kinematics.h"
#include "render/vtu_reader.h"
#include "run/simulation.h"
#include "run/snapshot_output.h"
#include "scenario/scenario.h"
#include "scenes/free_grains.h"
#include "scenes/scenario_files.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path scratch_file(const std::string& name) {
  return scenes::process_temp_dir("strain_rate") / name;
}

// The grain at time t of a homogeneous deformation x = F(t) X, velocity parameters
// v_J = F'(t) X_J (exact: MLS reproduces linear fields, so every node sees F and F').
void set_homogeneous_motion(Model& model, const Mat2& F, const Mat2& F_rate) {
  set_affine_deformation(model, 0, F);
  for (std::size_t j = 0; j < model.node_count(); ++j) {
    const Vec2 v = F_rate * Vec2(model.nodes.ref_x[j], model.nodes.ref_y[j]);
    model.nodes.vx[j] = v.x();
    model.nodes.vy[j] = v.y();
  }
}

// Uniaxial stretch at a steady rate r: F = diag(1 + r t, 1), E_xx = ((1 + r t)^2 - 1) / 2 the
// only component, so |E| = E_xx and d|E|/dt = (1 + r t) r; the field is that over V/D.
TEST(StrainRateField, SteadyStretchGivesTheAnalyticNormalizedRateAtEveryNode) {
  Model model = scenes::single_disc(scenes::elastic_material(), 1.0, 0.15);
  const double r = 0.4, t = 0.5, global = 0.25;  // global = V/D
  Mat2 F, F_rate;
  F << 1.0 + r * t, 0.0, 0.0, 1.0;
  F_rate << r, 0.0, 0.0, 0.0;
  set_homogeneous_motion(model, F, F_rate);
  const fs::path file = scratch_file("stretch.vtu");
  write_vtu_snapshot(model, file, global);
  const VtuMesh mesh = read_vtu(file);
  const std::vector<double> rate = point_scalar(mesh, "strain_rate_instant");
  ASSERT_EQ(rate.size(), model.node_count());
  const double expected = (1.0 + r * t) * r / global;  // 4.8
  for (std::size_t j = 0; j < rate.size(); ++j)
    ASSERT_NEAR(rate[j], expected, 1e-6 * expected) << "node " << j;
  // Without a previous snapshot strain_rate holds the instantaneous rate too.
  EXPECT_EQ(point_scalar(mesh, "strain_rate"), rate);
  // Without a global rate: the same rate in 1/time.
  write_vtu_snapshot(model, file);
  EXPECT_NEAR(point_scalar(read_vtu(file), "strain_rate_instant")[0], expected * global, 1e-6);
  // Pure shear at the same instant is not a stretch: F = [[1, g t], [0, 1]], F' = [[0, g], 0]:
  // E = [[0, g t / 2], [g t / 2, (g t)^2 / 2]], d|E|/dt from the closed form of |E|.
  const double g = 0.6;
  F << 1.0, g * t, 0.0, 1.0;
  F_rate << 0.0, g, 0.0, 0.0;
  set_homogeneous_motion(model, F, F_rate);
  write_vtu_snapshot(model, file, global);
  const double s = g * t;  // |E|^2 = s^2 / 2 + s^4 / 4; d|E|/dt = g (s + s^3) / (2 |E|)
  const double norm = std::sqrt(0.5 * s * s + 0.25 * s * s * s * s);
  const double shear_expected = g * (s + s * s * s) / (2.0 * norm) / global;
  for (const double v : point_scalar(read_vtu(file), "strain_rate_instant"))
    ASSERT_NEAR(v, shear_expected, 1e-6 * shear_expected);
  fs::remove_all(file.parent_path());
}

// A rigid rotation at any angle and spin: no strain, no strain rate, at every node.
TEST(StrainRateField, RigidlyRotatingGrainGivesZero) {
  Model model = scenes::single_disc(scenes::elastic_material(), 1.0, 0.15);
  const double theta = 0.7, omega = 3.0;
  const Mat2 R = rotation(theta);
  Mat2 J;
  J << 0.0, -1.0, 1.0, 0.0;
  set_homogeneous_motion(model, R, omega * J * R);  // d/dt R(theta) = omega J R
  const fs::path file = scratch_file("rotation.vtu");
  write_vtu_snapshot(model, file, 0.25);
  const VtuMesh mesh = read_vtu(file);
  // The test would see a spin mistaken for a stretch: |v| ~ omega at r = 1, over V/D 0.25.
  for (const char* field : {"strain_rate", "strain_rate_instant"})
    for (const double v : point_scalar(mesh, field))
      ASSERT_NEAR(v, 0.0, 1e-9) << field;
  for (const double v : point_scalar(mesh, "green_lagrange_norm"))
    ASSERT_NEAR(v, 0.0, 1e-9);
  fs::remove_all(file.parent_path());
}

// F(t) = diag(1 + r t, 1): |E| = E_xx = ((1 + r t)^2 - 1) / 2, so over [t1, t2]
//   (|E(t2)| - |E(t1)|) / (t2 - t1) = r (1 + r (t1 + t2) / 2),
// the rate at the interval's midpoint, where the instantaneous rate at t2 is r (1 + r t2).
Mat2 stretch(double r, double t) {
  Mat2 F;
  F << 1.0 + r * t, 0.0, 0.0, 1.0;
  return F;
}
Mat2 stretch_rate(double r) {
  Mat2 F_rate;
  F_rate << r, 0.0, 0.0, 0.0;
  return F_rate;
}

TEST(StrainRateField, IntervalIncrementOfASteadyStretchOverTheGlobalRate) {
  Model model = scenes::single_disc(scenes::elastic_material(), 1.0, 0.15);
  const double r = 0.4, t1 = 0.2, t2 = 0.5, global = 0.25;
  set_homogeneous_motion(model, stretch(r, t1), stretch_rate(r));
  const std::vector<double> before = nodal_strain_norms(model);
  set_homogeneous_motion(model, stretch(r, t2), stretch_rate(r));
  const fs::path file = scratch_file("interval.vtu");
  write_vtu_snapshot(model, file, global, StrainInterval{before, t2 - t1});
  const VtuMesh mesh = read_vtu(file);
  const double expected = r * (1.0 + 0.5 * r * (t1 + t2)) / global;  // 1.824
  const double instant = r * (1.0 + r * t2) / global;                // 1.92: 5% apart
  const std::vector<double> rate = point_scalar(mesh, "strain_rate");
  ASSERT_EQ(rate.size(), model.node_count());
  for (std::size_t j = 0; j < rate.size(); ++j) {
    ASSERT_NEAR(rate[j], expected, 1e-9 * expected) << "node " << j;
    ASSERT_NEAR(point_scalar(mesh, "strain_rate_instant")[j], instant, 1e-9 * instant);
  }
  // A previous snapshot of another model is refused, not misread.
  EXPECT_THROW(
      write_vtu_snapshot(model, file, global, StrainInterval{std::span(before).first(3), t2 - t1}),
      Error);
  fs::remove_all(file.parent_path());
}

// A one-grain run observed by its snapshot output, the grain's state set by hand at each
// instant: the files the run writes, with the bookkeeping of the run loop.
class ObservedGrain {
 public:
  ObservedGrain() {
    const fs::path dir = scenes::process_temp_dir("strain_rate_run");
    scenario_ = load_scenario(scenes::write_text_file(dir / "grain.toml", R"(name = "grain"
[time]
duration = 1.0
[output]
series_period = 0.1
field_period = 0.1
[discretization]
node_spacing = 0.15
[[materials]]
name = "soft"
young = 10.0
poisson = 0.3
[[grains]]
center = [0.0, 0.0]
radius = 0.5
material = "soft"
)"));
    folder_.dir = dir / "out";
    fs::create_directories(folder_.dir / "fields");
    fs::create_directories(folder_.dir / "grains");
    simulation_ = std::make_unique<Simulation>(scenario_);
    context_ =
        std::make_unique<RunContext>(RunContext{scenario_, folder_, *simulation_, loop_, 1e-9});
    output_ = std::make_unique<SnapshotOutput>(*context_);
    output_->begin(false);
  }
  Model& model() { return simulation_->model; }
  // The loop at (t, step): prepare, then commit unless the step was rolled back.
  void instant(double t, long step, bool committed = true) {
    output_->prepare(RunInstant{t, step});
    if (committed) output_->commit(StepTaken{RunInstant{t, step}, 0.01, true});
  }
  std::vector<double> field(int snapshot, const char* name) const {
    char file[32];
    std::snprintf(file, sizeof file, "%06d.vtu", snapshot);
    return point_scalar(read_vtu(folder_.dir / "fields" / file), name);
  }

 private:
  ScenarioDef scenario_;
  RunFolder folder_;
  RunLoopState loop_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<RunContext> context_;
  std::unique_ptr<SnapshotOutput> output_;
};

// Snapshots at t1, t2, t3 of a grain stretched at the steady rate r, then released to the
// t1 stretch; between them a rolled-back visit of t2 in another state (as after a rejected
// step). strain_rate (1/time here: no shear cell) is the closed-form increment at every
// node, measured from the committed snapshots only; |E| falling gives a positive rate.
TEST(StrainRateField, RunSnapshotsHoldTheIntervalIncrementThroughARollback) {
  ObservedGrain run;
  const double r = 0.4, t1 = 0.2, t2 = 0.5, t3 = 0.7;
  set_homogeneous_motion(run.model(), stretch(r, t1), stretch_rate(r));
  run.instant(t1, 0);
  set_homogeneous_motion(run.model(), stretch(3.0 * r, t2), stretch_rate(3.0 * r));
  run.instant(t2, 1, false);  // rolled back: taken again below, from the same start
  set_homogeneous_motion(run.model(), stretch(r, t2), stretch_rate(r));
  run.instant(t2, 1);
  set_homogeneous_motion(run.model(), stretch(r, t1), -stretch_rate(r));
  run.instant(t3, 2);
  const double first = r * (1.0 + r * t1);  // no previous snapshot: the instant
  const double second = r * (1.0 + 0.5 * r * (t1 + t2));
  const double e1 = 0.5 * (std::pow(1.0 + r * t1, 2) - 1.0);
  const double e2 = 0.5 * (std::pow(1.0 + r * t2, 2) - 1.0);
  const double third = (e2 - e1) / (t3 - t2);  // |E| fell back by e2 - e1
  const std::vector<double> rate0 = run.field(0, "strain_rate");
  const std::vector<double> rate1 = run.field(1, "strain_rate");
  const std::vector<double> rate2 = run.field(2, "strain_rate");
  ASSERT_EQ(rate1.size(), run.model().node_count());
  for (std::size_t j = 0; j < rate1.size(); ++j) {
    ASSERT_NEAR(rate0[j], first, 1e-9 * first) << "node " << j;
    ASSERT_NEAR(rate1[j], second, 1e-9 * second) << "node " << j;
    ASSERT_NEAR(rate2[j], third, 1e-9 * third) << "node " << j;
  }
  // The instantaneous field keeps its sign: the grain shortens at t3.
  EXPECT_LT(run.field(2, "strain_rate_instant")[0], 0.0);
}

// A grain turning rigidly between snapshots (any angle, any spin) has no strain and no
// strain increment at any node.
TEST(StrainRateField, RunSnapshotsOfARigidlyRotatingGrainAreZero) {
  ObservedGrain run;
  const double omega = 3.0;
  Mat2 J;
  J << 0.0, -1.0, 1.0, 0.0;
  for (int k = 0; k < 3; ++k) {
    const double t = 0.2 * (k + 1), theta = omega * t;
    set_homogeneous_motion(run.model(), rotation(theta), omega * J * rotation(theta));
    run.instant(t, k);
  }
  for (int k = 0; k < 3; ++k)
    for (const char* field : {"strain_rate", "strain_rate_instant"})
      for (const double v : run.field(k, field))
        ASSERT_NEAR(v, 0.0, 1e-9) << field << " at snapshot " << k;
}

}  // namespace
}  // namespace sg
