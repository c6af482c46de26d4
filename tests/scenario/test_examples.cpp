// Every examples/*.toml loads (so a renamed or removed key cannot leave an example behind),
// and the small ones build their model; full-size ones (a name ending in "-full") are only
// loaded: building them takes minutes and gigabytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "model/model.h"
#include "scenario/scenario.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> example_files() {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e :
       fs::directory_iterator(fs::path(SOFTGRAIN_SOURCE_DIR) / "examples"))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

bool is_full_size(const fs::path& file) {
  const std::string stem = file.stem().string();
  return stem.size() >= 5 && stem.compare(stem.size() - 5, 5, "-full") == 0;
}

TEST(Examples, EveryExampleLoadsAndTheSmallOnesBuild) {
  const std::vector<fs::path> files = example_files();
  // The examples this test was written with; more may come, none may silently disappear.
  for (const char* name : {"shear-cell-small.toml", "shear-cell-si.toml", "shear-cell-si-full.toml",
                           "shear-cell-full.toml"})
    EXPECT_NE(
        std::find(files.begin(), files.end(), fs::path(SOFTGRAIN_SOURCE_DIR) / "examples" / name),
        files.end())
        << name;
  int built = 0;
  for (const fs::path& file : files) {
    // Campaign files (softgrain sweep) are not scenarios; tests/campaign reads them.
    if (file.filename().string().starts_with("campaign-")) continue;
    SCOPED_TRACE(file.filename().string());
    ScenarioDef s;
    try {
      s = load_scenario(file);
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    EXPECT_EQ(s.name, file.stem().string());  // outputs go to out/<file name>
    if (is_full_size(file)) continue;
    try {
      const Model model = build_model(s);
      EXPECT_GT(model.bodies.size(), 0u);
      ++built;
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GE(built, 2);
}

// The SI example is what paper 003 describes: circles and ellipses in equal numbers, a
// servo-controlled pressure of 1 GPa on the top first body, 100 m/s.
TEST(Examples, SiShearCellIsPaper003Reduced) {
  for (const char* name : {"shear-cell-si.toml", "shear-cell-si-full.toml"}) {
    SCOPED_TRACE(name);
    const ScenarioDef s = load_scenario(fs::path(SOFTGRAIN_SOURCE_DIR) / "examples" / name);
    ASSERT_TRUE(s.shear_cell);
    EXPECT_EQ(s.shear_cell->normal_load, NormalLoad::pressure);
    EXPECT_EQ(s.shear_cell->pressure, 1e9);
    EXPECT_EQ(s.shear_cell->velocity, 100.0);
    ASSERT_EQ(s.shear_cell->components.size(), 2u);
    EXPECT_EQ(s.shear_cell->components[0].number_fraction,
              s.shear_cell->components[1].number_fraction);
    EXPECT_EQ(s.shear_cell->components[1].shape.kind, GrainShapeKind::ellipse);
  }
}

}  // namespace
}  // namespace sg
