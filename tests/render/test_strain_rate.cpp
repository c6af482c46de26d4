// The strain_rate nodal field of fields/*.vtu (io/vtk_writer.h): d|E|/dt over the global rate,
// written by the writer and read back as `render` reads it.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "io/vtk_writer.h"
#include "model/kinematics.h"
#include "render/vtu_reader.h"
#include "scenes/free_grains.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path scratch_file(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("softgrain_test_strain_rate_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
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
  const std::vector<double> rate = point_scalar(mesh, "strain_rate");
  ASSERT_EQ(rate.size(), model.node_count());
  const double expected = (1.0 + r * t) * r / global;  // 4.8
  for (std::size_t j = 0; j < rate.size(); ++j)
    ASSERT_NEAR(rate[j], expected, 1e-6 * expected) << "node " << j;
  // Without a global rate: the same rate in 1/time.
  write_vtu_snapshot(model, file);
  EXPECT_NEAR(point_scalar(read_vtu(file), "strain_rate")[0], expected * global, 1e-6);
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
  for (const double v : point_scalar(read_vtu(file), "strain_rate"))
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
  for (const double v : point_scalar(mesh, "strain_rate"))
    ASSERT_NEAR(v, 0.0, 1e-9);
  for (const double v : point_scalar(mesh, "green_lagrange_norm"))
    ASSERT_NEAR(v, 0.0, 1e-9);
  fs::remove_all(file.parent_path());
}

}  // namespace
}  // namespace sg
