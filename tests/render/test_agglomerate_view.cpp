// The filtered agglomerate view (`render --field agglomerates`, paper 002 Fig. 8B) on the tiny
// shear cell (tiny_run.h): only the grains with |C| above the threshold are coloured, red for
// C > 0 and blue for C < 0, in proportion to their area; every other grain light grey.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

#include "analysis/coherence_frames.h"
#include "core/error.h"
#include "picture_checks.h"
#include "render/colormap.h"
#include "render/picture_layout.h"
#include "render/png_reader.h"
#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"
#include "tiny_run.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

struct PixelCounts {
  int red = 0, blue = 0, light_grey = 0;
};

PixelCounts count_classes(const fs::path& png_path) {
  const PngPixels png = png_pixels(png_path);
  PixelCounts n;
  // The drawing only: the legend at the right repeats the three colours.
  const int right = png.width * 3 / 4;
  for (int y = 0; y < png.height; ++y)
    for (int x = 0; x < right; ++x) {
      const std::uint32_t v = png.at(x, y);
      n.red += test::pixel_is(v, agglomerate_colour(1.0), 3);
      n.blue += test::pixel_is(v, agglomerate_colour(-1.0), 3);
      n.light_grey += test::pixel_is(v, agglomerate_colour(0.0), 3);
    }
  return n;
}

class AgglomerateView : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { run_dir_ = test::tiny_shear_run_dir(); }
  static RenderOptions options(double threshold) {
    RenderOptions o;
    o.field = "agglomerates";
    o.width = 800;
    o.height = 800;  // limited by the width: the period drawn once, nothing repeated
    o.movie = false;
    o.last_frame_only = true;
    o.periodic = std::make_pair(0.0, 8.0);
    o.non_grain_rows = {"0", "1"};  // bottom, top
    o.agglomerate_threshold = threshold;
    return o;
  }
  static fs::path run_dir_;
};
fs::path AgglomerateView::run_dir_;

TEST_F(AgglomerateView, ColoursOnlyTheGrainsAboveTheThresholdBySign) {
  // The coherence the picture shows: C at each grain's centre on the last frame's setup.
  const PvdEntry last = read_pvd(run_dir_ / "fields.pvd").back();
  const GrainSnapshot snap = without_bodies(
      read_grain_snapshot((run_dir_ / "grains" / (last.file.stem().string() + ".csv")).string(),
                          last.time),
      {"0", "1"});
  ASSERT_EQ(snap.size(), 20u);
  const std::vector<GrainSnapshot> snaps = {snap};
  const GrainCoherence c =
      grain_coherence(snaps, mean_equivalent_diameter(snap), std::make_pair(0.0, 8.0));
  std::vector<double> magnitudes;
  for (std::size_t g = 0; g < snap.size(); ++g) {
    const double value = c.by_body[0][static_cast<std::size_t>(std::stol(snap.body[g]))];
    if (std::isfinite(value)) magnitudes.push_back(std::abs(value));
  }
  ASSERT_GE(magnitudes.size(), 10u);
  std::sort(magnitudes.begin(), magnitudes.end());
  // Halfway between two grains' |C| near the median: about half the grains above it.
  const std::size_t k = magnitudes.size() / 2;
  const double threshold = 0.5 * (magnitudes[k - 1] + magnitudes[k]);
  ASSERT_GT(magnitudes[k] - magnitudes[k - 1], 1e-6);
  double area_all = 0.0, area_red = 0.0, area_blue = 0.0;
  int above = 0;
  for (std::size_t g = 0; g < snap.size(); ++g) {
    const double value = c.by_body[0][static_cast<std::size_t>(std::stol(snap.body[g]))];
    area_all += snap.area[g];
    if (value > threshold) area_red += snap.area[g];
    if (value < -threshold) area_blue += snap.area[g];
    above += std::abs(value) > threshold ? 1 : 0;
  }
  const RenderResult r = render_run(run_dir_, options(threshold));
  ASSERT_EQ(r.images.size(), 1u);
  EXPECT_FALSE(r.has_range);
  EXPECT_NE(r.note.find(": " + std::to_string(above) + " of 20 over the 1 frame drawn"),
            std::string::npos)
      << r.note;
  const PixelCounts n = count_classes(r.images.front());
  const double grains = n.red + n.blue + n.light_grey;
  ASSERT_GT(grains, 10000.0);
  // The coloured share of the grains' pixels is their share of the grains' area (the outlines
  // cover a few percent of each grain alike).
  std::cout << "threshold " << threshold << ": " << above << " of 20 grains; pixel shares red "
            << n.red / grains << " blue " << n.blue / grains << ", area shares red "
            << area_red / area_all << " blue " << area_blue / area_all << "\n";
  EXPECT_NEAR(n.red / grains, area_red / area_all, 0.05);
  EXPECT_NEAR(n.blue / grains, area_blue / area_all, 0.05);
  EXPECT_GT(n.red + n.blue, 0);
  // Grain by grain: the pixel at its centre has the colour of its class (the layout of the
  // picture's box, as render_run made it).
  const Layout layout = make_layout(800, 800, r.world, true);
  const PngPixels png = png_pixels(r.images.front());
  int right_colour = 0;
  for (std::size_t g = 0; g < snap.size(); ++g) {
    const double value = c.by_body[0][static_cast<std::size_t>(std::stol(snap.body[g]))];
    const double grain_class = value > threshold ? 1.0 : value < -threshold ? -1.0 : 0.0;
    const double x = snap.position[g].x() - 8.0 * std::floor(snap.position[g].x() / 8.0);
    const auto px = static_cast<int>(layout.px(x)),
               py = static_cast<int>(layout.py(snap.position[g].y()));
    const bool ok = test::pixel_is(png.at(px, py), agglomerate_colour(grain_class), 3);
    EXPECT_TRUE(ok) << "grain " << snap.body[g] << " C = " << value;
    right_colour += ok ? 1 : 0;
  }
  EXPECT_EQ(right_colour, 20);

  // Above every grain's |C|: nothing coloured, every grain light grey.
  const RenderResult none =
      render_run(run_dir_, options(std::min(0.999, magnitudes.back() + 0.01)));
  const PixelCounts grey = count_classes(none.images.front());
  EXPECT_EQ(grey.red, 0);
  EXPECT_EQ(grey.blue, 0);
  EXPECT_NEAR(grey.light_grey, grains, 0.02 * grains);
}

TEST_F(AgglomerateView, RefusesAThresholdOutsideZeroToOne) {
  for (double bad : {0.0, 1.0, 1.5, -0.2}) {
    try {
      render_run(run_dir_, options(bad));
      ADD_FAILURE() << "threshold " << bad << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("--threshold"), std::string::npos) << e.what();
    }
  }
  const auto& fields = render_field_choices();
  EXPECT_NE(std::find(fields.begin(), fields.end(), "agglomerates"), fields.end());
}

}  // namespace
}  // namespace sg
