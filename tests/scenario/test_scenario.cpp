// Scenario files: the examples load and run; bad input gives one clear error naming the
// file, the line and the key; a run folder is complete only when the run is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "core/error.h"
#include "geometry/polygon.h"
#include "model/kinematics.h"
#include "model/model.h"
#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path write_temp(const std::string& name, const std::string& text) {
  return scenes::write_text_file(scenes::process_temp_dir("scenario") / name, text);
}

const std::string kValid = std::string(R"(
name = "tiny"
[time]
duration = 0.05
[output]
directory = "OUT"
)") + scenes::kTinyScenarioBody;

std::string error_of(const std::string& text) {
  return scenes::scenario_error(scenes::process_temp_dir("scenario"), text);
}

TEST(Scenario, ValidFileRunsToACompleteFolder) {
  const fs::path out = scenes::process_temp_dir("scenario") / "out";
  fs::remove_all(out);
  const ScenarioDef s = load_scenario(write_temp("tiny.toml", kValid));
  EXPECT_EQ(s.grains.size(), 2u);
  EXPECT_EQ(s.walls.size(), 1u);
  EXPECT_EQ(s.contact_laws[1].params.adhesion, 0.5);
  RunOptions options;
  options.output_root_override = out;
  const RunSummary r = run_scenario(s, options);
  EXPECT_GT(r.steps, 0);
  EXPECT_TRUE(fs::exists(out / "tiny" / "series.csv"));
  EXPECT_FALSE(fs::exists(out / "tiny" / "series.csv.partial"));
  EXPECT_TRUE(fs::exists(out / "tiny" / "fields.pvd"));
  EXPECT_TRUE(fs::exists(out / "tiny" / "contacts.pvd"));
  EXPECT_TRUE(fs::exists(out / "tiny" / "run.log"));
  std::ifstream series(out / "tiny" / "series.csv");
  std::string header;
  std::getline(series, header);
  EXPECT_NE(header.find("floor_fy"), std::string::npos) << header;
}

TEST(Scenario, ExamplesLoad) {
  for (const char* name : {"free-grains.toml", "mixed-box.toml", "shear-cell-small.toml"}) {
    const ScenarioDef s = load_scenario(fs::path(SOFTGRAIN_SOURCE_DIR) / "examples" / name);
    EXPECT_TRUE(!s.grains.empty() || s.shear_cell) << name;
  }
}

TEST(Scenario, ShearCellBuildsTwoDrivenFirstBodiesAndTheGrains) {
  const ScenarioDef s =
      load_scenario(fs::path(SOFTGRAIN_SOURCE_DIR) / "examples" / "shear-cell-small.toml");
  ASSERT_TRUE(s.shear_cell);
  const Model model = build_model(s);
  EXPECT_TRUE(model.periodic_x);
  EXPECT_EQ(model.x_max - model.x_min, s.shear_cell->length);
  ASSERT_EQ(model.bodies.size(), static_cast<std::size_t>(s.shear_cell->grains + 2));
  EXPECT_EQ(model.bodies[0].name, "bottom");
  EXPECT_EQ(model.bodies[1].name, "top");
  for (int b : {0, 1}) {
    const RigidDrive& d = model.rigid.drive[static_cast<std::size_t>(model.body(b).rigid_index)];
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(d.mode[k], DriveMode::velocity);
    // After the compaction: +V/2 for the top, -V/2 for the bottom; no vertical motion.
    const double late = 2.0 * s.shear_cell->compaction_time;
    EXPECT_DOUBLE_EQ(d.velocity[0](late), (b == 1 ? 0.5 : -0.5) * s.shear_cell->velocity);
    EXPECT_DOUBLE_EQ(d.velocity[1](late), 0.0);
  }
  // The top surface lies above every grain, the bottom one below.
  double top_min = 1e300, bottom_max = -1e300;
  for (int k = model.bodies[1].contour_begin; k < model.bodies[1].contour_end; ++k)
    top_min = std::min(
        top_min, model.rigid.y[1] + model.rigid_contour_offset[static_cast<std::size_t>(k)].y());
  for (int k = model.bodies[0].contour_begin; k < model.bodies[0].contour_end; ++k)
    bottom_max = std::max(
        bottom_max, model.rigid.y[0] + model.rigid_contour_offset[static_cast<std::size_t>(k)].y());
  for (std::size_t i = 0; i < model.node_count(); ++i) {
    EXPECT_LT(model.nodes.ref_y[i], top_min);
    EXPECT_GT(model.nodes.ref_y[i], bottom_max);
  }
  // The grains along the cell (geometry/packing.h order_along_x: by the centroids of the packed
  // contours; the bodies' contours are those resampled, hence the margin), each named after its
  // place in the drawn population: every name once, and not in that order (the packing places
  // the grains at random).
  std::vector<Vec2> p;
  compute_contour_positions(model, p);
  std::set<std::string> names;
  bool names_in_drawn_order = true;
  double previous_x = -1e300;
  for (std::size_t b = 2; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const double x =
        centroid(Polygon(p.begin() + body.contour_begin, p.begin() + body.contour_end)).x();
    EXPECT_GT(x, previous_x - 0.05) << body.name;
    previous_x = x;
    names.insert(body.name);
    names_in_drawn_order = names_in_drawn_order && body.name == "grain_" + std::to_string(b - 2);
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(s.shear_cell->grains));
  for (int i = 0; i < s.shear_cell->grains; ++i)
    EXPECT_TRUE(names.count("grain_" + std::to_string(i))) << i;
  EXPECT_FALSE(names_in_drawn_order);
}

TEST(Scenario, ErrorsNameFileLineAndKey) {
  struct Case {
    std::string from, to, expected;
  };
  const Case cases[] = {
      {"duration = 0.05", "duration = -1",
       "bad.toml:4: key 'time.duration': expected a positive number"},
      {"duration = 0.05", "duration = \"long\"", "key 'time.duration': expected a number"},
      {"duration = 0.05", "", "key 'time.duration': required number is missing"},
      {"poisson = 0.3", "poisson = 0.5",
       "key 'materials[0].poisson': expected a number in (-1, 0.5)"},
      {"young = 10.0", "young = 0.0", "key 'materials[0].young': expected a positive number"},
      {"radius = 0.5", "radius = 0.5\nradiuss = 1", "key 'grains[0].radiuss': unknown key"},
      {"material = \"soft\"\nvelocity", "material = \"rock\"\nvelocity",
       "key 'grains[0].material': unknown material 'rock'"},
      {"cohesion = 0.5", "cohesion = -0.5",
       "key 'contact_laws[1].cohesion': expected a number >= 0"},
      {"normal_stiffness = 1000.0\nfriction", "normal_stiffness = 0.0\nfriction",
       "key 'contact_laws[0].normal_stiffness': expected a positive number"},
      {"[[contact_laws]]\nmaterials = [\"hard\", \"hard\"]\nlaw = "
       "\"frictionless\"\nnormal_stiffness = 1000.0",
       "", "no contact law for materials 'hard' and 'hard'"},
      {"law = \"coulomb\"", "law = \"sticky\"", "key 'contact_laws[0].law': expected one of"},
      {"node_spacing = 0.15", "node_spacing = [1]",
       "key 'discretization.node_spacing': expected a number"},
  };
  for (const Case& c : cases) {
    const std::string what = error_of(scenes::replace_once(kValid, c.from, c.to));
    EXPECT_NE(what.find(c.expected), std::string::npos) << "got: " << what;
    EXPECT_NE(what.find("bad.toml"), std::string::npos) << "got: " << what;
  }
  EXPECT_NE(error_of("name = [").find("TOML syntax error"), std::string::npos);
}

}  // namespace
}  // namespace sg
