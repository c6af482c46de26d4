// The force kernel (model/force_kernel.h) against the scalar kernel it replaced
// (tests/scenes/reference_kernel.h), in every version this build has and this processor runs
// (the default one and, on x86-64, the AVX2 one): the forces and energies are the scalar
// kernel's bit for bit (in a SOFTGRAIN_NATIVE build the neo-Hookean law takes xsimd's vector log
// on wide batches: round-off), whatever the number of Gauss points per body (not a multiple of
// W); results do not depend on the thread count or on the kernel's instruction set. "Bit for
// bit" holds where Eigen does not fuse multiply-adds in the scalar laws
// (tests/material/test_material_batch.cpp); on an FMA build (SOFTGRAIN_NATIVE) the comparison is
// to round-off (1e-13).
#include <gtest/gtest.h>
#include <omp.h>

#include <cstdlib>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "material/simd.h"
#include "model/internal_forces.h"
#include "model/kinematics.h"
#include "scenes/free_grains.h"
#include "scenes/random_motion.h"
#include "scenes/reference_kernel.h"

namespace sg {
namespace {

constexpr int W = kSimdWidth;
#ifdef __FMA__
constexpr bool kEigenFuses = true;
#else
constexpr bool kEigenFuses = false;
#endif

// Discs of three sizes (radii 0.5, 0.37, 0.23 at h = 0.1; a test below checks that one has a
// number of Gauss points that is not a multiple of W), displaced and moving at random (strains
// of a few percent).
Model random_discs(const MaterialDef& material, unsigned seed) {
  Model model;
  const MaterialId m = model.add_material(material);
  const double radii[] = {0.5, 0.37, 0.23};
  for (int k = 0; k < 3; ++k)
    scenes::add_disc(model, m, Vec2(1.2 * k, 0.0), radii[k], 0.1, "disc" + std::to_string(k));
  scenes::set_random_motion(model, seed);
  return model;
}

TEST(ForceKernel, TheDiscsHaveBodiesWhoseGaussPointCountIsNotAMultipleOfW) {
  const Model model = random_discs(scenes::elastic_material(), 1);
  bool partial_chunk = false;
  for (const Body& body : model.bodies)
    partial_chunk = partial_chunk || (body.gauss_end - body.gauss_begin) % W != 0;
  if (W > 1) {
    EXPECT_TRUE(partial_chunk) << "no body exercises a partial chunk of W Gauss points";
  }
  // And W = 4, the AVX2 kernel's width.
  bool partial_avx2_chunk = false;
  for (const Body& body : model.bodies)
    partial_avx2_chunk = partial_avx2_chunk || (body.gauss_end - body.gauss_begin) % 4 != 0;
  EXPECT_TRUE(partial_avx2_chunk);
}

TEST(ForceKernel, TheAvx2KernelIsUsedWhereTheProcessorHasAvx2) {
  const std::vector<const ForceKernel*> kernels = available_force_kernels();
  ASSERT_FALSE(kernels.empty());
  EXPECT_EQ(kernels[0], &default_force_kernel());
  const char* asked = std::getenv("SOFTGRAIN_SIMD");
  if (asked == nullptr || std::string(asked).empty()) {
    EXPECT_EQ(&force_kernel(), kernels.back());
  }
  std::printf("kernels:");
  for (const ForceKernel* k : kernels)
    std::printf(" %s", k->isa);
  std::printf("; in use: %s\n", force_kernel().isa);
}

TEST(ForceKernel, SoftgrainSimdNamesAKernelOrIsAClearError) {
  EXPECT_EQ(&force_kernel_named("default"), &default_force_kernel());
  EXPECT_EQ(&force_kernel_named(nullptr), available_force_kernels().back());
  EXPECT_EQ(&force_kernel_named(""), available_force_kernels().back());
  if (avx2_force_kernel() != nullptr) {
    EXPECT_EQ(&force_kernel_named("avx2"), avx2_force_kernel());
  } else {
    EXPECT_THROW(force_kernel_named("avx2"), Error);
  }
  try {
    force_kernel_named("avx512");
    ADD_FAILURE() << "an unknown kernel was accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("SOFTGRAIN_SIMD"), std::string::npos) << message;
    EXPECT_NE(message.find("'avx512'"), std::string::npos) << message;
    EXPECT_NE(message.find("expected 'default' or 'avx2'"), std::string::npos) << message;
  }
}

struct Forces {
  std::vector<double> fx, fy, vfx, vfy;
  double elastic = 0, power = 0;
};

// add_body_internal_forces through one given kernel version.
BodyForceResult with_kernel(const ForceKernel& kernel, const Model& model, BodyId b,
                            const double* ux, const double* uy, const double* vx, const double* vy,
                            double* fx, double* fy, bool with_damping, double* vfx, double* vfy) {
  return add_body_internal_forces(model, b, ux, uy, vx, vy, fx, fy, with_damping, vfx, vfy,
                                  &kernel);
}

// One kernel (a version of ours, or the reference) over every body of the model.
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

TEST(ForceKernel, EveryVersionMatchesTheScalarKernelForEveryLawAndDampingModel) {
  for (const ForceKernel* kernel : available_force_kernels())
    for (MaterialLaw law : {MaterialLaw::neo_hookean, MaterialLaw::saint_venant_kirchhoff})
      for (DampingModel damping : {DampingModel::objective, DampingModel::corotational,
                                   DampingModel::reference_stiffness}) {
        MaterialDef material = scenes::elastic_material(law, 0.05, 0.45);
        material.damping_model = damping;
        const Model model = random_discs(material, 7);
        const Forces ours = forces_of(model, [&](auto&&... args) {
          return with_kernel(*kernel, std::forward<decltype(args)>(args)...);
        });
        const Forces reference = forces_of(model, scenes::reference_body_internal_forces);
        const double worst = worst_difference(ours, reference);
        std::printf("%s kernel, %s, %s: worst relative difference %.2e\n", kernel->isa,
                    to_string(law), to_string(damping), worst);
        // Bit for bit unless Eigen fuses or the neo-Hookean law takes xsimd's vector log (W > 2).
        if (!kEigenFuses && (law == MaterialLaw::saint_venant_kirchhoff || W <= 2))
          EXPECT_EQ(worst, 0.0) << "the same operations in the same order";
        else
          EXPECT_LE(worst, 1e-13) << to_string(damping);
      }
}

// Each version's viscous operator and deformation gradients are the scalar reference's, and so
// are the gradients its force evaluation writes out.
TEST(ForceKernel, EveryVersionsViscousOperatorAndGradientsAreTheScalarOnes) {
  for (const ForceKernel* kernel : available_force_kernels())
    for (DampingModel damping :
         {DampingModel::objective, DampingModel::corotational, DampingModel::reference_stiffness}) {
      MaterialDef material = scenes::elastic_material(MaterialLaw::neo_hookean, 0.05, 0.45);
      material.damping_model = damping;
      const Model model = random_discs(material, 11);
      const NodeState& n = model.nodes;
      const Mat2 rotation = body_rotation(model, 0).matrix();
      for (BodyId b = 0; b < static_cast<BodyId>(model.bodies.size()); ++b) {
        const auto o = static_cast<std::size_t>(model.body(b).node_begin);
        const auto count = static_cast<std::size_t>(model.body(b).node_count());
        const Body& body = model.body(b);
        std::vector<Mat2> ours_f(static_cast<std::size_t>(body.gauss_end - body.gauss_begin)),
            reference_f;
        kernel->deformation_gradients(model, body, n.ux.data() + o, n.uy.data() + o, ours_f.data());
        scenes::reference_deformation_gradients(model, b, n.ux.data() + o, n.uy.data() + o,
                                                reference_f);
        ASSERT_EQ(ours_f, reference_f) << kernel->isa;
        // The F the force evaluation leaves for the IMEX solve (BodyArrays::gradients): the
        // same bits, damped or not.
        for (const bool damped : {false, true}) {
          std::vector<Mat2> from_forces(ours_f.size(), Mat2::Zero());
          std::vector<double> fx(count), fy(count);
          add_body_internal_forces(model, b, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o,
                                   n.vy.data() + o, fx.data(), fy.data(), damped, nullptr, nullptr,
                                   kernel, from_forces.data());
          ASSERT_EQ(from_forces, ours_f) << kernel->isa << (damped ? ", damped" : "");
        }
        std::vector<double> ax(count), ay(count), bx(count), by(count);
        kernel->viscous_operator(model, body, ours_f.data(), rotation, n.vx.data() + o,
                                 n.vy.data() + o, ax.data(), ay.data());
        scenes::reference_viscous_operator(model, b, reference_f, rotation, n.vx.data() + o,
                                           n.vy.data() + o, bx.data(), by.data());
        if (kEigenFuses) {
          for (std::size_t i = 0; i < count; ++i) {
            ASSERT_NEAR(ax[i], bx[i], 1e-13 * (max_abs(bx) + max_abs(by))) << to_string(damping);
            ASSERT_NEAR(ay[i], by[i], 1e-13 * (max_abs(bx) + max_abs(by))) << to_string(damping);
          }
        } else {
          ASSERT_EQ(ax, bx) << kernel->isa << ", " << to_string(damping);
          ASSERT_EQ(ay, by) << kernel->isa << ", " << to_string(damping);
        }
      }
    }
}

TEST(ForceKernel, OneAndTwoThreadsGiveBitwiseIdenticalForces) {
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

TEST(ForceKernel, AnInvertedGaussPointIsReportedAsTheScalarKernelReportsIt) {
  Model model = random_discs(scenes::elastic_material(), 5);
  // Fold one node of the middle disc far over its neighbours: several Gauss points invert.
  const Body& body = model.bodies[1];
  const auto i = static_cast<std::size_t>(body.node_begin + body.node_count() / 2);
  model.nodes.ux[i] += 5.0;
  const NodeState& n = model.nodes;
  const auto o = static_cast<std::size_t>(body.node_begin);
  std::vector<double> fx(n.size()), fy(n.size());
  const BodyForceResult reference = scenes::reference_body_internal_forces(
      model, 1, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o, n.vy.data() + o, fx.data(),
      fy.data(), false);
  ASSERT_GE(reference.bad_gauss_point, 0);
  std::vector<double> vfx(n.size()), vfy(n.size());
  for (const ForceKernel* kernel : available_force_kernels()) {
    const BodyForceResult ours =
        with_kernel(*kernel, model, 1, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o,
                    n.vy.data() + o, fx.data(), fy.data(), false, vfx.data(), vfy.data());
    EXPECT_EQ(ours.bad_gauss_point, reference.bad_gauss_point) << kernel->isa;
    EXPECT_EQ(ours.bad_jacobian, reference.bad_jacobian) << kernel->isa;
  }
}

}  // namespace
}  // namespace sg
