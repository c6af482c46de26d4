// Colour scales of `softgrain render`: the default velocity range of a shear cell (+-V/2), the
// logarithmic scale (--log) and its decade colour bar, on the tiny runs of tiny_run.h and on
// the scale's own pieces.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "picture_checks.h"
#include "render/colormap.h"
#include "render/colour_bar.h"
#include "render/frame_style.h"
#include "render/picture_layout.h"
#include "render/png_reader.h"
#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE
#include "tiny_run.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// Min and max of a field over the points of the cells it colours (triangles, and the rigid
// bodies' polygons for fields defined on them), over the last snapshot or every snapshot.
std::pair<double, double> coloured_range(const fs::path& run_dir, const std::string& field,
                                         bool last_only) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const std::vector<PvdEntry> entries = read_pvd(run_dir / "fields.pvd");
  for (std::size_t i = last_only ? entries.size() - 1 : 0; i < entries.size(); ++i) {
    const VtuMesh m = read_vtu(entries[i].file);
    const std::vector<double> v = point_scalar(m, field);
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
      if (m.types[c] != kVtkTriangle &&
          !(field_defined_on_rigid(field) && m.types[c] == kVtkPolygon))
        continue;
      for (int p : m.cell(c)) {
        lo = std::min(lo, v[static_cast<std::size_t>(p)]);
        hi = std::max(hi, v[static_cast<std::size_t>(p)]);
      }
    }
  }
  return {lo, hi};
}

RenderOptions small_picture(const std::string& field) {
  RenderOptions o;
  o.field = field;
  o.width = 400;
  o.height = 240;
  o.movie = false;
  o.last_frame_only = true;
  return o;
}

// ------------------------------------------------------------ velocity range of a shear cell

TEST(VelocityRange, AShearCellDefaultsToPlusMinusHalfItsVelocity) {
  const fs::path dir = test::tiny_shear_run_dir();
  RenderOptions o = small_picture("velocity_x");
  o.periodic = std::make_pair(0.0, 8.0);
  o.shear_velocity = 1.0;  // the tiny cell's V
  RenderResult r = render_run(dir, o);
  EXPECT_EQ(r.range_min, -0.5);
  EXPECT_EQ(r.range_max, 0.5);
  EXPECT_NE(r.range_source.find("V/2 of the shear cell"), std::string::npos) << r.range_source;
  o.field = "velocity_y";
  r = render_run(dir, o);
  EXPECT_EQ(r.range_min, -0.5);
  EXPECT_EQ(r.range_max, 0.5);
  o.field = "velocity";  // the speed: 0 in the middle of the layer, V/2 at the first bodies
  r = render_run(dir, o);
  EXPECT_EQ(r.range_min, 0.0);
  EXPECT_EQ(r.range_max, 0.5);
  // --range and --robust override it; other fields keep min-max.
  o.field = "velocity_x";
  o.range = std::make_pair(-0.2, 0.3);
  r = render_run(dir, o);
  EXPECT_EQ(r.range_min, -0.2);
  EXPECT_EQ(r.range_source, "given");
  o.range.reset();
  o.robust_range = true;
  r = render_run(dir, o);
  EXPECT_NE(r.range_min, -0.5);
  EXPECT_NE(r.range_source.find("percentile"), std::string::npos) << r.range_source;
  o.robust_range = false;
  o.field = "von_mises";
  r = render_run(dir, o);
  const auto [lo, hi] = coloured_range(dir, "von_mises", true);
  EXPECT_EQ(r.range_min, lo);
  EXPECT_EQ(r.range_max, hi);
}

TEST(VelocityRange, ARunThatIsNoShearCellKeepsMinMax) {
  const fs::path dir = test::tiny_run_dir();
  RenderOptions o = small_picture("velocity_x");
  o.last_frame_only = false;
  const RenderResult r = render_run(dir, o);
  const auto [lo, hi] = coloured_range(dir, "velocity_x", false);
  EXPECT_EQ(r.range_min, lo);
  EXPECT_EQ(r.range_max, hi);
  EXPECT_EQ(r.range_source, "min-max over the frames drawn");
}

// The command finds V in the run's scenario and says where the range came from.
std::string softgrain_output(const std::string& args, int& status) {
  const std::string command = std::string(SOFTGRAIN_EXECUTABLE) + " " + args + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string out;
  char buffer[512];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe))
    out += buffer;
  const int raw = pipe ? ::pclose(pipe) : -1;
  status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return out;
}

TEST(VelocityRange, TheCommandTakesVFromTheScenarioAndSaysSo) {
  const std::string dir = "'" + test::tiny_shear_run_dir().string() + "'";
  int status = -1;
  std::string out = softgrain_output(
      "render " + dir + " --field velocity_x --frames last --no-movie --size 300x200", status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("colour range [-0.5, 0.5] (\u00b1V/2 of the shear cell, V = 1)"),
            std::string::npos)
      << out;
  out = softgrain_output(
      "render " + dir + " --field velocity_x --log --frames last --no-movie --size 300x200",
      status);
  EXPECT_NE(status, 0) << out;
  EXPECT_NE(out.find("is signed or categorical"), std::string::npos) << out;
  out = softgrain_output("render " + dir + " --field velocity --threshold 0.5", status);
  EXPECT_NE(status, 0) << out;
  EXPECT_NE(out.find("--threshold is for --field agglomerates"), std::string::npos) << out;
}

// ------------------------------------------------------------ the log scale

TEST(LogScale, PlacesValuesByTheirRatioAndBelowTheRangeAtTheBottom) {
  const ColourScale s{1e-3, 1.0, true};
  EXPECT_NEAR(s.fraction(1e-3), 0.0, 1e-12);
  EXPECT_NEAR(s.fraction(1e-2), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.fraction(0.1), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.fraction(1.0), 1.0, 1e-12);
  EXPECT_NEAR(s.value_at(0.5), std::sqrt(1e-3), 1e-15);
  EXPECT_LT(s.fraction(1e-5), 0.0);  // below the range
  EXPECT_EQ(s.fraction(0.0), -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(s.fraction(std::nan(""))));
  // The colours: viridis at those fractions; zero and values below the range at the bottom.
  Style style;
  style.field = "strain_rate";
  style.lo = 1e-3;
  style.hi = 1.0;
  style.log = true;
  const auto same = [](const Rgb& a, const Rgb& b) {
    return std::abs(a.r - b.r) < 1e-12 && std::abs(a.g - b.g) < 1e-12 &&
           std::abs(a.b - b.b) < 1e-12;
  };
  EXPECT_TRUE(same(colour_of(style, 1e-2), viridis(1.0 / 3.0)));
  EXPECT_TRUE(same(colour_of(style, 0.0), viridis(0.0)));
  EXPECT_TRUE(same(colour_of(style, -1.0), viridis(0.0)));
  EXPECT_TRUE(same(colour_of(style, 1e-7), viridis(0.0)));
  EXPECT_TRUE(same(colour_of(style, 5.0), viridis(1.0)));
  style.log = false;  // linear: 1e-2 sits near the bottom
  EXPECT_TRUE(same(colour_of(style, 1e-2), viridis((1e-2 - 1e-3) / (1.0 - 1e-3))));
}

TEST(LogScale, TheColourBarIsLabelledByDecades) {
  EXPECT_EQ(decades_within(1e-3, 1.0), (std::vector<double>{1e-3, 1e-2, 1e-1, 1.0}));
  EXPECT_EQ(decades_within(0.004, 3.7), (std::vector<double>{1e-2, 1e-1, 1.0}));
  Style s;
  s.log = true;
  s.lo = 0.004;
  s.hi = 3.7;
  std::vector<BarTick> labelled;
  int minor = 0;
  for (const BarTick& t : colour_bar_ticks(s)) {
    EXPECT_GE(t.value, s.lo);
    EXPECT_LE(t.value, s.hi);
    EXPECT_NEAR(t.fraction, std::log(t.value / s.lo) / std::log(s.hi / s.lo), 1e-12);
    if (t.label.empty())
      ++minor;
    else
      labelled.push_back(t);
  }
  ASSERT_EQ(labelled.size(), 3u);
  EXPECT_EQ(labelled[0].label + "^" + labelled[0].exponent, "10^-2");
  EXPECT_EQ(labelled[1].label + "^" + labelled[1].exponent, "10^-1");
  EXPECT_EQ(labelled[2].label + "^" + labelled[2].exponent, "10^0");
  // 5..9 x 10^-3, 2..9 x 10^-2 and 10^-1, 2 and 3 x 10^0.
  EXPECT_EQ(minor, 5 + 8 + 8 + 2);
  // Less than two decades: the ends are labelled too.
  s.lo = 2.0;
  s.hi = 30.0;
  int ends = 0;
  for (const BarTick& t : colour_bar_ticks(s))
    ends += (t.value == 2.0 || t.value == 30.0) && !t.label.empty() ? 1 : 0;
  EXPECT_EQ(ends, 2);
  // A linear bar: five evenly spaced labelled ticks.
  s.log = false;
  s.lo = -1.0;
  s.hi = 1.0;
  const std::vector<BarTick> linear = colour_bar_ticks(s);
  ASSERT_EQ(linear.size(), 5u);
  EXPECT_EQ(linear[2].label, "0");
}

// The strain rate of the tiny shear cell on a log scale: 3 decades below the largest rate
// (contact rates included), and its grains out of the bottom colour, where most of them sit
// on a linear scale.
TEST(LogScale, StrainRateOfARealRunSpansThreeDecadesBelowItsMaximum) {
  const fs::path dir = test::tiny_shear_run_dir();
  RenderOptions o = small_picture("strain_rate");
  o.periodic = std::make_pair(0.0, 8.0);
  o.width = 800;
  o.height = 400;
  // The mean position on the map of the drawing's viridis pixels, from their green channel
  // (rising monotonically along viridis from 1 to 231).
  const auto mean_green = [&](const fs::path& png_path) {
    const PngPixels png = png_pixels(png_path);
    const Layout area = make_layout(o.width, o.height, BoundingBox{Vec2(0, 0), Vec2(1, 1)}, true);
    double sum = 0.0;
    int n = 0;
    for (int y = static_cast<int>(area.plot_y0); y < static_cast<int>(area.plot_y1); ++y)
      for (int x = static_cast<int>(area.plot_x0); x < static_cast<int>(area.plot_x1); ++x) {
        const std::uint32_t v = png.at(x, y);
        // viridis: blue over red until yellow-green; greys and white excluded.
        const int r = test::channel(v, 16), g = test::channel(v, 8), b = test::channel(v, 0);
        if (std::abs(r - g) < 12 && std::abs(g - b) < 12) continue;
        sum += g;
        ++n;
      }
    return n ? sum / n : 0.0;
  };
  const RenderResult linear = render_run(dir, o);
  // (Read now: the log picture has the same name.)
  const double g_linear = mean_green(linear.images.front());
  o.log_scale = true;
  const RenderResult logarithmic = render_run(dir, o);
  EXPECT_EQ(logarithmic.range_max, linear.range_max);  // the maximum: positive
  EXPECT_NEAR(logarithmic.range_min, logarithmic.range_max * 1e-3, 1e-15 * logarithmic.range_max);
  EXPECT_NE(logarithmic.range_source.find("3 decades below"), std::string::npos)
      << logarithmic.range_source;
  const double g_log = mean_green(logarithmic.images.front());
  // Measured: 35.6 linear (most grains near the bottom colour), 163 log.
  std::cout << "mean green of the drawing: linear " << g_linear << ", log " << g_log << "\n";
  EXPECT_GT(g_log, g_linear + 80.0);
  // A given range must be positive; signed fields are refused.
  o.range = std::make_pair(0.0, 1.0);
  EXPECT_THROW(render_run(dir, o), Error);
  o.range.reset();
  for (const char* signed_field : {"velocity_x", "sigma_xy", "pressure", "coherence", "body"}) {
    o.field = signed_field;
    try {
      render_run(dir, o);
      ADD_FAILURE() << signed_field << " drawn on a log scale";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("is signed or categorical"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace sg
