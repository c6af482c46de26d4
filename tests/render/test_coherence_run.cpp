// Agglomerates in `analyze`, coherence pictures and the plots, on a real tiny shear cell
// (tiny_run.h), plus the pieces they are built from (coherence_at, the script search).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "analysis/coherence_frames.h"
#include "core/error.h"
#include "core/version.h"
#include "render/plot_runner.h"
#include "render/png_reader.h"
#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"
#include "report/analyze_run.h"
#include "scenes/scenario_files.h"
#include "tiny_run.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

using Table = std::vector<std::map<std::string, std::string>>;

Table read_table(const fs::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  {
    std::stringstream h(line);
    std::string f;
    while (std::getline(h, f, ','))
      header.push_back(f);
  }
  Table rows;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    std::string f;
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (!std::getline(r, f, ',')) f.clear();  // an empty last cell
      row[header[c]] = f;
    }
    rows.push_back(row);
  }
  return rows;
}

double num(const std::map<std::string, std::string>& row, const std::string& key) {
  return std::stod(row.at(key));
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// ---------------------------------------------------------------- coherence_at

TEST(CoherenceAt, BilinearOverDefinedNodesAndPeriodicInX) {
  // A 4 x 3 grid (x0 = 1, L = 8: hx = 2; y0 = -1, hy = 2) holding C = 0.1 i - 0.2 j:
  // bilinear interpolation reproduces a field linear in i and j exactly, in the interior.
  CoherenceField f;
  f.grid = make_periodic_grid(1.0, 8.0, -1.0, 3.0, 2.0);
  ASSERT_EQ(f.grid.nx, 4);
  ASSERT_EQ(f.grid.ny, 3);
  f.value.resize(f.grid.size());
  f.defined.assign(f.grid.size(), 1);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      f.value[f.grid.index(i, j)] = 0.1 * i - 0.2 * j;
  const Vec2 p(1.0 + 2.0 * 1.25, -1.0 + 2.0 * 0.6);  // i = 1.25, j = 0.6
  EXPECT_NEAR(coherence_at(f, p), 0.1 * 1.25 - 0.2 * 0.6, 1e-15);
  // Across the seam: between column 3 (x = 7) and column 0 again (x = 9 = 1 + L), a quarter
  // of the way: 0.75 C(3, 0) + 0.25 C(0, 0) on row 0.
  EXPECT_NEAR(coherence_at(f, Vec2(7.5, -1.0)), 0.75 * 0.3 + 0.25 * 0.0, 1e-15);
  // The same point one period to the left.
  EXPECT_NEAR(coherence_at(f, Vec2(7.5 - 8.0, -1.0)), 0.75 * 0.3, 1e-15);
  // Undefined corners drop out and the weights are renormalised: with (2, 1) undefined,
  // the point (1.5, 0.5) averages the three others with weights 1/4 each -> their mean.
  f.defined[f.grid.index(2, 1)] = 0;
  const double others =
      (f.value[f.grid.index(1, 0)] + f.value[f.grid.index(2, 0)] + f.value[f.grid.index(1, 1)]) /
      3.0;
  EXPECT_NEAR(coherence_at(f, Vec2(1.0 + 2.0 * 1.5, -1.0 + 2.0 * 0.5)), others, 1e-15);
  // No defined corner, or beyond half a cell outside the rows: NaN.
  for (int i : {1, 2})
    for (int j : {0, 1})
      f.defined[f.grid.index(i, j)] = 0;
  EXPECT_TRUE(std::isnan(coherence_at(f, Vec2(1.0 + 2.0 * 1.5, -1.0 + 2.0 * 0.5))));
  EXPECT_TRUE(std::isnan(coherence_at(f, Vec2(2.0, -1.0 - 1.1))));  // 0.55 cell below row 0
  EXPECT_TRUE(std::isnan(coherence_at(f, Vec2(2.0, 3.0 + 1.1))));   // 0.55 cell above row 2
}

TEST(CoherenceSetup, PaddedGridForANonPeriodicRunWrapsNothing) {
  // Grains over x in [2, 6]: the padded period must exceed the span by more than twice the
  // reach of the fit and of the disc, so that neither sees across the artificial seam.
  GrainSnapshot s;
  for (double x : {2.0, 4.0, 6.0}) {
    s.position.emplace_back(x, 0.0);
    s.velocity.emplace_back(0.0, 0.0);
    s.area.push_back(std::numbers::pi * 0.25);
    s.body.push_back("0");
  }
  const std::vector<GrainSnapshot> snaps = {s};
  const CoherenceSetup c = choose_coherence_setup(snaps, 1.0, std::nullopt, std::nullopt);
  EXPECT_FALSE(c.periodic);
  const double reach = std::max(c.params.interpolation.support_radius, c.params.coherence.radius);
  EXPECT_GT(c.grid.length - 4.0, 2.0 * reach);
  EXPECT_LT(c.grid.x0, 2.0 - reach);
  EXPECT_EQ(c.params.coherence.radius, 2.5);
  EXPECT_EQ(c.params.interpolation.support_radius, 2.0);
  EXPECT_THROW(choose_coherence_setup(snaps, 0.0, std::nullopt, std::nullopt), Error);
  const CoherenceSetup p = choose_coherence_setup(snaps, 1.0, std::make_pair(0.0, 10.0), {});
  EXPECT_TRUE(p.periodic);
  EXPECT_EQ(p.grid.nx, 10);
  EXPECT_EQ(p.grid.x0, 0.0);
}

// ---------------------------------------------------------------- the tiny shear cell

class TinyShear : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { run_dir_ = test::tiny_shear_run_dir(); }
  static fs::path run_dir_;
};
fs::path TinyShear::run_dir_;

std::size_t grain_rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::size_t n = 0;
  std::getline(in, line);
  while (std::getline(in, line))
    n += line.empty() ? 0 : 1;
  return n;
}

// Checks the agglomerate outputs of one analysis against each other and the definitions.
void check_agglomerate_files(const fs::path& run_dir, const AnalyzeResult& r) {
  ASSERT_TRUE(r.agglomerates.has_value());
  const AgglomerateResult& a = *r.agglomerates;
  const nlohmann::json doc = read_json(run_dir / "analysis" / "summary.json");
  const auto& q = doc.at("quantities");
  const auto& ag = doc.at("agglomerates");
  const Table rows = read_table(run_dir / "analysis" / "agglomerates.csv");
  ASSERT_EQ(rows.size(), a.structures.size());
  EXPECT_EQ(q.at("structure_count").at("value").get<double>(), static_cast<double>(rows.size()));
  double positive = 0.0, samples_in = 0.0;
  for (const auto& row : rows) {
    const int sign = std::stoi(row.at("sign"));
    EXPECT_TRUE(sign == 1 || sign == -1);
    positive += sign > 0 ? 1.0 : 0.0;
    // lifetime = frames x period; D = 2 sqrt(A_bar / pi) (paper 002 §3.4).
    EXPECT_NEAR(num(row, "lifetime"), num(row, "frames") * a.frame_period, 1e-9);
    EXPECT_NEAR(num(row, "diameter"), 2.0 * std::sqrt(num(row, "mean_area") / std::numbers::pi),
                1e-9);
    EXPECT_LE(num(row, "frames"), num(row, "last_frame") - num(row, "first_frame") + 1.0);
    samples_in += num(row, "grain_samples");
    if (!row.at("omega").empty() && !row.at("omega_tilde").empty()) {  // eq. 7: V = 1, D = 2.6
      EXPECT_NEAR(num(row, "omega_tilde"), num(row, "omega") / (-1.0 / 2.6), 1e-9);
    }
  }
  EXPECT_EQ(q.at("structure_count_positive").at("value").get<double>(), positive);
  EXPECT_EQ(samples_in, ag.at("grain_samples_in_structures").get<double>());
  EXPECT_NEAR(q.at("grain_share_in_structures").at("value").get<double>(),
              samples_in / ag.at("grain_samples").get<double>(), 1e-15);
  // Only the 20 grains are samples: the first bodies (rows 0 and 1 of grains/*.csv) are
  // not. Each window frame holds the 20 grains.
  const std::size_t frames = ag.at("frames").get<std::size_t>();
  EXPECT_EQ(ag.at("grain_samples").get<std::size_t>(), 20 * frames);
  EXPECT_EQ(grain_rows(run_dir / "grains" / "000000.csv"), 22u);
  // PDFs: each quantity's densities integrate to 1 when there is a structure with grains.
  const Table pdf = read_table(run_dir / "analysis" / "agglomerate_pdfs.csv");
  std::map<std::string, double> integral;
  for (const auto& row : pdf)
    integral[row.at("quantity")] += num(row, "density") * (num(row, "bin_hi") - num(row, "bin_lo"));
  ASSERT_EQ(integral.size(), 3u);
  for (const auto& [quantity, total] : integral)
    EXPECT_NEAR(total, samples_in > 0.0 ? 1.0 : 0.0, 1e-9) << quantity;
}

TEST_F(TinyShear, AnalyzeWritesAgglomeratesConsistentWithTheirDefinitions) {
  AnalyzeOptions o;
  const AnalyzeResult r = analyze_run(run_dir_, o);
  EXPECT_EQ(r.agglomerates_path, run_dir_ / "analysis" / "agglomerates.csv");
  EXPECT_EQ(r.agglomerate_pdfs_path, run_dir_ / "analysis" / "agglomerate_pdfs.csv");
  check_agglomerate_files(run_dir_, r);
  const nlohmann::json doc = read_json(r.summary_path);
  EXPECT_FALSE(doc.at("quantities").at("structure_count").at("value").is_null());
  // The window's snapshots: those of grains/*.csv whose time lies in the window.
  const double t0 = doc.at("quantities").at("window_begin").at("value").get<double>();
  const double t1 = doc.at("quantities").at("window_end").at("value").get<double>();
  std::size_t inside = 0;
  for (const PvdEntry& e : read_pvd(run_dir_ / "fields.pvd"))
    inside += e.time >= t0 - 1e-9 && e.time <= t1 + 1e-9 ? 1 : 0;
  EXPECT_EQ(doc.at("agglomerates").at("frames").get<std::size_t>(), inside);
  EXPECT_NEAR(doc.at("agglomerates").at("grid_spacing").get<double>(),
              8.0 / std::round(8.0 / r.parameters.mean_diameter), 1e-12);
}

TEST_F(TinyShear, ALowerThresholdFindsStructuresAndTheirStatistics) {
  // A 2.6-diameter layer is too thin for |C| > 0.8 (the shear alone gives |C| = 0.71); a
  // threshold of 0.3 marks most of it, so the per-structure checks have rows to check.
  AnalyzeOptions o;
  o.coherence_threshold = 0.3;
  const AnalyzeResult r = analyze_run(run_dir_, o);
  ASSERT_TRUE(r.agglomerates.has_value());
  ASSERT_GT(r.agglomerates->structures.size(), 0u);
  check_agglomerate_files(run_dir_, r);
  const nlohmann::json doc = read_json(r.summary_path);
  EXPECT_EQ(doc.at("agglomerates").at("threshold").get<double>(), 0.3);
  EXPECT_FALSE(doc.at("quantities").at("omega_tilde_mean").at("value").is_null());
  EXPECT_FALSE(doc.at("quantities").at("structure_diameter_mode").at("value").is_null());
  // A threshold outside (0, 1) is refused by the library: null + a note, no throw.
  o.coherence_threshold = 1.0;
  const AnalyzeResult bad = analyze_run(run_dir_, o);
  EXPECT_FALSE(bad.summary.agglomerates.has_value());
  bool noted = false;
  for (const auto& n : bad.notes)
    noted = noted || n.find("agglomerates not computed") != std::string::npos;
  EXPECT_TRUE(noted);
}

// The space-time picture's cells and the cylinders agree with the structures; the activated
// thickness lies within the gap, one row per window snapshot.
TEST_F(TinyShear, AnalyzeWritesTheSpaceTimeCellsTheCylindersAndTheActivatedThickness) {
  AnalyzeOptions o;
  o.coherence_threshold = 0.3;
  const AnalyzeResult r = analyze_run(run_dir_, o);
  ASSERT_TRUE(r.agglomerates.has_value());
  const Table cylinders = read_table(r.cylinders_path);
  ASSERT_EQ(cylinders.size(), r.agglomerates->structures.size());
  for (std::size_t k = 0; k < cylinders.size(); ++k) {
    const Structure& st = r.agglomerates->structures[k];
    EXPECT_NEAR(num(cylinders[k], "height"), st.lifetime, 1e-9);
    EXPECT_NEAR(num(cylinders[k], "diameter"), st.diameter, 1e-9);
    EXPECT_GE(num(cylinders[k], "x_center"), 0.0);
    EXPECT_LT(num(cylinders[k], "x_center"), 8.0);
  }
  // One row per labelled cell.
  const Table cells = read_table(r.space_time_path);
  const auto marked = static_cast<std::size_t>(std::count_if(r.agglomerates->labels.label.begin(),
                                                             r.agglomerates->labels.label.end(),
                                                             [](int l) { return l >= 0; }));
  EXPECT_EQ(cells.size(), marked);
  // ATT: D = 2.6 known, V = 1; both measures within [0, D]; one row per window snapshot.
  ASSERT_TRUE(r.att.has_value());
  const Table att = read_table(r.att_path);
  EXPECT_EQ(att.size(), static_cast<std::size_t>(r.agglomerates->labels.nt));
  for (const auto& row : att) {
    EXPECT_GE(num(row, "att_map"), 0.0);
    EXPECT_LE(num(row, "att_map"), 2.6 + 1e-12);
    EXPECT_GE(num(row, "att_profile"), 0.0);
  }
  EXPECT_TRUE(std::isfinite(r.summary.att_map));
  const nlohmann::json doc = read_json(r.summary_path);
  EXPECT_EQ(doc.at("att").at("threshold_low").get<double>(), 0.2);
  EXPECT_EQ(doc.at("att").at("layer_thickness").get<double>(), 2.6);
}

TEST_F(TinyShear, CoherencePicturesHaveTheSizeAndTheFixedRange) {
  RenderOptions o;
  o.field = "coherence";
  o.width = 360;
  o.height = 180;
  o.movie = false;
  o.periodic = std::make_pair(0.0, 8.0);
  o.non_grain_rows = {"0", "1"};  // bottom, top
  const RenderResult r = render_run(run_dir_, o);
  ASSERT_EQ(r.images.size(), read_pvd(run_dir_ / "fields.pvd").size());
  ASSERT_TRUE(r.has_range);
  EXPECT_EQ(r.range_min, -1.0);
  EXPECT_EQ(r.range_max, 1.0);
  for (const fs::path& png : r.images)
    EXPECT_EQ(png_size(png), std::make_pair(360, 180)) << png;
  EXPECT_EQ(r.images.front().filename(), "coherence_000000.png");
  // A missing grain snapshot is named.
  const fs::path moved = run_dir_.parent_path() / "000001.csv";
  fs::rename(run_dir_ / "grains" / "000001.csv", moved);
  try {
    render_run(run_dir_, o);
    ADD_FAILURE() << "rendered without grains/000001.csv";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("000001.csv"), std::string::npos) << e.what();
  }
  fs::rename(moved, run_dir_ / "grains" / "000001.csv");
}

// Width and height from a PNG's signature and IHDR chunk (PNG spec, §5.2-5.3, §11.2.2).
std::pair<long, long> png_header_size(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char b[24] = {};
  in.read(reinterpret_cast<char*>(b), 24);
  if (in.gcount() != 24) return {-1, -1};
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!std::equal(signature, signature + 8, b) || std::string(b + 12, b + 16) != "IHDR")
    return {-1, -1};
  auto be32 = [&](int k) {
    return (static_cast<long>(b[k]) << 24) | (static_cast<long>(b[k + 1]) << 16) |
           (static_cast<long>(b[k + 2]) << 8) | static_cast<long>(b[k + 3]);
  };
  return {be32(16), be32(20)};
}

TEST_F(TinyShear, PlotScriptDrawsValidPngs) {
  if (!python_has_matplotlib()) GTEST_SKIP() << kPlotPython << " cannot import matplotlib";
  AnalyzeOptions o;
  o.coherence_threshold = 0.3;  // so that the PDFs panel has structures
  analyze_run(run_dir_, o);
  std::vector<fs::path> tried;
  const auto script = find_plot_script(current_executable(), &tried);
  ASSERT_TRUE(script.has_value()) << "plot_run.py not found";
  const fs::path analysis = run_dir_ / "analysis";
  for (const char* name : {"mu.png", "profiles.png", "energy.png", "agglomerate_pdfs.png",
                           "space_time.png", "cylinders.png", "att.png"})
    fs::remove(analysis / name);
  ASSERT_EQ(run_plot_script(*script, run_dir_), 0);
  // Figure sizes (inches) x 110 dpi, as plot_run.py draws them.
  const std::map<std::string, std::pair<long, long>> expected = {
      {"mu.png", {880, 462}},          {"profiles.png", {880, 462}},
      {"energy.png", {880, 462}},      {"agglomerate_pdfs.png", {1210, 418}},
      {"space_time.png", {1210, 462}}, {"cylinders.png", {880, 660}},
      {"att.png", {880, 462}}};
  const nlohmann::json doc = read_json(analysis / "summary.json");
  for (const auto& [name, size] : expected) {
    const fs::path png = analysis / name;
    // The energy picture needs the budget, which the engine's bookkeeping may leave null.
    if (name == "energy.png" && doc.at("quantities").at("bulk_share").at("value").is_null()) {
      EXPECT_FALSE(fs::exists(png));
      continue;
    }
    ASSERT_TRUE(fs::exists(png)) << png;
    EXPECT_GT(fs::file_size(png), 1000u) << png;
    EXPECT_EQ(png_header_size(png), size) << png;
    EXPECT_FALSE(fs::exists(png.string() + ".tmp.png"));
    // The PNG text "Software" names the softgrain of summary.json (matplotlib: a tEXt chunk).
    std::ifstream in(png, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(bytes.find(std::string("Software") + '\0' + softgrain_version_line()),
              std::string::npos)
        << png;
  }
  // A folder that was never analysed: one line, non-zero status, nothing drawn.
  const fs::path empty = run_dir_.parent_path() / "not_analysed";
  fs::create_directories(empty);
  EXPECT_EQ(run_plot_script(*script, empty), 1);
  EXPECT_FALSE(fs::exists(empty / "analysis" / "mu.png"));
}

TEST(PlotScript, InstalledLayoutComesFirst) {
  // <prefix>/bin/softgrain finds <prefix>/share/softgrain/plot_run.py before the source tree.
  const fs::path prefix = scenes::process_temp_dir("install");
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share" / "softgrain");
  std::ofstream(prefix / "share" / "softgrain" / "plot_run.py") << "# stand-in\n";
  std::vector<fs::path> tried;
  const auto found = find_plot_script(prefix / "bin" / "softgrain", &tried);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(*found, prefix / "share" / "softgrain" / "plot_run.py");
  EXPECT_EQ(tried.size(), 1u);
  // Without it: the build tree's scripts/plot_run.py, the fallback.
  fs::remove(prefix / "share" / "softgrain" / "plot_run.py");
  tried.clear();
  const auto fallback = find_plot_script(prefix / "bin" / "softgrain", &tried);
  ASSERT_TRUE(fallback.has_value());
  EXPECT_EQ(fallback->filename(), "plot_run.py");
  EXPECT_EQ(fallback->parent_path().filename(), "scripts");
  EXPECT_EQ(tried.size(), 2u);
  fs::remove_all(prefix);
}

}  // namespace
}  // namespace sg
