// The figures of issue #29 (items 4 and 5) for the example campaign, end to end with the real
// executable: examples/campaign-pressure.toml (2 x 2 runs in (E~, c~) at one requested alpha~)
// on the tiny pressure-loaded cell of the campaign tests (tests/scenes/shear_cell_scenario.h),
// swept with its plots. Every run's analysis/composite.png (scripts/plot_run.py, with the
// three snapshots `analyze` draws into render/) and every campaign figure
// (scripts/plot_campaign.py --all) is there, non-empty, of the size its script draws it, and
// names the softgrain that made it in its PNG text "Software".
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/version.h"
#include "scenes/scenario_files.h"
#include "scenes/shear_cell_scenario.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Width and height from a PNG's signature and IHDR chunk (PNG spec, §5.2-5.3, §11.2.2);
// (-1, -1) if the file is not a PNG.
std::pair<long, long> png_header_size(const fs::path& path) {
  const std::string b = read(path);
  const std::string signature = "\x89PNG\r\n\x1a\n";
  if (b.size() < 24 || b.compare(0, 8, signature) != 0 || b.compare(12, 4, "IHDR") != 0)
    return {-1, -1};
  auto be32 = [&](std::size_t k) {
    long v = 0;
    for (std::size_t i = k; i < k + 4; ++i)
      v = (v << 8) | static_cast<unsigned char>(b[i]);
    return v;
  };
  return {be32(16), be32(20)};
}

// The figure is there, non-empty, `size` pixels, and names this softgrain.
void expect_figure(const fs::path& png, std::pair<long, long> size) {
  SCOPED_TRACE(png.string());
  ASSERT_TRUE(fs::exists(png));
  EXPECT_GT(fs::file_size(png), 1000u);
  EXPECT_EQ(png_header_size(png), size);
  EXPECT_FALSE(fs::exists(png.string() + ".tmp.png"));
  // The figure names the softgrain that analysed the runs (matplotlib: a tEXt chunk).
  const std::string build = std::string("softgrain ") + std::string(softgrain_version());
  EXPECT_NE(read(png).find(std::string("Software") + '\0' + build), std::string::npos);
  EXPECT_NE(read(png).find(std::string(softgrain_commit())), std::string::npos);
}

// correlations.csv's pairs with coefficients: the panels of correlations.png.
int pairs_with_coefficients(const fs::path& csv) {
  std::istringstream in(read(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "x,y,n,pearson,spearman");
  int with = 0, rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    std::vector<std::string> cells(1);
    for (char c : line)
      if (c == ',')
        cells.emplace_back();
      else
        cells.back() += c;
    EXPECT_EQ(cells.size(), 5u) << line;
    if (cells.size() == 5 && !cells[3].empty()) ++with;
  }
  EXPECT_EQ(rows, 10);  // plot_campaign.py's DEFAULT_PAIRS
  return with;
}

TEST(CampaignFigures, TheExampleCampaignDrawsTheCompositeAndTheCampaignFigures) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib, numpy, scipy' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "/usr/bin/python3 without matplotlib, numpy and scipy: no figures";
  const fs::path dir = scenes::process_temp_dir("campaign_figures");
  // The example as written, on the tiny cell (one field snapshot a time unit: 5 frames), its
  // window the cell's steady [2.5, 4].
  std::ofstream(dir / "cell.toml") << scenes::tiny_pressure_cell(1.0, "1.0");
  std::string campaign =
      read(fs::path(SOFTGRAIN_SOURCE_DIR) / "examples" / "campaign-pressure.toml");
  campaign = scenes::replace_once(campaign, "scenario = \"shear-cell-pressure.toml\"",
                                  "scenario = \"cell.toml\"");
  campaign = scenes::replace_once(campaign, "output = \"../out/campaigns\"", "output = \"out\"");
  campaign = scenes::replace_once(campaign, "analyze_options = [\"--no-agglomerates\"]",
                                  "analyze_options = [\"--window\", \"2.5\", \"4\", "
                                  "\"--no-agglomerates\"]");
  std::ofstream(dir / "campaign.toml") << campaign;
  const std::string command = std::string(SOFTGRAIN_EXECUTABLE) + " sweep '" +
                              (dir / "campaign.toml").string() + "' > '" +
                              (dir / "sweep.log").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read(dir / "sweep.log");
  const fs::path folder = dir / "out" / "pressure";

  // Each run: its composite (16 x 10 inches at 110 dpi), made with the three snapshots of the
  // last frame that analyze drew (1200 x 300 pixels: render/composite_snapshots.cpp).
  int runs = 0;
  for (const auto& entry : fs::directory_iterator(folder / "runs")) {
    ++runs;
    SCOPED_TRACE(entry.path().filename().string());
    expect_figure(entry.path() / "analysis" / "composite.png", {1760, 1100});
    for (const char* field : {"velocity_x", "strain_rate", "von_mises"}) {
      const fs::path png = entry.path() / "render" / (std::string(field) + "_000004.png");
      EXPECT_EQ(png_header_size(png), std::make_pair(1200L, 300L)) << png;
      EXPECT_FALSE(fs::exists(entry.path() / "render" / (std::string(field) + "_000003.png")))
          << field << ": only the last frame is drawn";
    }
  }
  EXPECT_EQ(runs, 4);

  // The campaign figures: one alpha~ slice, the one the campaign requested.
  const std::map<std::string, std::pair<long, long>> figures = {
      {"mu_map.png", {768, 576}},                  // 6.4 x 4.8 in at 120 dpi
      {"campaign_points.png", {704, 572}},         // 6.4 x 5.2 in at 110 dpi
      {"mu_vs_stress.png", {704, 484}},            // 6.4 x 4.4 in at 110 dpi
      {"bulk_share_vs_cohesion.png", {792, 528}},  // 7.2 x 4.8 in at 110 dpi
      {"maps_alpha=-2.5.png", {1300, 760}}};       // 13 x 7.6 in at 100 dpi
  for (const auto& [name, size] : figures)
    expect_figure(folder / name, size);
  // correlations.png: one 4.4 x 3.8 in panel (100 dpi) per pair with coefficients, three to a
  // line; the others are left out. Without agglomerates the structures' pairs have none.
  const int panels = pairs_with_coefficients(folder / "correlations.csv");
  EXPECT_GE(panels, 4);  // mu against the ATT, E~ and c~; the ATT against alpha~
  EXPECT_LT(panels, 10);
  const long columns = std::min(3, panels), lines = (panels + 2) / 3;
  expect_figure(folder / "correlations.png", {440 * columns, 380 * lines});
}

}  // namespace
}  // namespace sg
