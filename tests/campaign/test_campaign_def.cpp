// Campaign files: expansion into runs (grid product order, explicit lists, ids), each run's
// scenario (the base text with the values replaced, read back by the scenario reader), and
// errors naming the campaign file, the line and the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "campaign/campaign_def.h"
#include "campaign/campaign_table.h"
#include "core/error.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path test_dir() {
  return scenes::process_temp_dir("campaign");
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = test_dir() / name;
  std::ofstream(p) << text;
  return p;
}

const std::string kBase = std::string(R"(# the tiny test scene
name = "tiny"
[time]
duration = 0.05   # keep it short
[output]
series_period = 0.01
)") + scenes::kTinyScenarioBody;

// The run's scenario as the scenario reader sees it.
ScenarioDef read_run(const CampaignRun& run) {
  return load_scenario(write("run.toml", run.scenario_text));
}

std::string error_of(const fs::path& campaign) {
  try {
    load_campaign(campaign);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CampaignDef, GridIsTheProductWithTheFirstKeySlowest) {
  write("base.toml", kBase);
  const CampaignDef c = load_campaign(write("grid.toml", R"(
name = "g"
scenario = "base.toml"
[grid]
"materials.0.young" = [10.0, 20, 30.5]
"contact_laws.0.friction" = [0.1, 0.2]
)"));
  ASSERT_EQ(c.runs.size(), 6u);
  ASSERT_EQ(c.parameters.size(), 2u);
  EXPECT_EQ(c.parameters[0].key, "materials.0.young");
  EXPECT_EQ(c.parameters[1].key, "contact_laws.0.friction");
  const double young[] = {10.0, 10.0, 20.0, 20.0, 30.5, 30.5};
  const double friction[] = {0.1, 0.2, 0.1, 0.2, 0.1, 0.2};
  for (std::size_t k = 0; k < 6; ++k) {
    const ScenarioDef s = read_run(c.runs[k]);
    EXPECT_EQ(s.materials[0].young, young[k]) << k;
    EXPECT_EQ(s.contact_laws[0].params.friction, friction[k]) << k;
    EXPECT_EQ(s.materials[1].young, 100.0) << "a key not varied keeps the base value";
    EXPECT_EQ(s.name, c.runs[k].id);
    EXPECT_EQ(s.output_root, fs::path("runs"));
  }
  EXPECT_EQ(c.runs[0].id, "run-000_young=10_friction=0.1");
  EXPECT_EQ(c.runs[3].id, "run-003_young=20_friction=0.2");
  EXPECT_EQ(c.runs[5].id, "run-005_young=30.5_friction=0.2");
  // An integer given for a number is written as a number; values are the CSV cells.
  EXPECT_EQ(c.runs[2].values, (std::vector<std::string>{"20.0", "0.1"}));
}

TEST(CampaignDef, ListEntriesTimesGridAndNestedKeys) {
  write("base.toml", kBase);
  // Unquoted dotted keys (nested tables) mean the same as quoted ones.
  const CampaignDef c = load_campaign(write("list.toml", R"(
scenario = "base.toml"
[grid]
materials.1.young = [50.0, 60.0]
[[list]]
"time.duration" = 0.02
"materials.0.name" = "soft"
[[list]]
time.duration = 0.03
materials.0.name = "soft"
)"));
  EXPECT_EQ(c.name, "list");
  ASSERT_EQ(c.parameters.size(), 3u);
  EXPECT_EQ(c.parameters[0].key, "time.duration");
  EXPECT_EQ(c.parameters[2].key, "materials.1.young");
  ASSERT_EQ(c.runs.size(), 4u);
  const double duration[] = {0.02, 0.02, 0.03, 0.03};
  const double young[] = {50.0, 60.0, 50.0, 60.0};
  for (std::size_t k = 0; k < 4; ++k) {
    const ScenarioDef s = read_run(c.runs[k]);
    EXPECT_EQ(s.duration, duration[k]) << k;
    EXPECT_EQ(s.materials[1].young, young[k]) << k;
  }
  EXPECT_EQ(c.runs[1].id, "run-001_duration=0.02_name=soft_young=60");
}

TEST(CampaignDef, RunScenariosDoNotDependOnHowTheCampaignFileIsNamed) {
  // A campaign resumed from another working directory compares these texts with the
  // scenario.toml files already written.
  write("base.toml", kBase);
  const fs::path file = write("same.toml",
                              "scenario = \"base.toml\"\n[grid]\n"
                              "\"materials.0.young\" = [1.0, 2.0]\n");
  const CampaignDef a = load_campaign(file);
  const CampaignDef b = load_campaign(file.parent_path() / "." / file.filename());
  ASSERT_EQ(a.runs.size(), 2u);
  EXPECT_EQ(a.runs[1].scenario_text, b.runs[1].scenario_text);
}

TEST(CampaignDef, LabelsTellParametersWithTheSameNameApart) {
  write("base.toml", kBase);
  const CampaignDef c = load_campaign(write("labels.toml", R"(
scenario = "base.toml"
[grid]
"materials.0.young" = [1.0]
"materials.1.young" = [2.0]
)"));
  EXPECT_EQ(c.runs.at(0).id, "run-000_0.young=1_1.young=2");
}

TEST(CampaignDef, RunScenarioKeepsTheBaseTextAndChangesOnlyTheVariedLines) {
  write("base.toml", kBase);
  const CampaignDef c = load_campaign(write("text.toml", R"(
scenario = "base.toml"
[grid]
"time.duration" = [0.07]
)"));
  std::istringstream base(kBase), run(c.runs.at(0).scenario_text);
  std::vector<std::string> run_lines;
  for (std::string l; std::getline(run, l);)
    if (l.empty() || l[0] != '#' || l == "# the tiny test scene") run_lines.push_back(l);
  std::vector<std::string> changed;
  std::size_t at = 0;
  for (std::string l; std::getline(base, l); ++at) {
    // The base lines in order, the directory line inserted after [output].
    if (run_lines.at(at) == "directory = \"runs\"") ++at;
    if (run_lines.at(at) != l) changed.push_back(run_lines.at(at));
  }
  EXPECT_EQ(changed, (std::vector<std::string>{"name = \"run-000_duration=0.07\"",
                                               "duration = 0.07   # keep it short"}));
}

TEST(CampaignDef, BadKeysNameTheCampaignFileTheLineAndTheKey) {
  write("base.toml", kBase);
  const fs::path missing = write("missing.toml", R"(scenario = "base.toml"
[grid]
"materials.0.young" = [1.0]
"materials.5.young" = [1.0, 2.0]
)");
  const std::string e1 = error_of(missing);
  EXPECT_NE(e1.find(missing.string() + ":4: key 'materials.5.young' in [grid]"), std::string::npos)
      << e1;
  EXPECT_NE(e1.find("'materials' has 2 entries"), std::string::npos) << e1;

  const fs::path typo = write("typo.toml", R"(scenario = "base.toml"
[[list]]
"materials.0.yung" = 1.0
)");
  const std::string e2 = error_of(typo);
  EXPECT_NE(e2.find(typo.string() + ":3: key 'materials.0.yung' in [[list]]"), std::string::npos)
      << e2;
  EXPECT_NE(e2.find("has no 'materials.0.yung'"), std::string::npos) << e2;

  const fs::path type = write("type.toml", R"(scenario = "base.toml"
[grid]
"materials.0.name" = ["soft",
  3.0]
)");
  const std::string e3 = error_of(type);
  EXPECT_NE(e3.find(type.string() + ":4: key 'materials.0.name' in [grid]: expected a string"),
            std::string::npos)
      << e3;

  const fs::path unknown = write("unknown.toml", "scenario = \"base.toml\"\nparalel = 2\n");
  EXPECT_NE(error_of(unknown).find(unknown.string() + ":2: key 'paralel': unknown key"),
            std::string::npos);
  const fs::path nothing = write("nothing.toml", "scenario = \"base.toml\"\n");
  EXPECT_NE(error_of(nothing).find("nothing to vary"), std::string::npos);
  const fs::path name = write("name.toml", "scenario = \"base.toml\"\n[grid]\nname = [\"a\"]\n");
  EXPECT_NE(error_of(name).find(":3: key 'name' in [grid]: set by softgrain sweep"),
            std::string::npos);
}

TEST(CampaignTable, ReadsSummariesAndRefusesOtherVersions) {
  const fs::path good = write("summary.json", R"({"format": "softgrain-analysis-summary",
    "version": 1, "quantities": {"mu": {"value": 0.25}, "mu_std": {"value": null}}})");
  const auto q = read_summary_quantities(good);
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q[0].first, "mu");
  EXPECT_EQ(q[0].second, 0.25);
  EXPECT_TRUE(std::isnan(q[1].second));
  const fs::path v2 = write("summary2.json", R"({"format": "softgrain-analysis-summary",
    "version": 2, "quantities": {}})");
  EXPECT_THROW(read_summary_quantities(v2), Error);

  // A summary of this softgrain: what analysed it and what it could not measure.
  const fs::path recorded = write("summary3.json", R"({"format": "softgrain-analysis-summary",
    "version": 1, "softgrain": {"version": "0.1.0", "commit": "0123456789ab-dirty"},
    "quantities": {"mu": {"value": null}},
    "unmeasured": [{"quantity": "mu", "reason": "normal force 0, at t = 0"}],
    "warnings": [{"check": "mu_trend", "message": "m"}, {"check": "kinetic_drift", "message": "k"}]})");
  const SummaryRecord record = read_summary_record(recorded);
  EXPECT_EQ(record.software, "0.1.0 0123456789ab-dirty");
  EXPECT_EQ(record.unmeasured, "mu: normal force 0, at t = 0");
  EXPECT_EQ(record.warnings, "mu_trend; kinetic_drift");
  EXPECT_EQ(read_summary_record(good).software, "");  // written before softgrain said
  EXPECT_EQ(read_summary_record(good).unmeasured, "");

  SummaryRecord done;
  done.quantities = {{"mu", 0.5}, {"mu_std", q[1].second}};
  done.software = "0.1.0 0123456789ab";
  const std::vector<CampaignRow> rows = {{"run-000_name=a,b", {"'a,b'"}, "done", done},
                                         {"run-001_name=c", {"'c'"}, "done", record},
                                         {"run-002_name=d", {"'d'"}, "pending", {}}};
  EXPECT_EQ(campaign_table_csv({"materials.0.name"}, rows),
            "id,materials.0.name,status,softgrain,unmeasured,warnings,mu,mu_std\n"
            "\"run-000_name=a,b\",\"'a,b'\",done,0.1.0 0123456789ab,,,0.5,\n"
            "run-001_name=c,'c',done,0.1.0 0123456789ab-dirty,\"mu: normal force 0, at t = "
            "0\",mu_trend; kinetic_drift,,\n"
            "run-002_name=d,'d',pending,,,,,\n");
}

}  // namespace
}  // namespace sg
