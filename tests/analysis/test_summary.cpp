#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "analysis/summary.h"
#include "synthetic.h"

namespace sg {
namespace {

AnalysisSummary make_summary() {
  AnalysisSummary s;
  s.window.t_begin = 50.0;
  s.window.t_end = 300.0;
  s.window.detected = true;
  FrictionStats top{"top", 100.0, 40.0, 0.4, 0.01, 1.0, 0.4};
  FrictionStats bottom{"bottom", 100.0, 40.0, 0.4, 0.01, 1.0, 0.4};
  s.friction.bodies = {top, bottom};
  s.friction.mean = top;
  s.friction.mean.body = "mean";
  s.dimensionless.stiffness = 1.0;  // cohesion and viscosity unknown (NaN)
  EnergyBudget e;
  e.bulk_share = 0.75;
  e.contact_share = 0.25;
  e.bulk_friction = 0.3;
  e.contact_friction = 0.1;
  s.energy = e;
  s.solid_fraction = 0.85;
  return s;
}

TEST(Summary, JsonCarriesValuesUnitsDefinitionsAndNulls) {
  test::ScratchDir dir("summary");
  const std::string path = dir.file("run/analysis/summary.json");
  write_summary_json(path, make_summary());
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));  // renamed into place
  std::ifstream in(path);
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["format"], "softgrain-analysis-summary");
  EXPECT_EQ(doc["version"], 1);
  const auto& q = doc["quantities"];
  EXPECT_EQ(q["mu"]["value"].get<double>(), 0.4);
  EXPECT_EQ(q["mu"]["unit"], "1");
  EXPECT_NE(q["mu"]["definition"].get<std::string>().find("paper 002 eq. 4"), std::string::npos);
  EXPECT_EQ(q["top_mu_std"]["value"].get<double>(), 0.01);
  EXPECT_EQ(q["bottom_normal_stress"]["unit"], "stress");
  EXPECT_EQ(q["bulk_share"]["value"].get<double>(), 0.75);
  EXPECT_EQ(q["contact_friction"]["value"].get<double>(), 0.1);
  EXPECT_EQ(q["stiffness_tilde"]["value"].get<double>(), 1.0);
  EXPECT_TRUE(q["cohesion_tilde"]["value"].is_null());   // unknown c: null, not 0
  EXPECT_TRUE(q["structure_count"]["value"].is_null());  // no snapshot analysed
  EXPECT_EQ(q["solid_fraction"]["value"].get<double>(), 0.85);
  EXPECT_EQ(q["window_detected"]["value"].get<double>(), 1.0);
  // Every entry has the three fields.
  for (const auto& [key, entry] : q.items()) {
    EXPECT_TRUE(entry.contains("value")) << key;
    EXPECT_FALSE(entry["unit"].get<std::string>().empty()) << key;
    EXPECT_FALSE(entry["definition"].get<std::string>().empty()) << key;
  }
  // Rewriting replaces the file whole.
  AnalysisSummary changed = make_summary();
  changed.friction.mean.mu = 0.5;
  write_summary_json(path, changed);
  std::ifstream again(path);
  EXPECT_EQ(nlohmann::json::parse(again)["quantities"]["mu"]["value"].get<double>(), 0.5);
}

TEST(Summary, TableListsEveryQuantity) {
  const AnalysisSummary s = make_summary();
  const std::string table = format_summary_table(s);
  const auto entries = summary_entries(s);
  for (const auto& e : entries)
    EXPECT_NE(table.find(e.key), std::string::npos) << e.key;
  EXPECT_NE(table.find("0.4"), std::string::npos);
  // Lines: header, rule, one per entry.
  EXPECT_EQ(static_cast<std::size_t>(std::count(table.begin(), table.end(), '\n')),
            entries.size() + 2);
}

}  // namespace
}  // namespace sg
