// Packings: no overlap (checked here by brute force on the exact contours, periodic images
// included, independently of the packer's own grid), every grain inside its container,
// the requested count, a solid fraction above a stated minimum, determinism, speed.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "core/error.h"
#include "geometry/packing.h"
#include "geometry/shapes.h"

namespace sg {
namespace {

// Exact test: any pair of edges touching, or a vertex of one inside the other.
bool brute_force_overlap(const Polygon& a, const Polygon& b, double shift_x) {
  Polygon moved = b;
  for (Vec2& v : moved)
    v.x() += shift_x;
  Vec2 alo = a[0], ahi = a[0], blo = moved[0], bhi = moved[0];
  for (const Vec2& v : a)
    alo = alo.cwiseMin(v), ahi = ahi.cwiseMax(v);
  for (const Vec2& v : moved)
    blo = blo.cwiseMin(v), bhi = bhi.cwiseMax(v);
  if (ahi.x() < blo.x() || bhi.x() < alo.x() || ahi.y() < blo.y() || bhi.y() < alo.y())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < moved.size(); ++j)
      if (segments_intersect(a[i], a[(i + 1) % a.size()], moved[j], moved[(j + 1) % moved.size()]))
        return true;
  return contains(a, moved[0]) || contains(moved, a[0]);
}

int count_overlaps(const PackingResult& r, const ContainerDef& c) {
  const double width = c.x_max - c.x_min;
  const bool periodic = c.kind == ContainerKind::periodic_strip;
  int overlaps = 0;
  for (std::size_t i = 0; i < r.contours.size(); ++i)
    for (std::size_t j = i + 1; j < r.contours.size(); ++j)
      for (double shift : {-width, 0.0, width}) {
        if (!periodic && shift != 0.0) continue;
        if (brute_force_overlap(r.contours[i], r.contours[j], shift)) ++overlaps;
      }
  return overlaps;
}

void expect_inside(const PackingResult& r, const ContainerDef& c) {
  for (std::size_t i = 0; i < r.contours.size(); ++i) {
    for (const Vec2& v : r.contours[i]) {
      ASSERT_GE(v.y(), c.y_min) << "grain " << i;
      if (c.kind == ContainerKind::box) {
        ASSERT_LE(v.y(), c.y_max) << "grain " << i;
        ASSERT_GE(v.x(), c.x_min) << "grain " << i;
        ASSERT_LE(v.x(), c.x_max) << "grain " << i;
      }
    }
    if (c.kind == ContainerKind::periodic_strip) {
      ASSERT_GE(r.positions[i].x(), c.x_min);
      ASSERT_LT(r.positions[i].x(), c.x_max);
    }
  }
}

// Grains whose contour crosses the periodic seam (some vertex beyond x_min or x_max).
int seam_crossings(const PackingResult& r, const ContainerDef& c) {
  int n = 0;
  for (const Polygon& p : r.contours) {
    bool crosses = false;
    for (const Vec2& v : p)
      crosses = crosses || v.x() < c.x_min || v.x() >= c.x_max;
    n += crosses;
  }
  return n;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

GrainComponentDef discs_of_paper_001() {
  GrainComponentDef discs;  // defaults: uniform diameters in [0.85, 1.15] (paper 001 §2)
  discs.shape.contour_spacing = 0.12;  // DESIGN §2: h ~ 0.12 for d ~ 1
  return discs;
}

TEST(Packing, DiscsInAPeriodicStripAreDenseAndDisjointAcrossTheSeam) {
  const std::vector<GrainDef> grains = generate_grains({{discs_of_paper_001()}}, 200, 1);
  PackingDef def;
  def.container = {ContainerKind::periodic_strip, 0.0, 14.0, 0.0, 0.0};
  const auto start = std::chrono::steady_clock::now();
  const PackingResult r = pack_grains(grains, def, 42);
  const double seconds = seconds_since(start);
  std::printf(
      "200 discs, strip: solid fraction %.3f, bulk %.3f, top %.2f, %d sweeps, %.2f s, "
      "%d grains across the seam\n",
      r.solid_fraction, r.bulk_solid_fraction, r.top, r.sweeps, seconds,
      seam_crossings(r, def.container));
  ASSERT_EQ(r.contours.size(), 200u);
  EXPECT_EQ(count_overlaps(r, def.container), 0);
  expect_inside(r, def.container);
  EXPECT_GT(seam_crossings(r, def.container), 0);  // the images were exercised
  // 2D polydisperse discs: random close packing ~0.82-0.84, random loose ~0.77-0.80; the
  // whole-height fraction also counts the rough top layer (about half a diameter over ~15)
  // as void. Measured 0.740 and 0.770 for this seed; the bounds are the loose side of the
  // physical range, far above what placement alone gives (RSA here: 0.29).
  EXPECT_GT(r.solid_fraction, 0.70);
  EXPECT_GT(r.bulk_solid_fraction, 0.75);
  // (The time is printed, not asserted: performance is measured by bench/, and a timed test
  // fails on a loaded machine; 12.8 s was seen with other builds running.)
}

TEST(Packing, OrderAlongXSortsByTheCentroidsAndKeepsTiesInInputOrder) {
  PackingResult packed;
  packed.positions = {Vec2(3.0, 0.0), Vec2(-1.0, 5.0), Vec2(3.0, -2.0), Vec2(0.5, 1.0),
                      Vec2(-1.0, 0.0)};
  EXPECT_EQ(order_along_x(packed), (std::vector<std::size_t>{1, 4, 3, 0, 2}));
  EXPECT_TRUE(order_along_x(PackingResult{}).empty());
}

TEST(Packing, DiscsInABox) {
  const std::vector<GrainDef> grains = generate_grains({{discs_of_paper_001()}}, 200, 2);
  PackingDef def;
  def.container = {ContainerKind::box, 0.0, 12.0, 0.0, 40.0};
  const auto start = std::chrono::steady_clock::now();
  const PackingResult r = pack_grains(grains, def, 7);
  const double seconds = seconds_since(start);
  std::printf("200 discs, box: solid fraction %.3f, bulk %.3f, top %.2f, %d sweeps, %.2f s\n",
              r.solid_fraction, r.bulk_solid_fraction, r.top, r.sweeps, seconds);
  ASSERT_EQ(r.contours.size(), 200u);
  EXPECT_EQ(count_overlaps(r, def.container), 0);
  expect_inside(r, def.container);
  // Measured 0.712 (bulk 0.748): two walls add their own layering voids to the strip case.
  EXPECT_GT(r.solid_fraction, 0.68);
}

TEST(Packing, Paper003MixtureOfCirclesAndEllipsesInAStrip) {
  GrainComponentDef circles;
  circles.shape.diameter = {0.3, 0.5, SizeLaw::uniform};
  circles.shape.contour_spacing = 0.03;
  GrainComponentDef ellipses;
  ellipses.shape.kind = GrainShapeKind::ellipse;
  ellipses.shape.major_axis = {1.0, 2.0, SizeLaw::uniform};
  ellipses.shape.minor_axis = {0.6, 1.2, SizeLaw::uniform};
  ellipses.shape.contour_spacing = 0.06;
  ellipses.rigid = true;
  const std::vector<GrainDef> grains = generate_grains({{circles, ellipses}}, 192, 3);
  PackingDef def;
  def.container = {ContainerKind::periodic_strip, 0.0, 20.0, 0.0, 0.0};  // paper 003: ~20 µm
  const auto start = std::chrono::steady_clock::now();
  const PackingResult r = pack_grains(grains, def, 5);
  const double seconds = seconds_since(start);
  std::printf(
      "192 circles+ellipses, strip: solid fraction %.3f, bulk %.3f, top %.2f, %d "
      "sweeps, %.2f s, %d across the seam\n",
      r.solid_fraction, r.bulk_solid_fraction, r.top, r.sweeps, seconds,
      seam_crossings(r, def.container));
  ASSERT_EQ(r.contours.size(), 192u);
  EXPECT_EQ(count_overlaps(r, def.container), 0);
  expect_inside(r, def.container);
  // Measured 0.659 (bulk 0.755); the 0.6 of the issue for a compacted 2D sample.
  EXPECT_GT(r.solid_fraction, 0.6);
}

TEST(Packing, FourierGrainsInABoxWithAGap) {
  GrainComponentDef k;
  k.shape.kind = GrainShapeKind::fourier;
  k.shape.diameter = {0.8, 1.2, SizeLaw::uniform};
  k.shape.spectrum = {0.15, 0.06, 0.02, 16, 0.2};
  k.shape.contour_spacing = 0.08;
  const std::vector<GrainDef> grains = generate_grains({{k}}, 100, 4);
  PackingDef def;
  def.container = {ContainerKind::box, 0.0, 10.0, 0.0, 25.0};
  def.min_gap = 0.01;
  const PackingResult r = pack_grains(grains, def, 9);
  std::printf("100 Fourier grains, box, gap 0.01: solid fraction %.3f, bulk %.3f, %d sweeps\n",
              r.solid_fraction, r.bulk_solid_fraction, r.sweeps);
  ASSERT_EQ(r.contours.size(), 100u);
  EXPECT_EQ(count_overlaps(r, def.container), 0);
  expect_inside(r, def.container);
  // The gap: no vertex of one grain within 0.01 of another grain's contour (checked on
  // the pairs whose bounding boxes come within the gap).
  double closest = 1e9;
  for (std::size_t i = 0; i < r.contours.size(); ++i)
    for (std::size_t j = 0; j < r.contours.size(); ++j) {
      if (i == j || (r.positions[i] - r.positions[j]).norm() > 3.0) continue;
      for (const Vec2& v : r.contours[i])
        closest = std::min(closest, distance_to_contour(r.contours[j], v));
    }
  EXPECT_GE(closest, 0.01);
  EXPECT_GT(r.solid_fraction, 0.6);  // measured 0.645 (bulk 0.721)
}

TEST(Packing, SameSeedSamePackingOtherSeedOther) {
  const std::vector<GrainDef> grains = generate_grains({{discs_of_paper_001()}}, 60, 1);
  PackingDef def;
  def.container = {ContainerKind::periodic_strip, 0.0, 8.0, 0.0, 0.0};
  def.max_sweeps = 50;
  const PackingResult a = pack_grains(grains, def, 1), b = pack_grains(grains, def, 1);
  const PackingResult c = pack_grains(grains, def, 2);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.rotations, b.rotations);
  EXPECT_NE(a.positions, c.positions);
}

TEST(Packing, TooManyGrainsForTheBoxIsAClearError) {
  const std::vector<GrainDef> grains = generate_grains({{discs_of_paper_001()}}, 200, 1);
  PackingDef def;
  def.container = {ContainerKind::box, 0.0, 10.0, 0.0, 10.0};  // area 100 < 200 x 0.79
  EXPECT_THROW(pack_grains(grains, def, 1), Error);
  def.container = {ContainerKind::box, 0.0, 12.0, 0.0, 20.0};  // area 240: RSA jams first
  def.max_attempts_per_grain = 2000;
  try {
    pack_grains(grains, def, 1);
    ADD_FAILURE() << "expected sg::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("could not place grain"), std::string::npos) << e.what();
  }
}

TEST(Packing, ContoursOverlapDetectsCrossingAndContainment) {
  const Polygon a = make_disc(Vec2(0, 0), 1.0, 0.1);
  EXPECT_TRUE(contours_overlap(a, make_disc(Vec2(1.5, 0), 1.0, 0.1)));    // crossing
  EXPECT_TRUE(contours_overlap(a, make_disc(Vec2(0.1, 0), 0.3, 0.1)));    // inside
  EXPECT_FALSE(contours_overlap(a, make_disc(Vec2(2.01, 0), 1.0, 0.1)));  // apart
}

}  // namespace
}  // namespace sg
