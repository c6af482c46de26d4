// Pictures and the analyze driver on a real (tiny) run: a soft grain pressed on a floor
// next to a rigid grain, simulated here, then drawn and analysed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "render/png_reader.h"
#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"
#include "report/analyze_run.h"
#include "tiny_run.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

class RenderOnTinyRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { run_dir_ = test::tiny_run_dir(); }
  static fs::path run_dir_;
};
fs::path RenderOnTinyRun::run_dir_;

// Min and max of a point field over the points of the triangles, read straight from the
// DataArray of every snapshot (the range the colour bar must show).
std::pair<double, double> triangle_field_range(const fs::path& run_dir, const std::string& name) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const PvdEntry& e : read_pvd(run_dir / "fields.pvd")) {
    const VtuMesh m = read_vtu(e.file);
    const VtuArray* a = m.find(name);
    EXPECT_NE(a, nullptr) << name;
    if (!a) continue;
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
      if (m.types[c] != kVtkTriangle) continue;
      for (int p : m.cell(c)) {
        lo = std::min(lo, a->values[static_cast<std::size_t>(p)]);
        hi = std::max(hi, a->values[static_cast<std::size_t>(p)]);
      }
    }
  }
  return {lo, hi};
}

TEST_F(RenderOnTinyRun, VtuReaderReadsOurSnapshots) {
  const auto entries = read_pvd(run_dir_ / "fields.pvd");
  ASSERT_GE(entries.size(), 3u);  // t = 0, 0.02, 0.04 and the final state
  const VtuMesh m = read_vtu(entries.back().file);
  std::size_t triangles = 0, polygons = 0;
  for (int t : m.types)
    (t == kVtkTriangle ? triangles : polygons) += 1;
  EXPECT_GT(triangles, 20u);  // the soft grain's triangulation
  EXPECT_EQ(polygons, 2u);    // the rigid grain and the floor
  for (const char* f : {"von_mises", "velocity", "pressure", "green_lagrange_norm", "body_id"})
    EXPECT_NE(m.find(f), nullptr) << f;
  // velocity magnitude and components agree
  const auto speed = point_scalar(m, "velocity");
  const auto vx = point_scalar(m, "velocity_x");
  const auto vy = point_scalar(m, "velocity_y");
  for (std::size_t p = 0; p < m.points.size(); ++p)
    EXPECT_NEAR(speed[p], std::hypot(vx[p], vy[p]), 1e-12 * (1.0 + speed[p]));
  EXPECT_THROW(point_scalar(m, "no_such_field"), Error);
}

TEST_F(RenderOnTinyRun, VtuReaderRefusesATruncatedFile) {
  const auto entries = read_pvd(run_dir_ / "fields.pvd");
  std::ifstream in(entries.front().file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string full = text.str();
  const fs::path bad = run_dir_.parent_path() / "truncated.vtu";
  std::ofstream(bad) << full.substr(0, full.size() / 2);
  try {
    read_vtu(bad);
    FAIL() << "a truncated file was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("truncated.vtu"), std::string::npos) << e.what();
  }
}

TEST_F(RenderOnTinyRun, PicturesHaveTheRequestedSizeAndTheSeriesRange) {
  RenderOptions o;
  o.field = "von_mises";
  o.width = 320;
  o.height = 200;
  o.movie = false;
  const RenderResult r = render_run(run_dir_, o);
  const auto entries = read_pvd(run_dir_ / "fields.pvd");
  ASSERT_EQ(r.images.size(), entries.size());
  for (const fs::path& png : r.images) {
    EXPECT_EQ(png.parent_path(), run_dir_ / "render");
    EXPECT_EQ(png_size(png), std::make_pair(320, 200)) << png;
  }
  EXPECT_EQ(r.images.front().filename(), "von_mises_000000.png");
  // The colour bar spans the field over every frame: the grain is pressed, so > 0.
  const auto [lo, hi] = triangle_field_range(run_dir_, "von_mises");
  ASSERT_TRUE(r.has_range);
  EXPECT_EQ(r.range_min, lo);
  EXPECT_EQ(r.range_max, hi);
  EXPECT_GT(hi, 0.0);
}

TEST_F(RenderOnTinyRun, GivenRangeAndLastFrame) {
  RenderOptions o;
  o.field = "pressure";
  o.width = 400;
  o.height = 300;
  o.range = std::make_pair(-1.0, 2.0);
  o.last_frame_only = true;
  const RenderResult r = render_run(run_dir_, o);
  ASSERT_EQ(r.images.size(), 1u);
  EXPECT_EQ(r.range_min, -1.0);
  EXPECT_EQ(r.range_max, 2.0);
  EXPECT_EQ(png_size(r.images.front()), std::make_pair(400, 300));
  o.range = std::make_pair(2.0, 1.0);
  EXPECT_THROW(render_run(run_dir_, o), Error);
  o.range.reset();
  o.field = "no_such_field";
  EXPECT_THROW(render_run(run_dir_, o), Error);
}

// The MP4: one frame per snapshot at the picture size, counted by ffprobe (the run still
// succeeds without ffmpeg on PATH, with a note saying why there is no movie).
TEST_F(RenderOnTinyRun, MovieHasEveryFrameWhenFfmpegIsThere) {
  RenderOptions o;
  o.field = "velocity";
  o.width = 320;
  o.height = 200;
  const char* path = std::getenv("PATH");
  const std::string saved = path ? path : "";
  ::setenv("PATH", "", 1);  // no ffmpeg to be found
  const RenderResult without = render_run(run_dir_, o);
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_TRUE(without.movie.empty());
  EXPECT_NE(without.note.find("ffmpeg not found"), std::string::npos) << without.note;
  EXPECT_EQ(without.images.size(), read_pvd(run_dir_ / "fields.pvd").size());

  // ffmpeg is a dependency (scripts/install-deps.sh): the movie is checked, not skipped.
  ASSERT_EQ(
      std::system("command -v ffmpeg > /dev/null 2>&1 && command -v ffprobe > /dev/null 2>&1"), 0)
      << "ffmpeg/ffprobe not installed (scripts/install-deps.sh installs them)";
  const RenderResult r = render_run(run_dir_, o);
  ASSERT_FALSE(r.movie.empty()) << r.note;
  ASSERT_TRUE(fs::exists(r.movie));
  const std::string probe =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=width,height,nb_read_frames -of csv=p=0 '" +
      r.movie.string() + "'";
  FILE* pipe = ::popen(probe.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char line[256] = {};
  const bool read = std::fgets(line, sizeof line, pipe) != nullptr;
  ::pclose(pipe);
  ASSERT_TRUE(read) << probe;
  EXPECT_EQ(std::string(line), "320,200," + std::to_string(r.images.size()) + "\n");
}

TEST_F(RenderOnTinyRun, BodyFieldHasNoRangeAndTheGrainIsDrawn) {
  RenderOptions o;
  o.field = "body";
  o.width = 300;
  o.height = 200;
  o.last_frame_only = true;
  const RenderResult r = render_run(run_dir_, o);
  EXPECT_FALSE(r.has_range);
  ASSERT_EQ(r.images.size(), 1u);
  EXPECT_EQ(png_size(r.images.front()), std::make_pair(300, 200));
}

// Reads one numeric column of series.csv.
std::vector<double> series_column(const fs::path& path, const std::string& name) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  std::string field;
  int index = -1, k = 0;
  while (std::getline(header, field, ','))
    if (field == name)
      index = k;
    else
      ++k;
  EXPECT_GE(index, 0) << name;
  std::vector<double> out;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    for (int c = 0; std::getline(row, field, ','); ++c)
      if (c == index) out.push_back(std::stod(field));
  }
  return out;
}

TEST_F(RenderOnTinyRun, AnalyzeWritesTheSummaryWithTheSeriesEnergies) {
  const AnalyzeResult r = analyze_run(run_dir_, AnalyzeOptions{});
  const fs::path json_path = run_dir_ / "analysis" / "summary.json";
  ASSERT_EQ(r.summary_path, json_path);
  std::ifstream in(json_path);
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc.at("format"), "softgrain-analysis-summary");
  EXPECT_EQ(doc.at("version"), 1);
  const auto& q = doc.at("quantities");
  for (const char* key :
       {"mu", "mu_std", "normal_stress", "shear_stress", "stiffness_tilde", "cohesion_tilde",
        "viscosity_tilde", "bulk_share", "contact_share", "bulk_friction", "contact_friction",
        "bulk_power", "contact_power", "external_power", "solid_fraction", "structure_count"})
    EXPECT_TRUE(q.contains(key)) << key;
  // No shear cell: friction is null, and a note says why.
  EXPECT_TRUE(q.at("mu").at("value").is_null());
  bool explained = false;
  for (const auto& n : doc.at("notes"))
    explained = explained || n.get<std::string>().find("'top'") != std::string::npos;
  EXPECT_TRUE(explained);
  // Window = the whole run; the energy rates are the increments of series.csv over it.
  const fs::path series = run_dir_ / "series.csv";
  const auto t = series_column(series, "time");
  const auto damp = series_column(series, "damping_dissipation");
  const auto cont = series_column(series, "contact_dissipation");
  const auto work = series_column(series, "external_work");
  ASSERT_GE(t.size(), 10u);
  const double duration = t.back() - t.front();
  const double tol = 1e-9;
  EXPECT_NEAR(q.at("bulk_power").at("value").get<double>(), (damp.back() - damp.front()) / duration,
              tol);
  EXPECT_NEAR(q.at("contact_power").at("value").get<double>(),
              (cont.back() - cont.front()) / duration, tol);
  EXPECT_NEAR(q.at("external_power").at("value").get<double>(),
              (work.back() - work.front()) / duration, tol);
  EXPECT_NEAR(q.at("bulk_share").at("value").get<double>() +
                  q.at("contact_share").at("value").get<double>(),
              1.0, 1e-12);
  // Parameters the scenario gives, with their source; the others null.
  const auto& p = doc.at("parameters");
  EXPECT_EQ(p.at("young_modulus").at("value"), 10.0);
  EXPECT_NE(p.at("young_modulus").at("source").get<std::string>().find("scenario"),
            std::string::npos);
  EXPECT_TRUE(p.at("length").at("value").is_null());
  EXPECT_TRUE(q.at("solid_fraction").at("value").is_null());
  // Mean diameter from the grains' areas: the soft disc (r 0.5) and the rigid one (r 0.4),
  // the floor excluded. Polygonal contours make the areas a little smaller than pi r^2.
  EXPECT_NEAR(p.at("mean_diameter").at("value").get<double>(), 0.9, 0.02);
  EXPECT_TRUE(fs::exists(run_dir_ / "analysis" / "profiles.csv"));
}

TEST_F(RenderOnTinyRun, AnalyzeRefusesAFolderWithoutSeries) {
  EXPECT_THROW(analyze_run(run_dir_ / "fields", AnalyzeOptions{}), Error);
}

}  // namespace
}  // namespace sg
