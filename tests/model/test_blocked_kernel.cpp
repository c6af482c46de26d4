// The blocked SIMD force kernel (model/internal_forces.cpp on model/gauss_blocks.h) against
// the scalar kernel it replaced (tests/scenes/reference_kernel.h): the layout holds every
// Gauss point's row once, in order, whatever the number of points per body; the forces and
// energies are the scalar kernel's bit for bit where no logarithm enters (Saint-Venant-
// Kirchhoff, the viscous operator of the IMEX integrator; the neo-Hookean law too on 128-bit
// batches, where ln J is std::log per lane) and to round-off through xsimd's vector log (wider
// batches); results do not depend on the thread count. "Bit for bit" holds where Eigen
// does not fuse multiply-adds in the scalar laws (tests/material/test_material_batch.cpp); on an
// FMA build (SOFTGRAIN_NATIVE) the comparison is to round-off (1e-13).
#include <gtest/gtest.h>
#include <omp.h>

#include <random>
#include <vector>

#include "model/internal_forces.h"
#include "scenes/free_grains.h"
#include "scenes/reference_kernel.h"

namespace sg {
namespace {

constexpr int W = GaussBlocks::width;
#ifdef __FMA__
constexpr bool kEigenFuses = true;
#else
constexpr bool kEigenFuses = false;
#endif

// Discs of three sizes (radii 0.5, 0.37, 0.23 at h = 0.1; GaussBlocks.* checks that one has a
// number of Gauss points that is not a multiple of W),
// displaced and moving at random (strains of a few percent).
Model random_discs(const MaterialDef& material, unsigned seed) {
  Model model;
  const MaterialId m = model.add_material(material);
  const double radii[] = {0.5, 0.37, 0.23};
  for (int k = 0; k < 3; ++k)
    scenes::add_disc(model, m, Vec2(1.2 * k, 0.0), radii[k], 0.1, "disc" + std::to_string(k));
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  NodeState& n = model.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    n.ux[i] = 0.02 * u(random) + 0.05 * n.ref_x[i];
    n.uy[i] = 0.02 * u(random) - 0.03 * n.ref_y[i];
    n.vx[i] = u(random);
    n.vy[i] = u(random);
  }
  return model;
}

TEST(GaussBlocks, EveryRowOnceInOrderWithZeroPadding) {
  const Model model = random_discs(scenes::elastic_material(), 1);
  const GaussBlocks& blocks = model.gauss_blocks;
  const ShapeRows& rows = model.gauss_rows;
  bool partial_block = false;
  for (const Body& body : model.bodies) {
    const int points = body.gauss_end - body.gauss_begin;
    ASSERT_EQ(body.block_end - body.block_begin, (points + W - 1) / W);
    partial_block = partial_block || points % W != 0;
    for (int b = body.block_begin; b < body.block_end; ++b)
      for (int l = 0; l < W; ++l) {
        const auto lane = static_cast<std::size_t>(b * W + l);
        const int g = body.gauss_begin + (b - body.block_begin) * W + l;
        const int padded = blocks.row_offset[static_cast<std::size_t>(b) + 1] -
                           blocks.row_offset[static_cast<std::size_t>(b)];
        if (g >= body.gauss_end) {  // a padding lane: no weight, no entries
          ASSERT_EQ(blocks.gauss[lane], -1);
          ASSERT_EQ(blocks.weight[lane], 0.0);
          ASSERT_EQ(blocks.length[lane], 0);
        } else {
          ASSERT_EQ(blocks.gauss[lane], g);
          ASSERT_EQ(blocks.weight[lane], model.gauss_weight[static_cast<std::size_t>(g)]);
          ASSERT_EQ(blocks.length[lane], rows.offset[g + 1] - rows.offset[g]);
        }
        for (int r = 0; r < padded; ++r) {
          const auto e = static_cast<std::size_t>(
              (blocks.row_offset[static_cast<std::size_t>(b)] + r) * W + l);
          if (g < body.gauss_end && r < blocks.length[lane]) {
            const auto k = static_cast<std::size_t>(rows.offset[g] + r);
            ASSERT_EQ(blocks.node[e], rows.node[k]);
            ASSERT_EQ(blocks.dndx[e], rows.dndx[k]);
            ASSERT_EQ(blocks.dndy[e], rows.dndy[k]);
          } else {
            ASSERT_EQ(blocks.dndx[e], 0.0);
            ASSERT_EQ(blocks.dndy[e], 0.0);
            ASSERT_TRUE(blocks.node[e] >= 0 && blocks.node[e] < body.node_count());
          }
        }
      }
  }
  if (W > 1) {
    EXPECT_TRUE(partial_block) << "no body exercises a partial block";
  }
}

struct Forces {
  std::vector<double> fx, fy, vfx, vfy;
  double elastic = 0, power = 0;
};

// One kernel (blocked or reference) over every body of the model.
template <class Kernel>
Forces forces_of(const Model& model, Kernel kernel) {
  const NodeState& n = model.nodes;
  Forces f{std::vector<double>(n.size(), 0.0), std::vector<double>(n.size(), 0.0),
           std::vector<double>(n.size()), std::vector<double>(n.size())};
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const auto o = static_cast<std::size_t>(model.bodies[b].node_begin);
    const BodyForceResult r =
        kernel(model, static_cast<BodyId>(b), n.ux.data() + o, n.uy.data() + o, n.vx.data() + o,
               n.vy.data() + o, f.fx.data() + o, f.fy.data() + o, true, f.vfx.data() + o,
               f.vfy.data() + o);
    EXPECT_EQ(r.bad_gauss_point, -1);
    f.elastic += r.elastic_energy;
    f.power += r.damping_power;
  }
  return f;
}

double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (double x : a)
    m = std::max(m, std::abs(x));
  return m;
}

// Largest difference over the scale of the reference (max |f|, |E|, power).
double worst_difference(const Forces& a, const Forces& b) {
  double worst = 0.0;
  for (auto field : {&Forces::fx, &Forces::fy, &Forces::vfx, &Forces::vfy}) {
    const double scale = max_abs(b.*field);
    for (std::size_t i = 0; i < (a.*field).size(); ++i)
      worst = std::max(worst, std::abs((a.*field)[i] - (b.*field)[i]) / scale);
  }
  worst = std::max(worst, std::abs(a.elastic - b.elastic) / std::abs(b.elastic));
  return std::max(worst, std::abs(a.power - b.power) / std::abs(b.power));
}

TEST(BlockedKernel, MatchesTheScalarKernelForEveryLawAndDampingModel) {
  for (MaterialLaw law : {MaterialLaw::neo_hookean, MaterialLaw::saint_venant_kirchhoff})
    for (DampingModel damping :
         {DampingModel::objective, DampingModel::corotational, DampingModel::reference_stiffness}) {
      MaterialDef material = scenes::elastic_material(law, 0.05, 0.45);
      material.damping_model = damping;
      const Model model = random_discs(material, 7);
      const Forces blocked = forces_of(model, add_body_internal_forces);
      const Forces reference = forces_of(model, scenes::reference_body_internal_forces);
      const double worst = worst_difference(blocked, reference);
      std::printf("%s, %s: worst relative difference %.2e\n", to_string(law), to_string(damping),
                  worst);
      // Bit for bit unless Eigen fuses or the neo-Hookean law takes xsimd's vector log (W > 2).
      if (!kEigenFuses && (law == MaterialLaw::saint_venant_kirchhoff || W <= 2))
        EXPECT_EQ(worst, 0.0) << "the same operations in the same order";
      else
        EXPECT_LE(worst, 1e-13) << to_string(damping);
    }
}

TEST(BlockedKernel, ViscousOperatorAndGradientsAreTheScalarOnes) {
  for (DampingModel damping :
       {DampingModel::objective, DampingModel::corotational, DampingModel::reference_stiffness}) {
    MaterialDef material = scenes::elastic_material(MaterialLaw::neo_hookean, 0.05, 0.45);
    material.damping_model = damping;
    const Model model = random_discs(material, 11);
    const NodeState& n = model.nodes;
    const Mat2 rotation = body_rotation(model, 0).matrix();
    for (BodyId b = 0; b < static_cast<BodyId>(model.bodies.size()); ++b) {
      const auto o = static_cast<std::size_t>(model.bodies[static_cast<std::size_t>(b)].node_begin);
      const auto count =
          static_cast<std::size_t>(model.bodies[static_cast<std::size_t>(b)].node_count());
      std::vector<Mat2> blocked_f, reference_f;
      body_deformation_gradients(model, b, n.ux.data() + o, n.uy.data() + o, blocked_f);
      scenes::reference_deformation_gradients(model, b, n.ux.data() + o, n.uy.data() + o,
                                              reference_f);
      ASSERT_EQ(blocked_f, reference_f);
      std::vector<double> ax(count), ay(count), bx(count), by(count);
      apply_viscous_operator(model, b, blocked_f, rotation, n.vx.data() + o, n.vy.data() + o,
                             ax.data(), ay.data());
      scenes::reference_viscous_operator(model, b, reference_f, rotation, n.vx.data() + o,
                                         n.vy.data() + o, bx.data(), by.data());
      if (kEigenFuses) {
        for (std::size_t i = 0; i < count; ++i) {
          ASSERT_NEAR(ax[i], bx[i], 1e-13 * (max_abs(bx) + max_abs(by))) << to_string(damping);
          ASSERT_NEAR(ay[i], by[i], 1e-13 * (max_abs(bx) + max_abs(by))) << to_string(damping);
        }
      } else {
        ASSERT_EQ(ax, bx) << to_string(damping);
        ASSERT_EQ(ay, by) << to_string(damping);
      }
    }
  }
}

TEST(BlockedKernel, OneAndTwoThreadsGiveBitwiseIdenticalForces) {
  MaterialDef material = scenes::elastic_material(MaterialLaw::neo_hookean, 0.05, 0.45);
  Model model = random_discs(material, 3);
  // More bodies than threads, of different sizes, so that the dynamic schedule varies.
  for (int k = 0; k < 20; ++k)
    scenes::add_disc(model, 0, Vec2(0.0, 1.2 * (k + 1)), 0.23 + 0.01 * k, 0.1,
                     "extra" + std::to_string(k));
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
  EXPECT_EQ(fx[0], fx[1]);
  EXPECT_EQ(fy[0], fy[1]);
  EXPECT_EQ(vfx[0], vfx[1]);
  EXPECT_EQ(result[0].elastic_energy, result[1].elastic_energy);
  EXPECT_EQ(result[0].damping_power, result[1].damping_power);
}

TEST(BlockedKernel, AnInvertedGaussPointIsReportedAsTheScalarKernelReportsIt) {
  Model model = random_discs(scenes::elastic_material(), 5);
  // Fold one node of the middle disc far over its neighbours: several Gauss points invert.
  const Body& body = model.bodies[1];
  const auto i = static_cast<std::size_t>(body.node_begin + body.node_count() / 2);
  model.nodes.ux[i] += 5.0;
  const NodeState& n = model.nodes;
  const auto o = static_cast<std::size_t>(body.node_begin);
  std::vector<double> fx(n.size()), fy(n.size());
  const BodyForceResult blocked =
      add_body_internal_forces(model, 1, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o,
                               n.vy.data() + o, fx.data(), fy.data(), false);
  const BodyForceResult reference = scenes::reference_body_internal_forces(
      model, 1, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o, n.vy.data() + o, fx.data(),
      fy.data(), false);
  ASSERT_GE(reference.bad_gauss_point, 0);
  EXPECT_EQ(blocked.bad_gauss_point, reference.bad_gauss_point);
  EXPECT_EQ(blocked.bad_jacobian, reference.bad_jacobian);
}

}  // namespace
}  // namespace sg
