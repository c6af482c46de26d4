#include <gtest/gtest.h>

#include <cmath>

#include "analysis/agglomerate_statistics.h"
#include "analysis/agglomerates.h"
#include "core/error.h"
#include "synthetic.h"

namespace sg {
namespace {

// Grains of a disc-shaped cluster: jittered lattice of pitch 1 inside radius r around c,
// moving rigidly with drift u and angular velocity w.
void add_cluster(GrainSnapshot& s, const Vec2& c, double r, const Vec2& u, double w,
                 std::uint64_t seed) {
  test::Gaussian rng(seed);
  for (double y = -r; y <= r; y += 1.0)
    for (double x = -r; x <= r; x += 1.0) {
      const Vec2 d(x + 0.3 * (rng.uniform() - 0.5), y + 0.3 * (rng.uniform() - 0.5));
      if (d.norm() > r) continue;
      s.position.push_back(c + d);
      s.velocity.push_back(u + w * perp(d));
      s.area.push_back(0.6 + 0.4 * rng.uniform());
      s.body.push_back("g");
    }
}

TEST(AngularVelocity, RigidClusterGivesItsRotationRate) {
  // Eq. 6 on a rigidly rotating and drifting cluster with unequal grain areas: every
  // sample V_circ/R_i is omega exactly (area-weighted barycentre and mean velocity), so
  // the mean is omega to rounding; 1e-6 asked, 1e-12 met.
  for (const double w : {0.37, -1.5}) {
    GrainSnapshot s;
    add_cluster(s, Vec2(3.0, -2.0), 4.0, Vec2(0.8, -0.3), w, 21);
    std::vector<double> samples;
    const double omega = cluster_angular_velocity(s.position, s.velocity, s.area, &samples);
    EXPECT_NEAR(omega, w, 1e-12);
    EXPECT_EQ(samples.size(), s.size());  // no grain sits exactly on the barycentre
    for (const double x : samples)
      EXPECT_NEAR(x, w, 1e-12);
  }
  EXPECT_TRUE(std::isnan(cluster_angular_velocity({}, {}, {}, nullptr)));
}

TEST(Agglomerates, TwoRotatingClustersOneAcrossTheSeam) {
  // An empty periodic cell (L = 40, layer [0, 20]) with two rigid clusters of radius 4:
  // one clockwise (w = -0.2, turning with the shear) centred on the seam, x = 0.5, one
  // counter-clockwise (w = +0.1) at x = 20. Five snapshots one time unit apart, the same
  // motion each time. Known answers: 2 structures, each living 5 frames, omega exactly the
  // cluster's (eq. 6: any subset of a rigid cluster gives its rate), omega~ = w/(-V/D) with
  // V = 1, D = 20.
  const double length = 40.0;
  std::vector<GrainSnapshot> snaps;
  for (int t = 0; t < 5; ++t) {
    GrainSnapshot s;
    s.time = 10.0 + t;
    add_cluster(s, Vec2(0.5, 10.0), 4.0, Vec2(0.1, 0.0), -0.2, 31);
    add_cluster(s, Vec2(20.0, 10.0), 4.0, Vec2(-0.1, 0.05), 0.1, 32);
    for (auto& p : s.position)
      if (p.x() < 0.0) p.x() += length;  // the engine writes positions inside the period
    snaps.push_back(s);
  }
  const RegularGrid grid = make_periodic_grid(0.0, length, 0.0, 20.0, 1.0);
  const AgglomerateResult r = detect_agglomerates(snaps, grid, AgglomerateParams{}, 1.0, 20.0);
  ASSERT_EQ(r.structures.size(), 2u);
  EXPECT_DOUBLE_EQ(r.frame_period, 1.0);
  EXPECT_EQ(r.coherence.size(), 5u);
  const Structure& seam = r.structures[0].sign < 0 ? r.structures[0] : r.structures[1];
  const Structure& other = r.structures[0].sign < 0 ? r.structures[1] : r.structures[0];
  EXPECT_EQ(seam.sign, -1);
  EXPECT_EQ(other.sign, 1);
  for (const Structure* s : {&seam, &other}) {
    EXPECT_EQ(s->frame_count, 5);
    EXPECT_DOUBLE_EQ(s->lifetime, 5.0);
    EXPECT_GT(s->grain_samples, 0u);
    // Bounds, not a value: the MLS fit is defined, and exact for a rigid field, up to the
    // support radius rho = 2 beyond the outermost grains, so valid nodes reach radius
    // 4 + 2; nodes there see a lopsided disc, C = sqrt(1 - |Mbar - P|^2 / <|M - P|^2>)
    // (coherence.h) which may still pass 0.8. Detected diameter: above the cluster's
    // half-diameter, below 2 (4 + 2) = 12.
    EXPECT_GT(s->diameter, 4.0);
    EXPECT_LT(s->diameter, 12.0);
  }
  EXPECT_NEAR(seam.omega, -0.2, 1e-9);  // MLS is exact on a rigid field; rounding only
  EXPECT_NEAR(other.omega, 0.1, 1e-9);
  EXPECT_NEAR(seam.omega_normalized, -0.2 / (-1.0 / 20.0), 1e-8);  // +4: turns with the shear
  EXPECT_NEAR(other.omega_normalized, -2.0, 1e-8);
  EXPECT_GT(r.grain_share, 0.5);
  EXPECT_LE(r.grain_share, 1.0);
  EXPECT_EQ(r.grain_samples, 5 * snaps[0].size());

  const AgglomerateStatistics st = compute_agglomerate_statistics(r, 1.0);
  EXPECT_EQ(st.structure_count, 2.0);
  EXPECT_EQ(st.positive_count, 1.0);
  EXPECT_EQ(st.negative_count, 1.0);
  // Equivalent-grain weighting: the mean of omega~ weighs each cluster by its samples.
  const double w0 = static_cast<double>(seam.grain_samples),
               w1 = static_cast<double>(other.grain_samples);
  EXPECT_NEAR(st.omega_mean, (4.0 * w0 - 2.0 * w1) / (w0 + w1), 1e-8);
  // The mode is the heavier structure's omega~, to within half a bin (0.05).
  ASSERT_NE(w0, w1);
  EXPECT_NEAR(st.omega_mode, w0 > w1 ? 4.0 : -2.0, 0.05 + 1e-9);
}

TEST(Agglomerates, NoMotionNoStructure) {
  GrainSnapshot s;
  add_cluster(s, Vec2(10.0, 5.0), 4.0, Vec2(0.3, 0.0), 0.0, 41);
  const std::vector<GrainSnapshot> snaps = {s};
  const RegularGrid grid = make_periodic_grid(0.0, 20.0, 0.0, 10.0, 1.0);
  const AgglomerateResult r = detect_agglomerates(snaps, grid, AgglomerateParams{}, 1.0, 10.0);
  EXPECT_TRUE(r.structures.empty());
  EXPECT_EQ(r.grain_share, 0.0);
}

TEST(WeightedPdf, DensityIntegratesToOneAndWeightsCount) {
  const std::vector<double> values = {1.2, 1.7, 2.5, 9.0};
  const std::vector<double> weights = {1.0, 1.0, 2.0, 5.0};
  const WeightedPdf pdf = weighted_pdf(values, weights, 4, 0.0, 4.0);
  // Weight 2 in bin [1, 2), 2 in [2, 3); total inside 4, width 1: densities 0.5, 0.5.
  EXPECT_EQ(pdf.density, (std::vector<double>{0.0, 0.5, 0.5, 0.0}));
  EXPECT_EQ(pdf.outside, 5.0);
  EXPECT_EQ(pdf.mode(), 1.5);  // ties: the first highest bin
  EXPECT_THROW(weighted_pdf(values, weights, 0, 0.0, 1.0), Error);
}

}  // namespace
}  // namespace sg
