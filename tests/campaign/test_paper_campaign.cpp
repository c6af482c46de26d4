// A campaign in the papers' coordinates (campaign/paper_coordinates.h), end to end with the
// real executable: a 2 x 2 campaign in (E~, c~) of tiny pressure-loaded shear cells at one
// requested alpha~, its scenarios (E = p 10^E~, c = p 10^c~, alpha = 10^alpha~ D / V), the
// table with the requested and the realized coordinates and mu of every run, every campaign
// figure, and every coefficient of the correlation table checked against a direct
// computation on campaign.csv.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "campaign/campaign_def.h"
#include "core/error.h"
#include "core/version.h"
#include "scenes/scenario_files.h"
#include "scenes/shear_cell_scenario.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;
using Table = std::vector<std::map<std::string, std::string>>;

constexpr double kPressure = 1.0;

fs::path campaign_dir() {
  return scenes::process_temp_dir("paper_campaign");
}

// 16 soft grains, L = 6, 4 time units (load ramped over 0.4; a light top, density 0.1, with a
// servo damping of 0.5), under p = 1: E = 31.6 and 100 then make a shear wave (~ sqrt(E/rho),
// 6 to 10) fast against V = 1, and the layer carries the load without the top lifting off:
// Fn > 0 on every row of the window [2.5, 4] of every run, mu and the realized E~, c~ are
// measured. (Under p = 0.1, E = 3 to 10 and V about the wave speed, the top and the bottom
// lost contact on 15-90% of the window's rows and mu was null.) The papers' damping
// (alpha~ = -1.5, alpha ~ 0.1) integrated implicitly (integrator = "imex"): about 1 s per
// run, where the damping-limited explicit step took 4-5 s.
Table read_csv(const fs::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream h(line);
  for (std::string f; std::getline(h, f, ',');)
    header.push_back(f);
  Table rows;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    std::map<std::string, std::string> row;
    for (const std::string& k : header) {
      std::string f;
      if (!std::getline(r, f, ',')) f.clear();
      row[k] = f;
    }
    rows.push_back(row);
  }
  return rows;
}

double number(const std::string& s) {
  return s.empty() ? NAN : std::stod(s);
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxy / std::sqrt(sxx * syy);
}

// Ranks 1..n, ties given their mean rank (Spearman's rho = Pearson's r of the ranks).
std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]])
      ++j;
    for (std::size_t k = i; k <= j; ++k)
      r[order[k]] = 0.5 * static_cast<double>(i + j) + 1.0;
    i = j + 1;
  }
  return r;
}

TEST(PaperCampaign, ATinyCampaignInETildeAndCTildeGivesEveryFigure) {
  const fs::path dir = campaign_dir();
  std::ofstream(dir / "cell.toml") << scenes::tiny_pressure_cell(0.1, std::to_string(kPressure));
  std::ofstream(dir / "campaign.toml") << R"(name = "paper"
scenario = "cell.toml"
output = "out"
parallel = 2
threads = 1
analyze_options = ["--window", "2.5", "4", "--no-plots"]
[grid]
stiffness_tilde = [1.5, 2.0]
cohesion_tilde = [-1.0, 0.0]
[[list]]
viscosity_tilde = -1.5
)";
  // The runs' scenarios: the physical values the coordinates give.
  const CampaignDef def = load_campaign(dir / "campaign.toml");
  ASSERT_EQ(def.runs.size(), 4u);
  const CampaignRun& last = def.runs.back();  // E~ = 2, c~ = 0
  std::map<std::string, double> set;
  for (const auto& [key, text] : last.derived)
    set[key] = std::stod(text);
  EXPECT_NEAR(set.at("materials.0.young"), kPressure * 100.0, 1e-12);
  EXPECT_NEAR(set.at("contact_laws.0.cohesion"), kPressure, 1e-12);
  EXPECT_NEAR(set.at("contact_laws.1.cohesion"), kPressure, 1e-12);
  ASSERT_TRUE(set.count("materials.0.damping"));
  const double packed_gap = set.at("materials.0.damping") / std::pow(10.0, -1.5);  // V = 1
  EXPECT_GT(packed_gap, 1.0);  // 16 grains of diameter ~1 over L = 6: two to four layers
  EXPECT_LT(packed_gap, 6.0);

  const std::string command = std::string(SOFTGRAIN_EXECUTABLE) + " sweep '" +
                              (dir / "campaign.toml").string() + "' > '" +
                              (dir / "sweep.log").string() + "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const fs::path folder = dir / "out" / "paper";
  const Table table = read_csv(folder / "campaign.csv");
  ASSERT_EQ(table.size(), 4u);
  for (const auto& row : table) {
    EXPECT_EQ(row.at("status"), "done") << row.at("id");
    // Requested and realized coordinates side by side; sigma_n ~ p, alpha~ from the measured D.
    EXPECT_NEAR(number(row.at("viscosity_tilde_requested")), -1.5, 1e-12);
    const double realized = number(row.at("viscosity_tilde"));
    ASSERT_TRUE(std::isfinite(realized)) << row.at("id") << ": realized alpha~ missing";
    EXPECT_LT(std::abs(realized + 1.5), 0.25) << row.at("id");  // D compacts, in one map slice
    EXPECT_TRUE(std::isfinite(number(row.at("att_map"))));
    // mu measured, and sigma_n = p within 25% (the realized E~, c~ within log10(1.25) = 0.1).
    const double mu = number(row.at("mu"));
    ASSERT_TRUE(std::isfinite(mu)) << row.at("id") << ": mu missing";
    EXPECT_GT(mu, 0.0) << row.at("id");
    for (const char* k : {"stiffness_tilde", "cohesion_tilde"}) {
      const double requested = number(row.at(std::string(k) + "_requested"));
      EXPECT_NEAR(number(row.at(k)), requested, 0.1) << row.at("id") << " " << k;
    }
  }
  if (std::system("/usr/bin/python3 -c 'import matplotlib, scipy' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "/usr/bin/python3 without matplotlib and scipy: no figures to check";
  // Every campaign figure (scripts/plot_campaign.py --all): one map slice, alpha~ = -1.5.
  // Each names the softgrain that analysed the runs (campaign.csv's `softgrain`) in its PNG
  // text "Software" (matplotlib writes it as an uncompressed tEXt chunk).
  const std::string build =
      "softgrain " + std::string(softgrain_version()) + " " + std::string(softgrain_commit());
  for (const char* png : {"mu_map.png", "campaign_points.png", "mu_vs_stress.png",
                          "maps_alpha=-1.5.png", "correlations.png"}) {
    EXPECT_GT(fs::exists(folder / png) ? fs::file_size(folder / png) : 0u, 1000u) << png;
    std::ifstream in(folder / png, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(bytes.find(std::string("Software") + '\0' + build), std::string::npos) << png;
  }
  // The correlation table: every coefficient recomputed here on campaign.csv. A pair has
  // coefficients exactly when at least 3 runs have both quantities and neither is constant.
  const Table correlations = read_csv(folder / "correlations.csv");
  ASSERT_FALSE(correlations.empty());
  std::set<std::string> checked;
  for (const auto& c : correlations) {
    const std::string pair = c.at("x") + ":" + c.at("y");
    std::vector<double> x, y;
    for (const auto& row : table) {
      const double a = number(row.at(c.at("x"))), b = number(row.at(c.at("y")));
      if (std::isfinite(a) && std::isfinite(b)) {
        x.push_back(a);
        y.push_back(b);
      }
    }
    EXPECT_EQ(std::stoul(c.at("n")), x.size()) << pair;
    const bool constant = x.size() < 3 ||
                          std::all_of(x.begin(), x.end(), [&](double v) { return v == x[0]; }) ||
                          std::all_of(y.begin(), y.end(), [&](double v) { return v == y[0]; });
    if (constant) {
      EXPECT_TRUE(c.at("pearson").empty()) << pair;
      EXPECT_TRUE(c.at("spearman").empty()) << pair;
      continue;
    }
    ASSERT_FALSE(c.at("pearson").empty() || c.at("spearman").empty()) << pair;
    EXPECT_NEAR(number(c.at("pearson")), pearson(x, y), 1e-9) << pair;
    EXPECT_NEAR(number(c.at("spearman")), pearson(ranks(x), ranks(y)), 1e-9) << pair;
    checked.insert(pair);
  }
  // mu against the ATT and the realized E~ and c~, and alpha~ against the ATT: measured on
  // every run, so these pairs have coefficients (the structures' pairs need agglomerates).
  for (const char* pair :
       {"att_map:mu", "stiffness_tilde:mu", "cohesion_tilde:mu", "viscosity_tilde:att_map"})
    EXPECT_TRUE(checked.count(pair)) << pair << " not checked";
}

TEST(PaperCampaign, CoordinatesThatCannotBeImposedAreRefusedWithTheKey) {
  const fs::path dir = campaign_dir();
  scenes::CohesiveShearCell c;
  c.gap = 2.0;
  std::ofstream(dir / "gap.toml") << scenes::shear_cell_scenario(c);
  std::ofstream(dir / "bad.toml") << "scenario = \"gap.toml\"\n[grid]\nstiffness_tilde = [1.0]\n";
  try {
    load_campaign(dir / "bad.toml");
    ADD_FAILURE() << "E~ accepted under gap loading";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.toml:3: key 'stiffness_tilde'"), std::string::npos) << m;
    EXPECT_NE(m.find("pressure"), std::string::npos) << m;
  }
  // alpha~ under gap loading: alpha = 10^alpha~ D / V with the scenario's D.
  std::ofstream(dir / "alpha.toml") << "scenario = \"gap.toml\"\n[grid]\nviscosity_tilde = [-2]\n";
  const CampaignDef def = load_campaign(dir / "alpha.toml");
  ASSERT_EQ(def.runs.size(), 1u);
  ASSERT_EQ(def.runs[0].derived.size(), 1u);
  EXPECT_EQ(def.runs[0].derived[0].first, "materials.0.damping");
  EXPECT_NEAR(std::stod(def.runs[0].derived[0].second), 0.01 * 2.0 / 1.0, 1e-15);
  // A physical key varied both ways is refused.
  std::ofstream(dir / "twice.toml") << "scenario = \"gap.toml\"\n[grid]\nviscosity_tilde = "
                                       "[-2]\n\"materials.0.damping\" = [0.1]\n";
  EXPECT_THROW(load_campaign(dir / "twice.toml"), Error);
}

}  // namespace
}  // namespace sg
