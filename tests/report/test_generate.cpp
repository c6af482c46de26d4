// softgrain generate (report/sample_report.h, render/sample_picture.h): the sample folder of a tiny
// compaction box and of a tiny shear cell, measured on the model build_model gives (the one run
// simulates). This file includes the scenario layer (not analysis/velocity_grid.h: see
// run_folder.h).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "geometry/shapes.h"
#include "render/png_reader.h"
#include "render/sample_picture.h"
#include "report/sample_report.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

const std::string kMaterials = std::string("[time]\nduration = 1.0\n") + scenes::kSoftHardCoulomb;

const char* kBox = R"(
[compaction_box]
width = 4.0
grains = 14
grain_material = "soft"
wall_material = "hard"
lid_velocity = 0.2
final_height = 3.5
seed = 3

[[compaction_box.components]]
name = "rigid"
shape = "fourier"
fraction = 2.0
diameter = [0.8, 1.2]
elongation = 0.15
irregularity = 0.06
roughness = 0.01
material = "hard"
rigid = true

[[compaction_box.components]]
name = "soft"
shape = "fourier"
fraction = 1.0
diameter = [0.8, 1.2]
elongation = 0.15
irregularity = 0.06
material = "soft"
)";

const char* kShearCell = R"(
[shear_cell]
length = 8.0
grains = 12
grain_material = "soft"
first_body_material = "hard"
roughness_rms = 0.2
hurst = 0.6
gap = 2.4
seed = 2
)";

ScenarioDef scenario_from(const std::string& tag, const std::string& text) {
  const fs::path dir = scenes::process_temp_dir("generate");
  const fs::path file = scenes::write_text_file(dir / (tag + ".toml"), text);
  ScenarioDef s = load_scenario(file);
  s.output_root = dir / "out";
  return s;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The files generate writes, with counts equal to those of an independently built model (the
// one `run` would simulate: same builder, same seed).
void expect_sample_folder(const ScenarioDef& s, const SampleReport& r, const fs::path& dir) {
  for (const char* f : {"sample.vtu", "sample.json", "sample.png"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_FALSE(fs::exists(dir / "fields.pvd"));  // the render's temporary index is removed
  EXPECT_FALSE(fs::exists(dir / "render"));
  const Model run_model = build_model(s);
  const nlohmann::json j = read_json(dir / "sample.json");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["counts"]["bodies"].get<std::size_t>(), run_model.bodies.size());
  EXPECT_EQ(j["counts"]["nodes"].get<std::size_t>(), run_model.node_count());
  EXPECT_EQ(j["counts"]["gauss_points"].get<std::size_t>(), run_model.gauss_point_count());
  EXPECT_EQ(j["counts"]["contour_points"].get<std::size_t>(), run_model.contour_point_count());
  EXPECT_EQ(j["packing"]["overlapping_pairs"], 0);
  EXPECT_EQ(j["packing"]["smallest_gap"].get<double>(), r.smallest_gap);
  const auto [w, h] = png_size(dir / "sample.png");
  EXPECT_EQ(w, 1200);
  EXPECT_EQ(h, 800);
}

TEST(Generate, CompactionBoxSampleHasNoOverlapAndTheBuildersSolidFraction) {
  const ScenarioDef s = scenario_from("box", std::string(kMaterials) + kBox);
  Model model = build_model(s);
  const fs::path dir = s.output_root / s.name / "sample";
  const SampleReport r = measure_sample(s, model);
  write_sample(model, r, dir);
  draw_sample_picture(model, dir, "box");
  expect_sample_folder(s, r, dir);

  // 14 grains at 2 : 1 -> 9 rigid + 5 deformable (largest remainder), plus 4 rigid walls.
  EXPECT_EQ(r.grains, 14u);
  EXPECT_EQ(r.rigid_grains, 9u);
  EXPECT_EQ(r.deformable_grains, 5u);
  EXPECT_EQ(r.other_bodies, 4u);
  EXPECT_EQ(r.rigid_bodies, 13u);
  // The packer keeps 2% of the mean grain size (1) between contours and to the walls, and the
  // lid sits 2% above the deposit: the smallest gap is that clearance, not less.
  EXPECT_EQ(r.overlapping_pairs, 0);
  EXPECT_GE(r.smallest_gap, 0.02 - 1e-12);
  EXPECT_LT(r.smallest_gap, 0.05);
  // Solid fraction read off the built walls = the builder's grain area / (width x height).
  Model fresh;
  for (const MaterialDef& m : s.materials)
    fresh.add_material(m);
  const CompactionBoxInfo info =
      add_compaction_box(fresh, *s.compaction_box, 0, 1, s.discretization);
  EXPECT_NEAR(r.solid_fraction, info.solid_fraction, 1e-12 * info.solid_fraction);
  EXPECT_NEAR(r.grain_area, info.grain_area, 1e-12 * info.grain_area);
  // Sizes: per component, the draws' mean within 4 standard errors of the law's mean
  // (uniform on [0.8, 1.2]: std 0.1155), and the area-equivalent diameters inside the range.
  ASSERT_EQ(r.sizes.size(), 2u);
  for (const ComponentSizes& c : r.sizes) {
    EXPECT_EQ(c.quantity, "2 r_mean");
    EXPECT_DOUBLE_EQ(c.requested_mean, 1.0);
    EXPECT_NEAR(c.requested_std, 0.4 / std::sqrt(12.0), 1e-12);
    EXPECT_NEAR(c.drawn_mean, 1.0, 4.0 * c.requested_std / std::sqrt(double(c.count)));
    EXPECT_GT(c.area_diameter_mean, 0.8);
    EXPECT_LT(c.area_diameter_mean, 1.2);
    EXPECT_LT(c.ks_statistic, c.ks_critical_5pct) << c.name;  // seed 3
  }
  EXPECT_EQ(r.sizes[0].count + r.sizes[1].count, 14);
}

TEST(Generate, ShearCellSampleHasTheRequestedRoughness) {
  const ScenarioDef s = scenario_from("cell", std::string(kMaterials) + kShearCell);
  Model model = build_model(s);
  const fs::path dir = s.output_root / s.name / "sample";
  const SampleReport r = measure_sample(s, model);
  write_sample(model, r, dir);
  draw_sample_picture(model, dir, "cell");
  expect_sample_folder(s, r, dir);
  EXPECT_EQ(r.grains, 12u);
  EXPECT_EQ(r.other_bodies, 2u);
  EXPECT_EQ(r.overlapping_pairs, 0);
  EXPECT_GE(r.smallest_gap, 0.02 - 1e-12);  // the packer's clearance (2% of the size 1)
  // The rough surfaces are scaled to the requested RMS exactly (geometry/rough_surface.h);
  // the built first bodies' contours keep it to rounding.
  ASSERT_EQ(r.roughness.size(), 2u);
  for (const SurfaceRoughness& g : r.roughness)
    EXPECT_NEAR(g.measured_rms, 0.2, 1e-9) << g.body;
  // Spectral slope: the surfaces are random-phase sums with amplitudes exactly on the power
  // law C(q) ∝ q^-(1 + 2H), so the periodogram of the built contour lies on it and the fitted
  // slope is -(1 + 2H) = -2.2 to rounding (the tolerance of tests/geometry/
  // test_generation_rough.cpp). round(8 / 0.15) = 53 points: modes 1 .. 25.
  for (const SurfaceRoughness& g : r.roughness) {
    EXPECT_EQ(g.points, 53) << g.body;
    EXPECT_EQ(g.slope_min_mode, 1) << g.body;
    EXPECT_EQ(g.slope_max_mode, 25) << g.body;
    EXPECT_EQ(g.requested_hurst, 0.6) << g.body;
    EXPECT_NEAR(g.spectral_slope, -2.2, 1e-9) << g.body;
    EXPECT_NEAR(g.measured_hurst, 0.6, 1e-9) << g.body;
    EXPECT_TRUE(g.slope_note.empty()) << g.slope_note;
  }
  // Sizes: the draws' Kolmogorov-Smirnov distance to the requested law, below the 5% critical
  // value 1.36 / sqrt(n) (seed 2; the statistic itself is tested in tests/geometry).
  ASSERT_FALSE(r.sizes.empty());
  int drawn = 0;
  for (const ComponentSizes& c : r.sizes) {
    drawn += c.count;
    EXPECT_GT(c.ks_statistic, 0.0) << c.name;
    EXPECT_DOUBLE_EQ(c.ks_critical_5pct, 1.36 / std::sqrt(double(c.count))) << c.name;
    EXPECT_LT(c.ks_statistic, c.ks_critical_5pct) << c.name;
  }
  EXPECT_EQ(drawn, 12);
  // ... and the same numbers in sample.json.
  const nlohmann::json j = read_json(dir / "sample.json");
  ASSERT_EQ(j["sizes"].size(), r.sizes.size());
  for (std::size_t k = 0; k < r.sizes.size(); ++k) {
    EXPECT_EQ(j["sizes"][k]["ks_statistic"].get<double>(), r.sizes[k].ks_statistic);
    EXPECT_EQ(j["sizes"][k]["ks_critical_5pct"].get<double>(), r.sizes[k].ks_critical_5pct);
    EXPECT_EQ(j["sizes"][k]["ks_pass"].get<bool>(), true);
  }
  ASSERT_EQ(j["roughness"].size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(j["roughness"][k]["spectral_slope"].get<double>(), r.roughness[k].spectral_slope);
    EXPECT_DOUBLE_EQ(j["roughness"][k]["expected_slope"].get<double>(), -2.2);
    EXPECT_EQ(j["roughness"][k]["measured_hurst"].get<double>(), r.roughness[k].measured_hurst);
    EXPECT_EQ(j["roughness"][k]["requested_hurst"].get<double>(), 0.6);
    EXPECT_EQ(j["roughness"][k]["slope_modes"], nlohmann::json::array({1, 25}));
  }
  // Container: L times the distance between the mean surfaces (0 and top_mean_y at t = 0).
  EXPECT_GT(r.solid_fraction, 0.2);
  EXPECT_LT(r.solid_fraction, 0.9);
}

// The gap measure itself: two discs 0.1 apart, then overlapping by 0.1.
TEST(Generate, GapMeasureSeesAGapAndAnOverlap) {
  for (const double distance : {1.1, 0.9}) {
    Model model;
    MaterialDef m;
    m.name = "hard";
    m.young = 1000.0;
    model.add_material(m);
    model.add_rigid_body("a", make_disc(Vec2(0.0, 0.0), 0.5, 0.05), 0);
    model.add_rigid_body("b", make_disc(Vec2(distance, 0.0), 0.5, 0.05), 0);
    SampleReport r;
    measure_gaps(model, r);
    // Inscribed polygons of 63 sides: each radius falls short by at most r (1 - cos(pi/63)),
    // 6e-4, so the gap grows by up to 1.3e-3.
    if (distance > 1.0) {
      EXPECT_EQ(r.overlapping_pairs, 0);
      EXPECT_NEAR(r.smallest_gap, 0.1, 1.5e-3);
    } else {
      EXPECT_EQ(r.overlapping_pairs, 1);
      EXPECT_NEAR(r.smallest_gap, -0.1, 1.5e-3);
    }
  }
}

}  // namespace
}  // namespace sg
