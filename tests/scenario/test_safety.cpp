// The cases of issue #15 (docs/scenario.md, "Safety"): names that would reach outside the
// run folder, a periodic cell narrower than its grains, a node spacing far too small, an
// extreme initial stretch, grains overlapping at t = 0; and the run folder's own rules
// (io/run_directory.h): a foreign non-empty folder is neither written nor emptied.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/file_name.h"
#include "geometry/shapes.h"
#include "io/run_directory.h"
#include "model/kinematics.h"
#include "run/run.h"
#include "scenario/geometry_checks.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "solver/step_controller.h"
#include "solver/stepper.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path temp_root() {
  return scenes::process_temp_dir("safety");
}

// Two soft discs (radius 0.5, centres 0 and `distance` apart), no contact law unless asked.
std::string two_discs(const std::string& head, double distance = 2.0, const std::string& tail = "",
                      const std::string& stretch = "") {
  std::ostringstream s;
  s << head << "\n[time]\nduration = 0.01\n[discretization]\nnode_spacing = 0.1\n"
    << "[[materials]]\nname = \"soft\"\nyoung = 10.0\n"
    << "[[grains]]\nname = \"left\"\ncenter = [0.0, 0.0]\nradius = 0.5\nmaterial = \"soft\"\n"
    << stretch << "\n[[grains]]\nname = \"right\"\ncenter = [" << distance
    << ", 0.0]\nradius = 0.5\nmaterial = \"soft\"\n"
    << tail;
  return s.str();
}

TEST(Safety, NameThatIsAPathIsRefusedWithTheKeyAndTheRule) {
  for (const char* name : {"/etc", "../../x", "..", "", "a/b", "a\\\\b"}) {
    const std::string e =
        scenes::scenario_error(temp_root(), two_discs("name = \"" + std::string(name) + "\""));
    EXPECT_NE(e.find("bad.toml:1: key 'name'"), std::string::npos) << name << ": " << e;
    EXPECT_NE(e.find("expected a plain file name"), std::string::npos) << e;
  }
  EXPECT_EQ(scenes::scenario_error(temp_root(), two_discs("name = \"run-01_mu=0.2,x+y.z\"")), "");
}

TEST(Safety, NameRuleSaysWhatIsWrong) {
  EXPECT_TRUE(is_plain_file_name("shear-cell_2.5+x=1,2"));
  EXPECT_NE(plain_file_name_problem("../x").find("'/' is a path separator"), std::string::npos);
  EXPECT_NE(plain_file_name_problem("..").find("its parent"), std::string::npos);
  EXPECT_NE(plain_file_name_problem("").find("empty"), std::string::npos);
  EXPECT_NE(plain_file_name_problem("a b").find("' ' is not allowed"), std::string::npos);
  EXPECT_NE(plain_file_name_problem(std::string("a\x01", 2)).find("byte 0x01"), std::string::npos);
}

TEST(Safety, PeriodicCellNarrowerThanAGrainIsRefused) {
  // The case: a cell of width 0.5 around grains spread over 2 length units.
  const std::string e = scenes::scenario_error(
      temp_root(), two_discs("", 2.0, "[periodic]\nx_min = -0.25\nx_max = 0.25\n"));
  EXPECT_NE(e.find("key 'grains[0].radius'"), std::string::npos) << e;
  EXPECT_NE(e.find("grain 'left' is 1 wide in x, not narrower than the periodic cell [-0.25, "
                   "0.25) of width 0.5"),
            std::string::npos)
      << e;
  // Wide enough, but the second grain's centre is outside the cell.
  const std::string outside = scenes::scenario_error(
      temp_root(), two_discs("", 2.0, "[periodic]\nx_min = -1.0\nx_max = 1.5\n"));
  EXPECT_NE(outside.find("key 'grains[1].center'"), std::string::npos) << outside;
  EXPECT_NE(outside.find("centre at x = 2, outside the periodic cell [-1, 1.5)"), std::string::npos)
      << outside;
  EXPECT_EQ(scenes::scenario_error(temp_root(),
                                   two_discs("", 2.0, "[periodic]\nx_min = -1.0\nx_max = 3.0\n")),
            "");
}

TEST(Safety, NodeSpacingFarTooSmallIsRefusedAsTooSmallWithTheLimit) {
  const std::string text =
      scenes::replace_once(two_discs(""), "node_spacing = 0.1", "node_spacing = 1e-9");
  const std::string e = scenes::scenario_error(temp_root(), text);
  EXPECT_NE(e.find("key 'discretization.node_spacing'"), std::string::npos) << e;
  EXPECT_NE(e.find("node spacing 1e-09 is too small for grain 'left' of diameter 1"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("need node_spacing >= diameter / 2000 = 0.0005"), std::string::npos) << e;
  // The contour sampler refuses it too (generated grains), with its limit.
  try {
    make_disc(Vec2::Zero(), 0.5, 1e-9);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("contour spacing 1e-09 is too small"),
              std::string::npos)
        << error.what();
  }
}

TEST(Safety, ExtremeInitialStretchIsWarnedNamingTheGrain) {
  const ScenarioDef s = load_scenario(scenes::write_text_file(
      temp_root() / "stretch.toml", two_discs("", 2.0, "", "stretch = [50, 0.02]\n")));
  const Model model = build_model(s);
  std::ostringstream progress;
  const std::string note = check_initial_state(s, model, false, &progress);
  EXPECT_NE(note.find("# warning: grain 'left': initial stretch [50, 0.02] is beyond [0.5, 2]"),
            std::string::npos)
      << note;
  EXPECT_NE(progress.str().find("softgrain: warning: grain 'left'"), std::string::npos);
  EXPECT_EQ(note.find("'right'"), std::string::npos) << note;
}

TEST(Safety, GrainsOverlappingAtTheStartAreReportedWithTheDepth) {
  const ScenarioDef s =
      load_scenario(scenes::write_text_file(temp_root() / "overlap.toml", two_discs("", 0.8)));
  const Model model = build_model(s);
  // No contacts: grains pass through each other, nothing to report.
  EXPECT_EQ(check_initial_state(s, model, false, nullptr), "");
  const std::string note = check_initial_state(s, model, true, nullptr);
  // Discs of radius 0.5 with centres 0.8 apart overlap by 0.2 (the polygons: a little less).
  const std::string head = "# warning: bodies 'left' and 'right' overlap at t = 0 by ";
  ASSERT_EQ(note.rfind(head, 0), 0u) << note;
  const double depth = std::stod(note.substr(head.size()));
  EXPECT_GT(depth, 0.18);
  EXPECT_LE(depth, 0.2 + 1e-12);
  // Apart: nothing.
  const ScenarioDef apart =
      load_scenario(scenes::write_text_file(temp_root() / "apart.toml", two_discs("", 1.05)));
  EXPECT_EQ(check_initial_state(apart, build_model(apart), true, nullptr), "");
}

TEST(Safety, CollapsingStableStepIsWarnedOnceNamingTheBody) {
  // The left disc is compressed more and more between steps (uniform stretch s in x and y,
  // J = s^2): its elements stiffen and the stable step the controller re-estimates before
  // each step falls with them; the warning comes once, when it is 100 times below the first.
  const ScenarioDef s =
      load_scenario(scenes::write_text_file(temp_root() / "crush.toml", two_discs("", 2.0)));
  Model model = build_model(s);
  Stepper solver(model);
  StepControlParams params;
  params.reestimate_interval = 1;
  int calls = 0;
  double warned_at = 0.0;
  std::string warning;
  params.on_step_collapse = [&](const StableStep& now, double first_dt) {
    ++calls;
    warning = describe_step_collapse(model, now, first_dt);
    EXPECT_LT(now.dt * kStepCollapseFactor, first_dt);
  };
  StepController controller(solver, nullptr, params);
  const double first = controller.next_step();
  controller.advance();
  for (double stretch : {0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.008, 0.006}) {
    set_affine_deformation(model, 0, stretch * Mat2::Identity());
    for (int i = model.bodies[0].node_begin; i < model.bodies[0].node_end; ++i)
      model.nodes.vx[static_cast<std::size_t>(i)] = model.nodes.vy[static_cast<std::size_t>(i)] =
          0.0;
    controller.advance();
    if (calls == 1 && warned_at == 0.0) warned_at = stretch;
  }
  EXPECT_EQ(calls, 1);
  EXPECT_GT(warned_at, 0.0);
  std::cout << "stable step 100x below the first (" << first << ") at stretch " << warned_at
            << "\n";
  EXPECT_NE(warning.find("below 1/100 of the first estimate"), std::string::npos) << warning;
  EXPECT_NE(warning.find("body 'left' sets it"), std::string::npos) << warning;
}

TEST(Safety, RunRefusesAForeignFolderAndDeletesNothingThere) {
  const fs::path root = temp_root() / "runs";
  const fs::path foreign = root / "data";
  fs::create_directories(foreign);
  std::ofstream(foreign / "checkpoint.bin") << "someone else's file";
  std::ofstream(foreign / "notes.txt") << "keep me";
  try {
    prepare_run_directory(root, "data", false);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("is not empty and is not a softgrain run folder"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::exists(foreign / "checkpoint.bin"));  // not deleted
  // A folder a killed run left before its run.log (only softgrain's entries) is ours; starting
  // over there removes its old checkpoint.
  const fs::path killed = root / "killed";
  fs::create_directories(killed / "fields");
  std::ofstream(killed / "checkpoint.bin") << "old";
  std::ofstream(killed / "run.log.tmp") << "softgrain run log\n";
  EXPECT_EQ(prepare_run_directory(root, "killed", false), killed);
  EXPECT_FALSE(fs::exists(killed / "checkpoint.bin"));
  // A folder with softgrain's run.log is ours whatever else it holds.
  std::ofstream(foreign / "run.log") << "softgrain run log\nscenario = x\n";
  EXPECT_EQ(prepare_run_directory(root, "data", false), foreign);
  EXPECT_FALSE(fs::exists(foreign / "checkpoint.bin"));
  EXPECT_TRUE(fs::exists(foreign / "notes.txt"));
  for (const char* bad : {"..", "../x", "/etc", ""})
    EXPECT_THROW(prepare_run_directory(root, bad, false), Error) << bad;
}

TEST(Safety, RunIntoASymbolicLinkIsRefused) {
  const fs::path root = temp_root() / "links";
  fs::create_directories(root / "elsewhere");
  fs::create_directory_symlink(root / "elsewhere", root / "link");
  EXPECT_THROW(prepare_run_directory(root, "link", false), Error);
  EXPECT_TRUE(fs::is_empty(root / "elsewhere"));
}

}  // namespace
}  // namespace sg
