// The vectorized laws (material/material_batch.h) against the scalar ones (material.h), lane
// by lane, on random deformation gradients, rates and rotations: J from 1e-3 to 20 and J within
// 1e-12 of 1, both laws, the three damping models, and padding lanes (F = I, no rate).
//  - Without a logarithm (Saint-Venant-Kirchhoff, every viscous stress) the batch evaluates the
//    scalar law's operations in the scalar law's order: bit for bit the same, where Eigen does
//    not fuse. Eigen's packet math calls fused multiply-add itself where the instruction set has
//    it (a SOFTGRAIN_NATIVE build on an FMA machine; -ffp-contract=off does not reach explicit
//    intrinsics), and the scalar laws then round differently: relative 1e-13 there.
//  - The neo-Hookean law differs only through ln J where the batch uses xsimd's vector log
//    (wider than 128 bits; within an ulp or two of std::log): relative 1e-13 of the size of the
//    terms that carry ln J. On 128-bit batches (default build) it is std::log per lane: bit for
//    bit.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "material/material_batch.h"

namespace sg {
namespace {

constexpr int W = kSimdWidth;
#ifdef __FMA__
constexpr bool kEigenFuses = true;
#else
constexpr bool kEigenFuses = false;
#endif
using Lanes = std::array<double, W>;

MaterialParams params(MaterialLaw law, DampingModel model) {
  MaterialDef d;
  d.name = "m";
  d.law = law;
  d.young = 10.0;
  d.poisson = 0.495;
  d.damping = 0.02;
  d.damping_model = model;
  return make_material_params(d);
}

Lanes lanes(const DoubleBatch& b) {
  alignas(kSimdAlignment) Lanes v;
  b.store_aligned(v.data());
  return v;
}

Mat2 lane(const Tensor2B& t, int l) {
  const auto i = static_cast<std::size_t>(l);
  Mat2 m;
  m << lanes(t.xx)[i], lanes(t.xy)[i], lanes(t.yx)[i], lanes(t.yy)[i];
  return m;
}

Tensor2B batch_of(const std::vector<Mat2>& m, std::size_t first) {
  alignas(kSimdAlignment) std::array<Lanes, 4> c;
  for (std::size_t l = 0; l < W; ++l) {
    const Mat2& a = m[first + l];
    c[0][l] = a(0, 0);
    c[1][l] = a(0, 1);
    c[2][l] = a(1, 0);
    c[3][l] = a(1, 1);
  }
  return {DoubleBatch::load_aligned(c[0].data()), DoubleBatch::load_aligned(c[1].data()),
          DoubleBatch::load_aligned(c[2].data()), DoubleBatch::load_aligned(c[3].data())};
}

// F = R(theta) diag(s1, s2) R(phi) with J = s1 s2 spread over [1e-3, 20] (log-uniform), every
// fourth one with J within 1e-12 of 1, and a few padding lanes (identity).
struct Samples {
  std::vector<Mat2> f, rate;
};

Mat2 rotation(double angle) {
  Mat2 r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

Samples random_samples(int count) {
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Samples s;
  for (int k = 0; k < count; ++k) {
    const double j = k % 4 == 3 ? 1.0 + (2 * u(random) - 1) * 1e-12
                                : std::exp(std::log(1e-3) + u(random) * std::log(2e4));
    const double stretch = std::exp(1.5 * (2 * u(random) - 1));  // s1 / s2
    Mat2 d = Mat2::Zero();
    d(0, 0) = std::sqrt(j * stretch);
    d(1, 1) = std::sqrt(j / stretch);
    if (k % 4 == 3) d = std::sqrt(j) * Mat2::Identity();  // J near 1 and F near a rotation
    const Mat2 f = rotation(6.3 * u(random)) * d * rotation(6.3 * u(random));
    Mat2 rate;
    rate << 2 * u(random) - 1, 2 * u(random) - 1, 2 * u(random) - 1, 2 * u(random) - 1;
    const bool padding = k % 11 == 5;
    s.f.push_back(padding ? Mat2::Identity() : f);
    s.rate.push_back(padding ? Mat2::Zero() : rate);
  }
  return s;
}

// Bit for bit where Eigen does not fuse, else relative 1e-13 of the tensor's size.
void expect_same(const Mat2& batch, const Mat2& scalar) {
  if (kEigenFuses)
    ASSERT_LE((batch - scalar).norm(), 1e-13 * scalar.norm());
  else
    for (int c = 0; c < 4; ++c)
      ASSERT_EQ(batch(c), scalar(c));
}
void expect_same(double batch, double scalar) {
  if (kEigenFuses)
    ASSERT_LE(std::abs(batch - scalar), 1e-13 * std::abs(scalar));
  else
    ASSERT_EQ(batch, scalar);
}

constexpr int kSamples = 64 * 8 * 5;  // a multiple of every SIMD width

TEST(MaterialBatch, SaintVenantKirchhoffIsTheScalarLaw) {
  const MaterialParams m = params(MaterialLaw::saint_venant_kirchhoff, DampingModel::objective);
  const Samples s = random_samples(kSamples);
  for (std::size_t first = 0; first < s.f.size(); first += W) {
    const ElasticBatch b = elastic_response(m, batch_of(s.f, first));
    for (int l = 0; l < W; ++l) {
      const ElasticResponse r = elastic_response(m, s.f[first + static_cast<std::size_t>(l)]);
      expect_same(lane(b.first_piola, l), r.first_piola);
      expect_same(lanes(b.energy_density)[static_cast<std::size_t>(l)], r.energy_density);
    }
  }
}

TEST(MaterialBatch, NeoHookeanAgreesWithTheScalarLawToRoundOff) {
  const MaterialParams m = params(MaterialLaw::neo_hookean, DampingModel::objective);
  const Samples s = random_samples(kSamples);
  double worst_p = 0.0, worst_w = 0.0;
  for (std::size_t first = 0; first < s.f.size(); first += W) {
    const ElasticBatch b = elastic_response(m, batch_of(s.f, first));
    for (int l = 0; l < W; ++l) {
      const Mat2& f = s.f[first + static_cast<std::size_t>(l)];
      const ElasticResponse r = elastic_response(m, f);
      const double j = f.determinant(), log_j = std::abs(std::log(j));
      // The size of the terms: |P| and lambda |ln J| |F^-T| (the only term through the log);
      // for W, each of its three terms.
      const double p_scale = r.first_piola.norm() + m.lambda * log_j * f.inverse().norm();
      const double w_scale = 0.5 * m.mu * std::abs(f.squaredNorm() - 2.0) + m.mu * log_j +
                             0.5 * m.lambda * log_j * log_j;
      const double dp = (lane(b.first_piola, l) - r.first_piola).norm() / p_scale;
      const double dw =
          std::abs(lanes(b.energy_density)[static_cast<std::size_t>(l)] - r.energy_density);
      worst_p = std::max(worst_p, p_scale > 0 ? dp : 0.0);
      worst_w = std::max(worst_w, w_scale > 0 ? dw / w_scale : dw);
      if (f == Mat2::Identity()) {  // padding lanes: exactly no stress and no energy
        ASSERT_EQ(lane(b.first_piola, l).norm(), 0.0);
        ASSERT_EQ(lanes(b.energy_density)[static_cast<std::size_t>(l)], 0.0);
      }
    }
  }
  std::printf("neo-Hookean batch vs scalar: worst relative P %.2e, W %.2e (W = %d)\n", worst_p,
              worst_w, W);
  EXPECT_LE(worst_p, 1e-13);
  EXPECT_LE(worst_w, 1e-13);
  if (!kEigenFuses && W <= 2) {  // std::log per lane (batch_log): the scalar law's bits
    EXPECT_EQ(worst_p, 0.0);
    EXPECT_EQ(worst_w, 0.0);
  }
}

TEST(MaterialBatch, ViscousStressesAreTheScalarOnes) {
  const Samples s = random_samples(kSamples);
  const Mat2 r = rotation(2.1);
  for (DampingModel model :
       {DampingModel::objective, DampingModel::corotational, DampingModel::reference_stiffness}) {
    const MaterialParams m = params(MaterialLaw::neo_hookean, model);
    for (std::size_t first = 0; first < s.f.size(); first += W) {
      const ViscousBatch b = viscous_response(m, batch_of(s.f, first), batch_of(s.rate, first), r);
      for (int l = 0; l < W; ++l) {
        const std::size_t k = first + static_cast<std::size_t>(l);
        const ViscousResponse v = viscous_response(m, s.f[k], s.rate[k], r);
        expect_same(lane(b.first_piola, l), v.first_piola);
        expect_same(lanes(b.power_density)[static_cast<std::size_t>(l)], v.power_density);
        if (s.rate[k] == Mat2::Zero()) {
          ASSERT_EQ(lane(b.first_piola, l).norm(), 0.0);
        }
      }
    }
  }
}

}  // namespace
}  // namespace sg
