// `analyze` on the tiny shear cell (tiny_run.h: compaction_time 1.5): the scenario's end of the
// compaction reaches the window detection (RunInfo::loading_end, report/shear_report.cpp; the
// detection itself is tested on a synthetic ramp, SteadyWindow.NeverStartsInsideTheLoadRamp),
// and summary.json carries the steadiness checks, what was not measured, and mu's error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "render/run_folder.h"
#include "report/analyze_run.h"
#include "tiny_run.h"

namespace sg {
namespace {

TEST(AnalyzeWindow, StartsAfterTheCompactionOfTheScenario) {
  const auto& dir = test::tiny_shear_run_dir();
  EXPECT_DOUBLE_EQ(read_run_info(dir).loading_end, 1.5);
  const AnalyzeResult r = analyze_run(dir, AnalyzeOptions{});
  EXPECT_TRUE(r.summary.window.detected);
  EXPECT_GE(r.summary.window.t_begin, 1.5);
  bool noted = false;
  for (const std::string& n : r.notes)
    noted = noted ||
            n.find("detected after the compaction or load ramp (t >= 1.5)") != std::string::npos;
  EXPECT_TRUE(noted);

  std::ifstream in(r.summary_path);
  const auto doc = nlohmann::json::parse(in);
  ASSERT_TRUE(doc.contains("warnings"));
  EXPECT_TRUE(doc.at("warnings").is_array());
  EXPECT_EQ(doc.at("warnings").size(), r.summary.warnings.size());
  ASSERT_TRUE(doc.contains("unmeasured"));
  EXPECT_EQ(doc.at("unmeasured").size(), r.unmeasured.size());
  // mu is measured or said not to be, never silently null.
  const auto& mu = doc.at("quantities").at("mu").at("value");
  EXPECT_EQ(mu.is_null(), !r.unmeasured.empty());
  if (!mu.is_null()) {
    EXPECT_GT(doc.at("quantities").at("mu_error").at("value").get<double>(), 0.0);
  }
}

// The same run cut just after its compaction (3 series rows after t = 1.5): no steady state can
// be detected after the compaction, and mu is said not measured, with that reason, instead of
// being measured on a window inside the compaction (or the analysis failing as a whole).
TEST(AnalyzeWindow, TooFewRowsAfterTheCompactionLeaveMuUnmeasured) {
  namespace fs = std::filesystem;
  const fs::path& full = test::tiny_shear_run_dir();
  const fs::path cut = full.parent_path() / "tiny-shear-cut";
  fs::remove_all(cut);
  fs::create_directories(cut);
  fs::copy_file(full / "run.log", cut / "run.log");
  std::ifstream in(full / "series.csv");
  std::ofstream out(cut / "series.csv");
  std::string line;
  std::getline(in, line);
  out << line << "\n";
  int rows = 0;
  while (std::getline(in, line) && std::stod(line.substr(0, line.find(','))) <= 1.525) {
    out << line << "\n";
    ++rows;
  }
  out.close();
  ASSERT_GT(rows, 100);
  const AnalyzeResult r = analyze_run(cut, AnalyzeOptions{});
  ASSERT_EQ(r.unmeasured.size(), 1u);
  EXPECT_EQ(r.unmeasured[0].quantity, "mu");
  EXPECT_NE(r.unmeasured[0].reason.find("no steady-state window"), std::string::npos)
      << r.unmeasured[0].reason;
  EXPECT_NE(r.unmeasured[0].reason.find("after t = 1.5"), std::string::npos)
      << r.unmeasured[0].reason;
  EXPECT_TRUE(std::isnan(r.summary.friction.mean.mu));
  EXPECT_FALSE(r.summary.window.detected);
}

}  // namespace
}  // namespace sg
