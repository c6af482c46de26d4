// Internal forces of a deformable grain: patch test, objectivity, conservation properties.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "meshfree/body_discretization.h"
#include "model/internal_forces.h"
#include "model/kinematics.h"
#include "scenes/free_grains.h"

namespace sg {
namespace {

// Closed-form compressible neo-Hookean first Piola stress (plane strain), written again here
// independently of material.cpp: P = mu (F - F^-T) + lambda ln J F^-T.
Mat2 neo_hookean_piola(const MaterialParams& m, const Mat2& f) {
  const Mat2 f_inv_t = f.inverse().transpose();
  return m.mu * (f - f_inv_t) + m.lambda * std::log(f.determinant()) * f_inv_t;
}

void zero_forces(Model& model) {
  std::fill(model.nodes.fx.begin(), model.nodes.fx.end(), 0.0);
  std::fill(model.nodes.fy.begin(), model.nodes.fy.end(), 0.0);
}

double max_force(const Model& model) {
  double f = 0.0;
  for (std::size_t i = 0; i < model.node_count(); ++i)
    f = std::max(f, std::hypot(model.nodes.fx[i], model.nodes.fy[i]));
  return f;
}

TEST(PatchTest, HomogeneousDeformationIsReproducedExactly) {
  const double radius = 1.0, h = 0.12;
  for (int gauss_points : {3, 6}) {
    Model model = scenes::single_disc(scenes::elastic_material(), radius, h, gauss_points);
    Mat2 f;
    f << 1.05, 0.03, -0.02, 0.97;
    set_affine_deformation(model, 0, f);
    const Body& body = model.bodies[0];
    const MaterialParams& m = model.materials[0];
    const Mat2 p_exact = neo_hookean_piola(m, f);
    for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
      const Mat2 fg = gauss_deformation_gradient(model, 0, g);
      // MLS reproduces linear fields to round-off (~1e-14 per entry, summed over ~15 nodes).
      ASSERT_NEAR((fg - f).norm(), 0.0, 1e-12) << "Gauss point " << g;
      ASSERT_NEAR((elastic_response(m, fg).first_piola - p_exact).norm(), 0.0,
                  1e-10 * p_exact.norm());
    }
    zero_forces(model);
    add_internal_forces(model);
    // Resultant and moment of the internal forces vanish exactly (round-off): the quantities
    // the dynamics conserves.
    Vec2 resultant(0, 0);
    double moment = 0.0;
    for (int i = body.node_begin; i < body.node_end; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const Vec2 fi(model.nodes.fx[k], model.nodes.fy[k]);
      resultant += fi;
      moment += cross(
          Vec2(model.nodes.ref_x[k] + model.nodes.ux[k], model.nodes.ref_y[k] + model.nodes.uy[k]),
          fi);
    }
    const double force_scale = p_exact.norm() * h;  // a node's share of a boundary traction
    EXPECT_NEAR(resultant.norm(), 0.0, 1e-11 * force_scale);
    EXPECT_NEAR(moment, 0.0, 1e-11 * force_scale * radius);

    // Interior nodes (supports not reaching the contour) carry no internal force in the
    // continuum: f_I = -integral(P grad N_I) = -P times the integral of grad N_I, which is zero.
    // Gauss quadrature of the non-polynomial MLS gradients over background triangles leaves a
    // residual (the "integration constraint" of EFG). Measured with the default supports:
    // 5.6e-2 |P| h with 3 points, 1.3e-2 with 6 points; the bounds leave ~40% margin and
    // require the residual to shrink with the quadrature order, as an integration error does.
    double worst = 0.0;
    for (int i = body.boundary_end; i < body.node_end; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const double r = std::hypot(model.nodes.ref_x[k], model.nodes.ref_y[k]);
      if (r + 3.0 * h > radius) continue;  // its support (radius ~2.3 h) may reach the contour
      worst = std::max(worst, std::hypot(model.nodes.fx[k], model.nodes.fy[k]) / force_scale);
    }
    RecordProperty("interior_force_" + std::to_string(gauss_points), std::to_string(worst));
    std::printf("interior node force / (|P| h) with %d Gauss points: %.3e\n", gauss_points, worst);
    EXPECT_LT(worst, gauss_points == 3 ? 8e-2 : 2e-2);
  }
}

// The patch test of issue #32 on a graded disc: the homogeneous F is reproduced exactly (MLS
// reproduces linear fields whatever the node density), the resultant and moment vanish, and
// the interior nodes' residual force (the EFG integration error) stays of the order of the
// uniform disc's at the same contour spacing. Each node's residual is scaled by its own
// spacing l_I = sqrt(2 V_I / sqrt 3) (V_I its lumped volume: the area of its cell in a
// triangular lattice of spacing l_I), the force a traction of |P| puts on a cell of that size.
// Nodes whose support (radius rho_I) may reach the contour are left out (r + 1.3 rho_I > R,
// as r + 3 h > R for the uniform disc's rho ~ 2.3 h).
struct PatchResidual {
  std::size_t nodes = 0;
  double worst = 0.0;    // largest interior residual / (|P| l_I)
  double f_error = 0.0;  // largest |F_g - F| over the Gauss points
};
PatchResidual graded_patch_residual(double radius, double h, double interior, int gauss_points) {
  Model model;
  const MaterialId material = model.add_material(scenes::elastic_material());
  const BodyDiscretization d =
      discretize_body(make_disc(Vec2(0, 0), radius, h),
                      scenes::graded_discretization(h, interior, gauss_points), "disc");
  model.add_deformable_body("disc", d, material);
  Mat2 f;
  f << 1.05, 0.03, -0.02, 0.97;
  set_affine_deformation(model, 0, f);
  const Body& body = model.bodies[0];
  const MaterialParams& m = model.materials[0];
  const Mat2 p_exact = neo_hookean_piola(m, f);
  PatchResidual out;
  out.nodes = model.node_count();
  for (int g = body.gauss_begin; g < body.gauss_end; ++g)
    out.f_error = std::max(out.f_error, (gauss_deformation_gradient(model, 0, g) - f).norm());
  zero_forces(model);
  add_internal_forces(model);
  Vec2 resultant(0, 0);
  double moment = 0.0;
  for (int i = body.node_begin; i < body.node_end; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2 fi(model.nodes.fx[k], model.nodes.fy[k]);
    resultant += fi;
    moment += cross(
        Vec2(model.nodes.ref_x[k] + model.nodes.ux[k], model.nodes.ref_y[k] + model.nodes.uy[k]),
        fi);
  }
  const double force_scale = p_exact.norm() * h;
  EXPECT_NEAR(resultant.norm(), 0.0, 1e-11 * force_scale);
  EXPECT_NEAR(moment, 0.0, 1e-11 * force_scale * radius);
  for (int i = body.boundary_end; i < body.node_end; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double r = std::hypot(model.nodes.ref_x[k], model.nodes.ref_y[k]);
    if (r + 1.3 * d.support_radius[k] > radius) continue;
    const double spacing = std::sqrt(2.0 * d.lumped_volume[k] / std::sqrt(3.0));
    out.worst = std::max(
        out.worst, std::hypot(model.nodes.fx[k], model.nodes.fy[k]) / (p_exact.norm() * spacing));
  }
  return out;
}

// Graded: contour spacing 0.12 (the uniform patch test's), interior 0.36 (ratio 3, paper 003's).
// Measured (3 / 6 Gauss points): graded 149 nodes, residual 5.8e-2 / 4.2e-2; uniform 271 nodes,
// 5.5e-2 / 1.2e-2 (same scaling). Grading costs nothing with 3 points; with 6 the residual
// shrinks less than the uniform disc's (the coarse cells' Gauss points sit in larger supports
// whose gradients vary more over a cell). The bounds leave ~30% above the graded values and
// still require the residual to shrink with the quadrature order.
TEST(PatchTest, GradedDiscReproducesHomogeneousDeformation) {
  const double radius = 1.0, h = 0.12, interior = 0.36;
  double three_point_residual = 0.0;
  for (int gauss_points : {3, 6}) {
    const PatchResidual graded = graded_patch_residual(radius, h, interior, gauss_points);
    const PatchResidual uniform = graded_patch_residual(radius, h, 0.0, gauss_points);
    std::printf(
        "patch test, %d Gauss points: graded %zu nodes, residual %.3e, F error %.1e; "
        "uniform %zu nodes, residual %.3e\n",
        gauss_points, graded.nodes, graded.worst, graded.f_error, uniform.nodes, uniform.worst);
    RecordProperty("graded_interior_force_" + std::to_string(gauss_points),
                   std::to_string(graded.worst));
    EXPECT_LT(graded.f_error, 1e-12);
    EXPECT_LT(graded.nodes, uniform.nodes);
    EXPECT_LT(graded.worst, gauss_points == 3 ? 7.5e-2 : 5.5e-2);
    if (gauss_points == 3)
      three_point_residual = graded.worst;
    else
      EXPECT_LT(graded.worst, three_point_residual);
  }
}

TEST(Objectivity, RigidRotationOf90DegreesGivesNoStressNoForce) {
  Model model =
      scenes::single_disc(scenes::elastic_material(MaterialLaw::neo_hookean, 0.05), 0.5, 0.08);
  set_affine_deformation(model, 0, rotation(std::numbers::pi / 2));
  // A spinning velocity field on top: the damping must not see it either.
  set_rigid_velocity(model, 0, Vec2(0.3, -0.2), 2.0);
  zero_forces(model);
  const InternalForceResult r = add_internal_forces(model);
  const MaterialParams& m = model.materials[0];
  // Scale: the force a 1% strain would give a node, lambda * 0.01 * h.
  const double scale = (m.lambda + 2 * m.mu) * 0.01 * 0.08;
  EXPECT_LT(max_force(model), 1e-10 * scale);
  EXPECT_NEAR(r.elastic_energy, 0.0, 1e-12);
  EXPECT_NEAR(r.damping_power, 0.0, 1e-12);
  for (int g = 0; g < model.bodies[0].gauss_end; ++g) {
    const Mat2 f = gauss_deformation_gradient(model, 0, g);
    EXPECT_NEAR(cauchy_stress(m, f).von_mises(), 0.0, 1e-10 * m.mu);
  }
}

TEST(Objectivity, ReferenceStiffnessDampingWouldDampTheSameRotation) {
  // Contrast, so the test above can fail for the right reason: the non-objective alpha K0 v
  // sees a strain rate sym(grad0 v) != 0 once the grain has turned by 90 degrees.
  Model model = scenes::single_disc(scenes::elastic_material(), 0.5, 0.08);
  set_affine_deformation(model, 0, rotation(std::numbers::pi / 2));
  set_rigid_velocity(model, 0, Vec2(0, 0), 2.0);
  double worst = 0.0;
  for (int g = 0; g < model.bodies[0].gauss_end; ++g) {
    Mat2 f_rate = Mat2::Zero();
    const ShapeRows& rows = model.gauss_rows;
    for (auto k = rows.offset[static_cast<std::size_t>(g)];
         k < rows.offset[static_cast<std::size_t>(g) + 1]; ++k) {
      const auto j = static_cast<std::size_t>(rows.node[static_cast<std::size_t>(k)]);
      f_rate += Vec2(model.nodes.vx[j], model.nodes.vy[j]) *
                Vec2(rows.dndx[static_cast<std::size_t>(k)], rows.dndy[static_cast<std::size_t>(k)])
                    .transpose();
    }
    const Mat2 small_strain_rate = 0.5 * (f_rate + f_rate.transpose());
    worst = std::max(worst, small_strain_rate.norm());
  }
  EXPECT_GT(worst, 1.0);  // |sym(W R)| = sqrt(2) * omega for a 90 degree turn
}

TEST(BadInput, ContourErrorsNameTheBody) {
  Model model;
  const MaterialId m = model.add_material(scenes::elastic_material());
  Polygon clockwise = make_disc(Vec2(0, 0), 1.0, 0.1);
  std::reverse(clockwise.begin(), clockwise.end());
  try {
    model.add_deformable_body("grain_7", clockwise, m, scenes::discretization(0.1));
    FAIL() << "clockwise contour accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("grain_7"), std::string::npos) << e.what();
  }
  const Polygon bow_tie = {Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)};
  EXPECT_THROW(model.add_deformable_body("bow", bow_tie, m, scenes::discretization(0.1)), Error);
  try {
    model.add_deformable_body("small", make_disc(Vec2(0, 0), 0.2, 0.05), m,
                              scenes::discretization(0.5));
    FAIL() << "spacing larger than the body accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("small"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(model.bodies.empty());
}

TEST(BadInput, MaterialErrorsNameTheMaterial) {
  Model model;
  MaterialDef bad = scenes::elastic_material();
  bad.name = "rubber";
  bad.poisson = 0.5;
  try {
    model.add_material(bad);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rubber"), std::string::npos);
  }
  bad.poisson = 0.3;
  bad.young = -1;
  EXPECT_THROW(model.add_material(bad), Error);
  EXPECT_TRUE(model.materials.empty());
}

TEST(Mass, LumpedMassesArePositiveAndSumToTheBodyMass) {
  const double radius = 0.5, h = 0.07;
  Model model = scenes::single_disc(scenes::elastic_material(), radius, h);
  for (double m : model.nodes.mass)
    EXPECT_GT(m, 0.0);
  // Partition of unity: sum of lumped masses = rho * (polygon area), to round-off.
  EXPECT_NEAR(total_mass(model), model.bodies[0].reference_area, 1e-12);
  const Polygon contour = make_disc(Vec2(0, 0), radius, h);
  EXPECT_NEAR(model.bodies[0].reference_area, signed_area(contour), 1e-12);
}

}  // namespace
}  // namespace sg
