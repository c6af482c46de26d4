// Fourier-descriptor shapes and grain populations (shape laws, mixtures).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "geometry/fourier_shape.h"
#include "geometry/packing.h"

namespace sg {
namespace {

constexpr double pi = std::numbers::pi;

TEST(FourierShape, ZeroAmplitudesGiveARegularPolygonOnTheCircle) {
  const double r = 0.7, h = 0.05;
  const Vec2 c(1.0, -2.0);
  const Polygon p = make_fourier_shape(c, r, {}, h);
  for (const Vec2& v : p)
    EXPECT_NEAR((v - c).norm(), r, 1e-14);
  EXPECT_TRUE(is_counter_clockwise(p));
  EXPECT_FALSE(is_self_intersecting(p));
  // Uniform arc-length resampling of a circle is a regular n-gon: area (n/2) r^2 sin(2pi/n).
  const double n = static_cast<double>(p.size());
  EXPECT_NEAR(signed_area(p), 0.5 * n * r * r * std::sin(2.0 * pi / n), 1e-6 * r * r);
  EXPECT_NEAR(n, 2.0 * pi * r / h, 1.0);
}

TEST(FourierShape, SpectrumAnchorsAndLogLogDecay) {
  const FourierSpectrumDef s{0.1, 0.04, 0.01, 16, 0.0};
  const std::vector<double> d = fourier_descriptor_spectrum(s);
  ASSERT_EQ(d.size(), 17u);
  EXPECT_EQ(d[0], 1.0);
  EXPECT_EQ(d[1], 0.0);
  EXPECT_DOUBLE_EQ(d[2], 0.1);
  EXPECT_DOUBLE_EQ(d[3], 0.04);
  EXPECT_DOUBLE_EQ(d[8], 0.01);
  // One straight line in log-log through (3, D3) and (8, D8), continued beyond 8.
  const double slope = std::log(0.01 / 0.04) / std::log(8.0 / 3.0);
  for (int n = 4; n <= 16; ++n)
    EXPECT_NEAR(d[static_cast<std::size_t>(n)], 0.04 * std::pow(n / 3.0, slope), 1e-15) << n;
}

TEST(FourierShape, SmallAmplitudesAreSimpleCcwWithParsevalArea) {
  const FourierSpectrumDef s{0.05, 0.03, 0.01, 16, 0.2};
  RandomEngine engine(11);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<FourierMode> modes = sample_fourier_modes(s, engine);
    const double r = 1.0, h = 0.01;
    const Polygon p = make_fourier_shape(Vec2::Zero(), r, modes, h);
    EXPECT_TRUE(is_counter_clockwise(p));
    EXPECT_FALSE(is_self_intersecting(p));
    // Exact area of the curve: pi r^2 (1 + sum D_n^2 / 2). The inscribed polygon misses
    // about (2 pi^2 / 3) / n^2 of it for n ~ 2 pi r / h = 628 vertices (1.7e-5); 1e-4
    // relative covers the curvature variations, and is 20 times smaller than the
    // Parseval term itself (sum D_n^2 / 2 ~ 2e-3), which the check therefore sees.
    double parseval = 1.0;
    for (const FourierMode& m : modes)
      parseval += 0.5 * m.amplitude * m.amplitude;
    EXPECT_NEAR(signed_area(p) / (pi * r * r), parseval, 1e-4);
    EXPECT_GT(parseval - 1.0, 1e-3);
    // Vertices on the exact curve.
    for (const Vec2& v : p)
      EXPECT_NEAR(v.norm(), r * fourier_relative_radius(modes, std::atan2(v.y(), v.x())), 1e-13);
  }
}

TEST(FourierShape, RoughGrainsStayValidAndHugeAmplitudesAreRejected) {
  RandomEngine engine(3);
  const FourierSpectrumDef rough{0.2, 0.08, 0.03, 24, 0.3};
  for (int trial = 0; trial < 20; ++trial) {
    const Polygon p = sample_fourier_shape(Vec2::Zero(), 0.5, rough, 0.03, engine);
    EXPECT_TRUE(is_counter_clockwise(p));
    EXPECT_FALSE(is_self_intersecting(p));
  }
  const FourierSpectrumDef impossible{0.9, 0.9, 0.5, 16, 0.0};
  EXPECT_THROW(sample_fourier_shape(Vec2::Zero(), 0.5, impossible, 0.03, engine, 20), Error);
}

TEST(FourierShape, SameSeedSameShape) {
  const FourierSpectrumDef s{0.1, 0.05, 0.02, 16, 0.1};
  RandomEngine a(5), b(5), c(6);
  const Polygon pa = sample_fourier_shape(Vec2::Zero(), 1.0, s, 0.05, a);
  const Polygon pb = sample_fourier_shape(Vec2::Zero(), 1.0, s, 0.05, b);
  const Polygon pc = sample_fourier_shape(Vec2::Zero(), 1.0, s, 0.05, c);
  EXPECT_EQ(pa, pb);
  EXPECT_NE(pa, pc);
}

// Paper 003: equal numbers of circles (diameter 0.3-0.5 µm) and ellipses (long axis 1-2,
// short 0.6-1.2 µm); here one component rigid to check that the flags follow the grain.
MixtureDef paper_003_mixture() {
  GrainComponentDef circles;
  circles.name = "circles";
  circles.shape.kind = GrainShapeKind::disc;
  circles.shape.diameter = {0.3, 0.5, SizeLaw::uniform};
  circles.shape.contour_spacing = 0.03;
  circles.number_fraction = 0.5;
  circles.material = "oxide";
  GrainComponentDef ellipses;
  ellipses.name = "ellipses";
  ellipses.shape.kind = GrainShapeKind::ellipse;
  ellipses.shape.major_axis = {1.0, 2.0, SizeLaw::uniform};
  ellipses.shape.minor_axis = {0.6, 1.2, SizeLaw::uniform};
  ellipses.shape.contour_spacing = 0.06;
  ellipses.number_fraction = 0.5;
  ellipses.rigid = true;
  ellipses.material = "steel";
  return {{circles, ellipses}};
}

TEST(GrainPopulation, MixtureCountsFlagsAndShapes) {
  const std::vector<GrainDef> grains = generate_grains(paper_003_mixture(), 192, 2024);
  ASSERT_EQ(grains.size(), 192u);
  int circles = 0;
  for (const GrainDef& g : grains) {
    EXPECT_TRUE(is_counter_clockwise(g.contour));
    EXPECT_NEAR(centroid(g.contour).norm(), 0.0, 1e-12);
    if (g.component == 0) {
      ++circles;
      EXPECT_FALSE(g.rigid);
      EXPECT_EQ(g.material, "oxide");
      EXPECT_GE(g.size, 0.3);
      EXPECT_LE(g.size, 0.5);
      EXPECT_NEAR(g.bounding_radius, 0.5 * g.size,
                  1e-6 * g.size);  // re-centred on the discrete centroid
    } else {
      EXPECT_TRUE(g.rigid);
      EXPECT_EQ(g.material, "steel");
      EXPECT_GE(g.size, 1.0);
      EXPECT_LE(g.size, 2.0);
      EXPECT_NEAR(g.bounding_radius, 0.5 * g.size,
                  1e-6 * g.size);  // the long half-axis; centroid of the resampled contour is off
                                   // the centre by < 1e-7
    }
  }
  EXPECT_EQ(circles, 96);  // paper 003: 96 + 96
  // Shuffled: not all circles first.
  int first_ellipse = 0;
  while (grains[static_cast<std::size_t>(first_ellipse)].component == 0)
    ++first_ellipse;
  EXPECT_LT(first_ellipse, 20);
}

TEST(GrainPopulation, LargestRemainderCountsSumToTheTotal) {
  MixtureDef m;
  for (int c = 0; c < 3; ++c) {
    GrainComponentDef k;
    k.shape.contour_spacing = 0.2;
    k.number_fraction = 1.0;  // thirds of 100: 33.33 each, one extra to the first
    m.components.push_back(k);
  }
  const std::vector<GrainDef> grains = generate_grains(m, 100, 1);
  int counts[3] = {0, 0, 0};
  for (const GrainDef& g : grains)
    ++counts[g.component];
  EXPECT_EQ(counts[0], 34);
  EXPECT_EQ(counts[1], 33);
  EXPECT_EQ(counts[2], 33);
}

TEST(GrainPopulation, FourierGrainsAndBadInput) {
  GrainComponentDef k;
  k.shape.kind = GrainShapeKind::fourier;
  k.shape.diameter = {0.8, 1.2, SizeLaw::uniform};
  k.shape.spectrum = {0.15, 0.05, 0.02, 16, 0.2};
  k.shape.contour_spacing = 0.05;
  const std::vector<GrainDef> grains = generate_grains({{k}}, 30, 8);
  for (const GrainDef& g : grains) {
    EXPECT_FALSE(is_self_intersecting(g.contour));
    EXPECT_GT(signed_area(g.contour), 0.0);
  }
  MixtureDef empty;
  EXPECT_THROW(generate_grains(empty, 10, 1), Error);
  k.number_fraction = -1.0;
  EXPECT_THROW(generate_grains({{k}}, 10, 1), Error);
}

}  // namespace
}  // namespace sg
