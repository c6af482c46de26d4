// The F-bar formulation (material.h VolumetricFormulation::fbar, model/fbar_kernel_impl.h):
// patch test, objectivity, forces the exact gradient of the F-bar energy (patch coupling
// included), its patches, and the kernel's versions and thread counts giving the same bits.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "model/internal_forces.h"
#include "model/kinematics.h"
#include "scenes/free_grains.h"
#include "scenes/random_motion.h"

namespace sg {
namespace {

MaterialDef fbar_material(double poisson = 0.495, double damping = 0.0) {
  MaterialDef m = scenes::elastic_material(MaterialLaw::neo_hookean, damping, poisson);
  m.volumetric = VolumetricFormulation::fbar;
  return m;
}

Model disc_of(const MaterialDef& material, int gauss_points = 3, double h = 0.12) {
  return scenes::single_disc(material, 0.5, h, gauss_points);
}

// A non-homogeneous displacement of a few percent (bending, shear and a bulge) and a rough
// part (strains of about 2% from node to node), which makes det F vary inside every patch.
void deform(Model& model) {
  NodeState& n = model.nodes;
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double x = n.ref_x[i], y = n.ref_y[i];
    n.ux[i] = 0.04 * x * y + 0.03 * y - 0.02 * x + 0.05 * x * x + 0.003 * u(random);
    n.uy[i] = -0.06 * x * x + 0.02 * y * y + 0.01 * x - 0.03 * y + 0.003 * u(random);
  }
}

struct Forces {
  std::vector<double> fx, fy;
  double energy = 0.0;
};

Forces forces(const Model& model, const ForceKernel* kernel = nullptr) {
  const NodeState& n = model.nodes;
  Forces f{std::vector<double>(n.size(), 0.0), std::vector<double>(n.size(), 0.0)};
  const BodyForceResult r =
      add_body_internal_forces(model, 0, n.ux.data(), n.uy.data(), n.vx.data(), n.vy.data(),
                               f.fx.data(), f.fy.data(), false, nullptr, nullptr, kernel);
  EXPECT_EQ(r.bad_gauss_point, -1);
  f.energy = r.elastic_energy;
  return f;
}

double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (double x : a)
    m = std::max(m, std::abs(x));
  return m;
}

// The F-bar energy written again here from its definition, with Eigen and the scalar law:
// sum_g w_g W(F_bar_g), F_bar_g = (J_bar / J_g)^(1/2) F_g, J_bar the weighted mean of J over
// the point's patch.
double fbar_energy(const Model& model) {
  const Body& body = model.bodies[0];
  const MaterialParams& m = model.materials[0];
  std::vector<double> weight(static_cast<std::size_t>(body.patch_count), 0.0);
  std::vector<double> j_sum(weight.size(), 0.0);
  std::vector<Mat2> f;
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    f.push_back(gauss_deformation_gradient(model, 0, g));
    const auto p = static_cast<std::size_t>(model.gauss_patch[static_cast<std::size_t>(g)]);
    weight[p] += model.gauss_weight[static_cast<std::size_t>(g)];
    j_sum[p] += model.gauss_weight[static_cast<std::size_t>(g)] * f.back().determinant();
  }
  double energy = 0.0;
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    const auto k = static_cast<std::size_t>(g);
    const auto p = static_cast<std::size_t>(model.gauss_patch[k]);
    const Mat2& fg = f[static_cast<std::size_t>(g - body.gauss_begin)];
    const Mat2 f_bar = std::sqrt(j_sum[p] / weight[p] / fg.determinant()) * fg;
    energy += model.gauss_weight[k] * elastic_response(m, f_bar).energy_density;
  }
  return energy;
}

TEST(FBar, PatchesAreTheGaussPointsNearestToEachNode) {
  for (int gauss_points : {3, 6}) {
    const Model model = disc_of(fbar_material(), gauss_points);
    const Body& body = model.bodies[0];
    // Every node is a vertex of some triangle and the nearest node of one of its points.
    EXPECT_EQ(body.patch_count, body.node_count()) << gauss_points;
    std::vector<int> size(static_cast<std::size_t>(body.patch_count), 0);
    for (int g = body.gauss_begin; g < body.gauss_end; ++g)
      ++size[static_cast<std::size_t>(model.gauss_patch[static_cast<std::size_t>(g)])];
    // With 3 points per triangle a patch is one point per triangle around the node (a median
    // dual cell): 6 on average in a triangulation of the plane.
    const double mean = static_cast<double>(body.gauss_end - body.gauss_begin) / body.patch_count;
    std::printf("%d Gauss points: %d patches of %.2f points on average (%d to %d)\n", gauss_points,
                body.patch_count, mean, *std::min_element(size.begin(), size.end()),
                *std::max_element(size.begin(), size.end()));
    EXPECT_GT(mean, gauss_points == 3 ? 4.0 : 8.0);
    EXPECT_GE(*std::min_element(size.begin(), size.end()), 1);
  }
}

TEST(FBar, HomogeneousDeformationIsReproducedAndInteriorForcesVanish) {
  for (int gauss_points : {3, 6}) {
    MaterialDef standard_def = fbar_material(0.45);
    standard_def.volumetric = VolumetricFormulation::standard;
    Model fbar = disc_of(fbar_material(0.45), gauss_points);
    Model standard = disc_of(standard_def, gauss_points);
    Mat2 f;
    f << 1.05, 0.03, -0.02, 0.93;
    set_affine_deformation(fbar, 0, f);
    set_affine_deformation(standard, 0, f);
    const Forces a = forces(fbar), b = forces(standard);
    // A homogeneous F has J_bar = J in every patch: F_bar = F and the coupling term vanishes,
    // so the forces and the energy are the standard ones to round-off.
    const double scale = max_abs(b.fx) + max_abs(b.fy);
    for (std::size_t i = 0; i < a.fx.size(); ++i) {
      ASSERT_NEAR(a.fx[i], b.fx[i], 1e-12 * scale) << i;
      ASSERT_NEAR(a.fy[i], b.fy[i], 1e-12 * scale) << i;
    }
    EXPECT_NEAR(a.energy, b.energy, 1e-13 * b.energy);
    // Interior nodes carry no force in the continuum; the residual is the EFG integration
    // error of the standard patch test (test_internal_forces.cpp: below 8e-2 |P| h with 3
    // points, 2e-2 with 6).
    const Body& body = fbar.bodies[0];
    const MaterialParams& m = fbar.materials[0];
    const double force_scale = elastic_response(m, f).first_piola.norm() * 0.12;
    double worst = 0.0;
    for (int i = body.boundary_end; i < body.node_end; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (std::hypot(fbar.nodes.ref_x[k], fbar.nodes.ref_y[k]) + 3.0 * 0.12 > 0.5) continue;
      worst = std::max(worst, std::hypot(a.fx[k], a.fy[k]) / force_scale);
    }
    std::printf("%d Gauss points: interior force / (|P| h) %.3e\n", gauss_points, worst);
    EXPECT_LT(worst, gauss_points == 3 ? 8e-2 : 2e-2);
  }
}

TEST(FBar, RigidRotationGivesNoStressAndRotatesTheForcesOfADeformedState) {
  Model model = disc_of(fbar_material(0.495, 0.05));
  const double angle = 0.7 * std::numbers::pi;
  set_affine_deformation(model, 0, rotation(angle));
  set_rigid_velocity(model, 0, Vec2(0.3, -0.2), 2.0);
  std::fill(model.nodes.fx.begin(), model.nodes.fx.end(), 0.0);
  std::fill(model.nodes.fy.begin(), model.nodes.fy.end(), 0.0);
  const InternalForceResult r = add_internal_forces(model);
  const MaterialParams& m = model.materials[0];
  const double scale = (m.lambda + 2 * m.mu) * 0.01 * 0.12;  // a 1% strain's nodal force
  EXPECT_LT(max_abs(model.nodes.fx), 1e-10 * scale);
  EXPECT_LT(max_abs(model.nodes.fy), 1e-10 * scale);
  EXPECT_NEAR(r.elastic_energy, 0.0, 1e-12);
  EXPECT_NEAR(r.damping_power, 0.0, 1e-12);

  // A deformed state turned rigidly: same energy, forces turned with it (x -> Q x is the
  // parameters' map too, MLS reproducing linear fields).
  deform(model);
  const Forces before = forces(model);
  const Mat2 q = rotation(angle);
  NodeState& n = model.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const Vec2 x = q * Vec2(n.ref_x[i] + n.ux[i], n.ref_y[i] + n.uy[i]);
    n.ux[i] = x.x() - n.ref_x[i];
    n.uy[i] = x.y() - n.ref_y[i];
  }
  const Forces after = forces(model);
  EXPECT_GT(before.energy, 0.0);
  EXPECT_NEAR(after.energy, before.energy, 1e-12 * before.energy);
  const double force_scale = max_abs(before.fx) + max_abs(before.fy);
  for (std::size_t i = 0; i < n.size(); ++i) {
    const Vec2 turned = q * Vec2(before.fx[i], before.fy[i]);
    ASSERT_NEAR(after.fx[i], turned.x(), 1e-11 * force_scale) << i;
    ASSERT_NEAR(after.fy[i], turned.y(), 1e-11 * force_scale) << i;
  }
}

TEST(FBar, ForcesAreMinusTheGradientOfTheFBarEnergy) {
  for (int gauss_points : {3, 6}) {
    Model model = disc_of(fbar_material(0.495), gauss_points);
    deform(model);
    const Forces f = forces(model);
    // The kernel books the F-bar energy (the ledger's elastic energy).
    const double energy = fbar_energy(model);
    EXPECT_NEAR(f.energy, energy, 1e-12 * energy);
    // F-bar matters here: its forces differ from the standard ones by 9% of the largest force
    // (measured), 1e8 times the tolerance below.
    MaterialDef standard_def = fbar_material(0.495);
    standard_def.volumetric = VolumetricFormulation::standard;
    Model standard = disc_of(standard_def, gauss_points);
    deform(standard);
    const Forces s = forces(standard);
    const double scale = std::max(max_abs(f.fx), max_abs(f.fy));
    double differs = 0.0;
    for (std::size_t i = 0; i < f.fx.size(); ++i)
      differs = std::max(differs, std::abs(f.fx[i] - s.fx[i]) / scale);
    EXPECT_GT(differs, 0.03);
    // f_J = -dPi/du_J by central differences of the energy written above, every third node
    // (step 1e-6: truncation ~1e-12 and cancellation ~1e-10 of the force scale; measured worst
    // 1.0e-10 with 3 and 6 points).
    const double eps = 1e-6;
    double worst = 0.0;
    for (std::size_t i = 0; i < model.node_count(); i += 3)
      for (std::vector<double>* u : {&model.nodes.ux, &model.nodes.uy}) {
        const double u0 = (*u)[i];
        (*u)[i] = u0 + eps;
        const double plus = fbar_energy(model);
        (*u)[i] = u0 - eps;
        const double minus = fbar_energy(model);
        (*u)[i] = u0;
        const double force = u == &model.nodes.ux ? f.fx[i] : f.fy[i];
        worst = std::max(worst, std::abs(force + (plus - minus) / (2 * eps)) / scale);
      }
    std::printf("%d Gauss points: worst |f + dPi/du| / max|f| = %.2e (F-bar - standard: %.2f)\n",
                gauss_points, worst, differs);
    EXPECT_LT(worst, 1e-8);
  }
}

// Discs of three sizes (Gauss point counts not multiples of the SIMD width), displaced and
// moving at random.
Model random_discs(const MaterialDef& material, int count, unsigned seed) {
  Model model;
  const MaterialId m = model.add_material(material);
  for (int k = 0; k < count; ++k)
    scenes::add_disc(model, m, Vec2(1.2 * k, 0.0), 0.23 + 0.07 * (k % 4), 0.1,
                     "disc" + std::to_string(k));
  scenes::set_random_motion(model, seed);
  return model;
}

TEST(FBar, EveryKernelVersionAndThreadCountGivesTheSameBits) {
  for (DampingModel damping : kDampingModels) {
    MaterialDef material = fbar_material(0.495, 0.05);
    material.damping_model = damping;
    Model model = random_discs(material, 3, 7);
    std::vector<std::vector<double>> results;
    for (const ForceKernel* kernel : available_force_kernels()) {
      const NodeState& n = model.nodes;
      std::vector<double> out(4 * n.size(), 0.0);
      double energy = 0.0, power = 0.0;
      for (std::size_t b = 0; b < model.bodies.size(); ++b) {
        const auto o = static_cast<std::size_t>(model.bodies[b].node_begin);
        const BodyForceResult r = add_body_internal_forces(
            model, static_cast<BodyId>(b), n.ux.data() + o, n.uy.data() + o, n.vx.data() + o,
            n.vy.data() + o, out.data() + o, out.data() + n.size() + o, true,
            out.data() + 2 * n.size() + o, out.data() + 3 * n.size() + o, kernel);
        energy += r.elastic_energy;
        power += r.damping_power;
      }
      out.push_back(energy);
      out.push_back(power);
      results.push_back(out);
      std::printf("%s kernel (%s damping): energy %.17g, power %.17g\n", kernel->isa,
                  to_string(damping), energy, power);
    }
    for (const std::vector<double>& r : results)
      EXPECT_TRUE(r == results.front()) << to_string(damping);
  }

  Model model = random_discs(fbar_material(0.495, 0.05), 24, 9);
  std::vector<double> fx[2], fy[2], vfx[2];
  InternalForceResult result[2];
  for (int t = 0; t < 2; ++t) {
    omp_set_num_threads(t + 1);
    std::fill(model.nodes.fx.begin(), model.nodes.fx.end(), 0.0);
    std::fill(model.nodes.fy.begin(), model.nodes.fy.end(), 0.0);
    result[t] = add_internal_forces(model);
    fx[t] = model.nodes.fx;
    fy[t] = model.nodes.fy;
    vfx[t] = model.nodes.viscous_fx;
  }
  omp_set_num_threads(1);
  EXPECT_GT(result[0].elastic_energy, 0.0);
  EXPECT_TRUE(fx[0] == fx[1] && fy[0] == fy[1] && vfx[0] == vfx[1]);
  EXPECT_EQ(result[0].elastic_energy, result[1].elastic_energy);
  EXPECT_EQ(result[0].damping_power, result[1].damping_power);
}

}  // namespace
}  // namespace sg
