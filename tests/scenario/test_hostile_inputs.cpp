// Issue #26: hostile and careless inputs, round two. Bad cells of the CSV files a scenario
// points to (grains, contour, profile), which aborted the process through an ODR violation
// (two classes sg::CsvTable), now give file:line:column messages; non-finite numbers are
// refused where the scenario gives them, naming the key; special files (FIFO, folder, device)
// given as inputs are refused by type before they are opened.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path temp_root() {
  return scenes::process_temp_dir("hostile");
}

constexpr const char* kHead = R"([time]
duration = 0.01
[discretization]
node_spacing = 0.1
[[materials]]
name = "soft"
young = 10.0
)";

// The error of a scenario whose [[grains]] come from grains.csv holding `csv`.
std::string grains_file_error(const std::string& csv) {
  scenes::write_text_file(temp_root() / "grains.csv", csv);
  return scenes::scenario_error(
      temp_root(),
      std::string(kHead) + "[[grains]]\ngrains_file = \"grains.csv\"\nmaterial = \"soft\"\n");
}

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(HostileInputs, GrainsFileBadCellsNameFileLineAndColumn) {
  EXPECT_HAS(grains_file_error("x,y,diameter\n0,0,1\n3,0,-0.2\n"),
             "grains.csv:3: column 3 'diameter': expected a positive number, got '-0.2'");
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "1e400"})
    EXPECT_HAS(grains_file_error(std::string("x,y,diameter\n0,0,") + bad + "\n"),
               std::string("grains.csv:2: column 3 'diameter': expected a finite number, got '") +
                   bad + "'");
  EXPECT_HAS(grains_file_error("x,y,diameter\n0,0,abc\n"),
             "grains.csv:2: column 3 'diameter': expected a number, got 'abc'");
  EXPECT_HAS(grains_file_error("x,y,diameter\n0,nan,1\n"),
             "grains.csv:2: column 2 'y': expected a finite number, got 'nan'");
  EXPECT_HAS(grains_file_error("x,y,diameter\n0,0,1,0.5\n"),
             "grains.csv:2: column 4: expected 3 cells (the header's columns), got 4");
  EXPECT_HAS(grains_file_error("x,y,diameter\n0,0,1 junk\n"),
             "grains.csv:2: column 3 'diameter': expected a number, got '1 junk'");
  EXPECT_HAS(grains_file_error("x,y,diameter,rigid\n0,0,1,yes\n"),
             "grains.csv:2: column 4 'rigid': expected 0, 1, true or false, got 'yes'");
  EXPECT_HAS(grains_file_error("x,y,diameter,vx\n0,0,1,inf\n"),
             "grains.csv:2: column 4 'vx': expected a finite number, got 'inf'");
  EXPECT_HAS(grains_file_error("x,y,diameter,spin\n0,0,1,nan\n"),
             "grains.csv:2: column 4 'spin': expected a finite number, got 'nan'");
  EXPECT_HAS(grains_file_error("x,y,a,b\n0,0,1,inf\n"),
             "grains.csv:2: column 4 'b': expected a finite number, got 'inf'");
  EXPECT_HAS(grains_file_error("x,y,diameter\n"), "grains.csv: no data rows after the header");
  EXPECT_HAS(grains_file_error(""), "grains.csv:1: expected a header row of column names");
}

TEST(HostileInputs, GrainsFileEmptyShortAndMissingColumnsSayWhatIsMissing) {
  // An empty row: its first cell.
  EXPECT_HAS(grains_file_error("x,y,diameter\n0,0,1\n,,\n"),
             "grains.csv:3: column 1 'x': required number is missing");
  // A short row: the diameter is what is missing, and the row is said to be short (it used to
  // say that column 'b', absent from the header, was missing).
  const std::string short_row = grains_file_error("x,y,diameter\n1,2\n");
  EXPECT_HAS(short_row,
             "grains.csv:2: column 3 'diameter': a grain needs a diameter, or semi-axes a and b; "
             "the row gives neither (the row has 2 cells, the header 3 columns)");
  EXPECT_EQ(short_row.find("'b'"), std::string::npos) << short_row;
  EXPECT_HAS(grains_file_error("x,y,a,b\n1,2\n"),
             "grains.csv:2: column 3 'a': a grain needs a diameter, or semi-axes a and b");
  EXPECT_HAS(grains_file_error("x,y,diameter\n1\n"),
             "grains.csv:2: column 2 'y': required number is missing (the row has 1 cell, the "
             "header 3 columns)");
  // A missing column: the header quoted is the header (it used to be the file's last line).
  EXPECT_HAS(grains_file_error("x,diameter\n0,1\n5,1\n"),
             "grains.csv:1: column 'y' is required (header: x,diameter)");
  EXPECT_HAS(grains_file_error("x,y\n0,1\n"), "needs a column diameter, or columns a and b");
  EXPECT_HAS(grains_file_error("x,y,diam\n0,1,1\n"),
             "grains.csv:1: column 3 'diam': unknown column");
}

TEST(HostileInputs, ContourAndProfileFilesWithTextInANumberNameTheCell) {
  scenes::write_text_file(temp_root() / "contour.csv", "x,y\n0,0\n1,zero\n1,1\n");
  const std::string contour = scenes::scenario_error(
      temp_root(), std::string(kHead) +
                       "[[grains]]\nshape = \"contour\"\ncontour_file = \"contour.csv\"\n"
                       "material = \"soft\"\n");
  EXPECT_HAS(contour, "contour.csv:3: column 2 'y': expected a number, got 'zero'");
  scenes::write_text_file(temp_root() / "contour.csv", "x,y\n0,0\n1,0\ninf,1\n");
  EXPECT_HAS(
      scenes::scenario_error(temp_root(), std::string(kHead) + "[[grains]]\nshape = \"contour\"\n"
                                                               "contour_file = \"contour.csv\"\n"
                                                               "material = \"soft\"\n"),
      "contour.csv:4: column 1 'x': expected a finite number, got 'inf'");
  const std::string strip = std::string(kHead) + R"([periodic]
x_min = 0.0
x_max = 4.0
[[strips]]
material = "soft"
surface_y = 0.0
back_y = -1.0
[strips.profile]
kind = "points"
file = "profile.csv"
)";
  scenes::write_text_file(temp_root() / "profile.csv", "x,y\n0,0\n1,0.1x\n2,0\n");
  EXPECT_HAS(scenes::scenario_error(temp_root(), strip),
             "profile.csv:3: column 2 'y': expected a number, got '0.1x'");
  // A NaN height used to be reported as the back face cutting the surface.
  scenes::write_text_file(temp_root() / "profile.csv", "x,y\n0,0\n1,nan\n2,0\n");
  EXPECT_HAS(scenes::scenario_error(temp_root(), strip),
             "profile.csv:3: column 2 'y': expected a finite number, got 'nan'");
}

TEST(HostileInputs, NonFiniteScenarioNumbersAreRefusedNamingTheKey) {
  const std::string disc = "[[grains]]\ncenter = [0.0, 0.0]\nradius = 0.5\nmaterial = \"soft\"\n";
  const std::string base = std::string(kHead) + disc;
  struct Case {
    std::string from, to, key;
  };
  for (const Case& c : std::vector<Case>{
           {"duration = 0.01", "duration = inf", "bad.toml:2: key 'time.duration'"},
           {"young = 10.0", "young = inf", "bad.toml:7: key 'materials[0].young'"},
           {"young = 10.0", "young = 10.0\ndensity = nan",
            "bad.toml:8: key 'materials[0].density'"},
           {"radius = 0.5", "radius = 0.5\nspin = nan", "bad.toml:11: key 'grains[0].spin'"},
           {"radius = 0.5", "radius = 0.5\nvelocity = [nan, 0.0]",
            "bad.toml:11: key 'grains[0].velocity'"},
           {"center = [0.0, 0.0]", "center = [-inf, 0.0]", "bad.toml:9: key 'grains[0].center'"},
       }) {
    const std::string e =
        scenes::scenario_error(temp_root(), scenes::replace_once(base, c.from, c.to));
    EXPECT_HAS(e, c.key);
    EXPECT_HAS(e, "expected a");
    EXPECT_HAS(e, "finite");
  }
  // A NaN drive velocity: the key, not a contour point mid-run.
  const std::string driven = std::string(kHead) + R"([[grains]]
center = [0.0, 0.0]
radius = 0.5
material = "soft"
rigid = true
[grains.drive]
x = { velocity = nan }
)";
  EXPECT_HAS(scenes::scenario_error(temp_root(), driven),
             "key 'grains[0].drive.x.velocity': expected a finite number, got nan");
}

TEST(HostileInputs, CoincidentGrainsAreRefusedNamingBoth) {
  // Two identical rows: the contours coincide, and the overlap warning (contour points
  // strictly inside another body) used to say nothing.
  EXPECT_HAS(grains_file_error("x,y,diameter\n0,0,1\n3,0,1\n0,0,1\n"),
             "bad.toml:9: key 'grains[0].grains_file': grains 'grains_0' and 'grains_2' are at "
             "the same place (centre 0, 0): coincident grains");
  // Offset by 0.05: accepted (and warned as overlapping when contacts are on).
  EXPECT_EQ(grains_file_error("x,y,diameter\n0,0,1\n0.05,0,1\n"), "");
  const std::string disc = "[[grains]]\ncenter = [1.0, 2.0]\nradius = 0.5\nmaterial = \"soft\"\n";
  EXPECT_HAS(scenes::scenario_error(temp_root(), std::string(kHead) + disc + disc),
             "bad.toml:13: key 'grains[1].center': grains 'grain_0' and 'grain_1' are at the same "
             "place (centre 1, 2)");
}

TEST(HostileInputs, NumbersBeyondWhatARunHoldsAreRefused) {
  const std::string base =
      std::string(kHead) + "[[grains]]\ncenter = [0.0, 0.0]\nradius = 0.5\nmaterial = \"soft\"\n";
  // A density of 1e300 used to end in NaN energies with exit status 0.
  EXPECT_HAS(
      scenes::scenario_error(
          temp_root(), scenes::replace_once(base, "young = 10.0", "young = 10.0\ndensity = 1e300")),
      "bad.toml:8: key 'materials[0].density': expected a number of magnitude at most "
      "1e+100");
  EXPECT_HAS(
      scenes::scenario_error(temp_root(), scenes::replace_once(base, "young = 10.0",
                                                               "young = 10.0\ndensity = 1e-300")),
      "bad.toml:8: key 'materials[0].density': expected a positive number of at least "
      "1e-100");
  EXPECT_HAS(scenes::scenario_error(
                 temp_root(),
                 scenes::replace_once(base, "radius = 0.5", "radius = 0.5\nvelocity = [1e200, 0]")),
             "bad.toml:11: key 'grains[0].velocity': [x, y]: expected a number of magnitude at "
             "most 1e+100");
  EXPECT_HAS(grains_file_error("x,y,diameter\n0,0,1e120\n"),
             "grains.csv:2: column 3 'diameter': expected a number of magnitude at most 1e+100");
}

// examples/shear-cell-small.toml with `from` replaced by `to`.
std::string shear_cell_small(const std::string& from, const std::string& to) {
  std::ifstream in(fs::path(SOFTGRAIN_SOURCE_DIR) / "examples" / "shear-cell-small.toml");
  std::ostringstream text;
  text << in.rdbuf();
  return scenes::replace_once(text.str(), from, to);
}

TEST(HostileInputs, MisleadingMessagesNowNameTheKey) {
  // A node spacing of 1e90 used to say that two contour points of grain_0 "coincide".
  const std::string spacing = scenes::scenario_error(
      temp_root(), shear_cell_small("node_spacing = 0.15", "node_spacing = 1e90"));
  EXPECT_HAS(spacing,
             "key 'discretization.node_spacing': node spacing 1e+90 is too large for "
             "the generated grains of diameter down to 0.85: need node_spacing <= "
             "diameter / 2 = 0.425");
  const std::string disc = "[[grains]]\ncenter = [0.0, 0.0]\nradius = 0.5\nmaterial = \"soft\"\n";
  EXPECT_HAS(scenes::scenario_error(
                 temp_root(), scenes::replace_once(std::string(kHead) + disc, "node_spacing = 0.1",
                                                   "node_spacing = 0.6")),
             "key 'discretization.node_spacing': node spacing 0.6 is too large for grain "
             "'grain_0' of diameter 1: need node_spacing <= diameter / 2 = 0.5");
  // An absurd cohesion: its tensile reach makes the contact cutoff longer than the periodic
  // cell; the run used to stop at step 0 on "the periodic cell (length 20) must be longer than
  // 2 (cutoff + skin) + the widest segment = 1.5e+57", naming neither the law nor the key.
  const std::string cohesion =
      scenes::scenario_error(temp_root(), shear_cell_small("cohesion = 0.1 ", "cohesion = 1e60 "));
  EXPECT_HAS(cohesion, ".cohesion': the contact cutoff + skin = ");
  EXPECT_HAS(cohesion,
             "is not below half the periodic cell (length 20): it follows this law's "
             "tensile reach ");
  EXPECT_HAS(cohesion, "bad.toml:43: key 'contact_laws[");
  // A grain count of 1e11 overflowed an int (a hang or bad_alloc).
  EXPECT_HAS(
      scenes::scenario_error(temp_root(), shear_cell_small("grains = 60", "grains = 100000000000")),
      "key 'shear_cell.grains': expected an integer in [1, 1000000], got 100000000000");
}

TEST(HostileInputs, AnExplodingBodyIsNamedInPlaceOfTheBroadPhaseLimit) {
  // A spin of 1e30 tears the deformable disc apart in its first step: the run used to stop on
  // the broad phase's "the periodic cell must be longer than ... the widest segment", naming
  // no body.
  const std::string text = std::string(kHead) + R"([periodic]
x_min = -5.0
x_max = 5.0
[[grains]]
center = [0.0, 0.0]
radius = 0.5
material = "soft"
spin = 1e30
[[grains]]
center = [2.0, 0.0]
radius = 0.5
material = "soft"
[[contact_laws]]
materials = ["soft", "soft"]
law = "frictionless"
normal_stiffness = 100.0
)";
  const ScenarioDef s = load_scenario(scenes::write_text_file(temp_root() / "spin.toml", text));
  RunOptions options;
  options.output_root_override = temp_root() / "runs";
  options.stop_after_steps = 5;
  try {
    run_scenario(s, options);
    ADD_FAILURE() << "the exploding disc ran";
  } catch (const Error& e) {
    EXPECT_HAS(std::string(e.what()), "body 'grain_0', contour segment ");
    EXPECT_HAS(std::string(e.what()), "more than the periodic cell (length 10) allows");
    EXPECT_HAS(std::string(e.what()), "the body has exploded");
  }
}

TEST(HostileInputs, SpecialFilesAreRefusedByTypeBeforeOpening) {
  const fs::path fifo = temp_root() / "fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  fs::create_directories(temp_root() / "folder");
  // As the scenario file: a FIFO used to block open() forever; a folder or /dev/zero said
  // "key 'time': required table is missing".
  const std::vector<std::pair<fs::path, std::string>> cases = {
      {fifo, "is a FIFO (named pipe): expected a regular file"},
      {temp_root() / "folder", "is a folder: expected a regular file"},
      {"/dev/zero", "is a device: expected a regular file"},
      {temp_root() / "nothing.toml", "does not exist"}};
  for (const auto& [path, problem] : cases) {
    try {
      load_scenario(path);
      ADD_FAILURE() << path << " accepted";
    } catch (const Error& e) {
      EXPECT_HAS(std::string(e.what()), "scenario file '" + path.string() + "' " + problem);
    }
  }
  // As a CSV path: they used to "not exist".
  for (const auto& [path, problem] : cases) {
    const std::string e =
        scenes::scenario_error(temp_root(), std::string(kHead) + "[[grains]]\ngrains_file = \"" +
                                                path.string() + "\"\nmaterial = \"soft\"\n");
    EXPECT_HAS(e, "key 'grains[0].grains_file': file '" + path.string() + "' " + problem);
  }
  // A name longer than a file name can be is refused by length, the message stays short.
  const std::string long_name(1 << 20, 'a');
  const std::string e =
      scenes::scenario_error(temp_root(), std::string(kHead) + "[[grains]]\ngrains_file = \"" +
                                              long_name + "\"\nmaterial = \"soft\"\n");
  EXPECT_HAS(e, "bytes, at most 4096 are allowed");
  EXPECT_LT(e.size(), 1000u);
}

}  // namespace
}  // namespace sg
