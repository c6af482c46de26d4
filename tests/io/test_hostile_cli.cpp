// Issue #26 through the real executable: the exit status and the one-line message for
// hostile and careless inputs (bad CSV cells, which used to abort with exit 134 and no
// message; a FIFO as the scenario, which used to hang; special files; `-o` naming a plain
// file, which was an "unexpected error"; a name of a megabyte), a run folder whose subfolder
// is a symbolic link (used to be written through), and a write that fails mid-run as on a
// full disk (used to leave its .tmp behind and run.log silent).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "io/run_lock.h"
#include "io/softgrain_process.h"
#include "scenes/scenario_files.h"
#include "test_locations.h"  // SOFTGRAIN_EXECUTABLE, SOFTGRAIN_SOURCE_DIR

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path temp_root() {
  return scenes::process_temp_dir("hostile_cli");
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct Outcome {
  int exit_code = -1;  // -1: killed by a signal (a crash) or by the time limit
  int signal = 0;
  bool timed_out = false;
  std::string err;  // stderr
};

// Runs `softgrain <args> --threads 1` with a time limit (a hang is a failure, not a stuck
// test); `file_size_limit` > 0 caps every file the process writes (the write that passes it
// fails as on a full disk).
Outcome softgrain(std::vector<std::string> args, long file_size_limit = 0,
                  std::chrono::seconds limit = std::chrono::seconds(60)) {
  static int calls = 0;
  testing::SoftgrainLaunch launch;
  launch.stderr_path = (temp_root() / ("stderr-" + std::to_string(++calls) + ".txt")).string();
  launch.file_size_limit = file_size_limit;
  launch.kill_after = limit;
  args.push_back("--threads");
  args.push_back("1");
  const testing::SoftgrainEnd end = testing::run_softgrain_process(std::move(args), launch);
  Outcome o;
  o.exit_code = end.exit_code;
  o.signal = end.killed_at_limit ? 0 : end.signal;
  o.timed_out = end.killed_at_limit;
  o.err = read_text(launch.stderr_path);
  return o;
}

// A refusal: exit status 1, one "softgrain: error:" line holding `part`, no crash.
void expect_refused(const Outcome& o, const std::string& part, const std::string& label) {
  EXPECT_FALSE(o.timed_out) << label << ": hangs";
  EXPECT_EQ(o.signal, 0) << label << ": killed by signal " << o.signal << "\n" << o.err;
  EXPECT_EQ(o.exit_code, 1) << label << "\n" << o.err;
  EXPECT_NE(o.err.find("softgrain: error: "), std::string::npos) << label << "\n" << o.err;
  EXPECT_NE(o.err.find(part), std::string::npos) << label << ": expected '" << part << "' in\n"
                                                 << o.err;
  EXPECT_EQ(o.err.find("unexpected error"), std::string::npos) << label << "\n" << o.err;
}

// Two soft discs apart, no contacts: about 20 steps of 0.0255, a snapshot every other step.
std::string two_discs(const std::string& name, const std::string& grains = "") {
  return "name = \"" + name + R"("
[time]
duration = 0.5
[output]
field_period = 0.05
[discretization]
node_spacing = 0.1
[[materials]]
name = "soft"
young = 10.0
)" +
         (grains.empty() ? R"([[grains]]
center = [0.0, 0.0]
radius = 0.5
material = "soft"
[[grains]]
center = [2.0, 0.0]
radius = 0.5
material = "soft"
)"
                         : grains);
}

TEST(HostileCli, BadCsvCellsExitWithOneMessageNamingFileLineAndColumn) {
  const std::string grains = "[[grains]]\ngrains_file = \"grains.csv\"\nmaterial = \"soft\"\n";
  const fs::path scenario =
      scenes::write_text_file(temp_root() / "csv.toml", two_discs("csv", grains));
  struct Case {
    const char* csv;
    const char* message;
  };
  for (const Case& c : {
           Case{"x,y,diameter\n0,0,-0.2\n",
                "grains.csv:2: column 3 'diameter': expected a positive number, got '-0.2'"},
           Case{"x,y,diameter\n0,0,nan\n",
                "grains.csv:2: column 3 'diameter': expected a finite number, got 'nan'"},
           Case{"x,y,diameter\n0,0,big\n",
                "grains.csv:2: column 3 'diameter': expected a number, got 'big'"},
           Case{"x,y,diameter\n0,0,1\n,,\n",
                "grains.csv:3: column 1 'x': required number is missing"},
           Case{
               "x,y,diameter\n1,2\n",
               "grains.csv:2: column 3 'diameter': a grain needs a diameter, or semi-axes a and b"},
           Case{"x,y,diameter,rigid\n0,0,1,2\n",
                "grains.csv:2: column 4 'rigid': expected 0, 1, true or false, got '2'"},
           Case{"x,y,diameter\n0,0,1,junk\n", "grains.csv:2: column 4: expected 3 cells"},
           Case{"x,diameter\n0,1\n", "grains.csv:1: column 'y' is required (header: x,diameter)"},
       }) {
    scenes::write_text_file(temp_root() / "grains.csv", c.csv);
    expect_refused(softgrain({"run", scenario.string(), "-o", (temp_root() / "out").string()}),
                   c.message, c.csv);
  }
  scenes::write_text_file(temp_root() / "contour.csv", "x,y\n0,0\n1,0\n1,one\n");
  const fs::path contour = scenes::write_text_file(
      temp_root() / "contour.toml",
      two_discs("contour",
                "[[grains]]\nshape = \"contour\"\ncontour_file = \"contour.csv\"\n"
                "material = \"soft\"\n"));
  expect_refused(softgrain({"info", contour.string()}),
                 "contour.csv:4: column 2 'y': expected a number, got 'one'", "contour");
  scenes::write_text_file(temp_root() / "profile.csv", "x,y\n0,0\n1,0..1\n");
  const fs::path profile = scenes::write_text_file(
      temp_root() / "profile.toml",
      two_discs("profile",
                "[periodic]\nx_min = 0.0\nx_max = 4.0\n[[strips]]\nmaterial = "
                "\"soft\"\nsurface_y = 0.0\nback_y = -1.0\n[strips.profile]\nkind = "
                "\"points\"\nfile = \"profile.csv\"\n"));
  expect_refused(softgrain({"info", profile.string()}),
                 "profile.csv:3: column 2 'y': expected a number, got '0..1'", "profile");
}

TEST(HostileCli, SpecialFilesAsTheScenarioAreRefusedWithoutHanging) {
  const fs::path fifo = temp_root() / "scenario-fifo.toml";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  fs::create_directories(temp_root() / "a-folder.toml");
  const auto limit = std::chrono::seconds(20);
  expect_refused(softgrain({"run", fifo.string()}, 0, limit),
                 "scenario file '" + fifo.string() + "' is a FIFO (named pipe)", "FIFO");
  expect_refused(softgrain({"info", (temp_root() / "a-folder.toml").string()}, 0, limit),
                 "is a folder: expected a regular file", "folder");
  expect_refused(softgrain({"info", "/dev/zero"}, 0, limit),
                 "scenario file '/dev/zero' is a device: expected a regular file", "/dev/zero");
}

TEST(HostileCli, OutputRootThatIsAFileAndAHugeNameAreRefusedPlainly) {
  const fs::path scenario = scenes::write_text_file(temp_root() / "plain.toml", two_discs("plain"));
  const fs::path file = scenes::write_text_file(temp_root() / "a-file", "not a folder");
  expect_refused(softgrain({"run", scenario.string(), "-o", file.string()}),
                 "output folder '" + file.string() + "' exists and is not a folder", "-o file");
  EXPECT_EQ(read_text(file), "not a folder");
  const fs::path huge =
      scenes::write_text_file(temp_root() / "huge.toml", two_discs(std::string(1 << 20, 'n')));
  const Outcome o = softgrain({"run", huge.string(), "-o", (temp_root() / "out").string()});
  expect_refused(o,
                 "huge.toml:1: key 'name': the run name becomes the run folder <output>/<name>/: "
                 "expected a plain file name",
                 "1 MiB name");
  EXPECT_NE(o.err.find("it is 1048576 bytes long, a file name holds at most 255"),
            std::string::npos)
      << o.err.substr(0, 2000);
  EXPECT_LT(o.err.size(), 2000u);
}

TEST(HostileCli, ALinkedSubfolderOfTheRunFolderIsRefusedAndNothingIsWrittenThere) {
  const fs::path scenario =
      scenes::write_text_file(temp_root() / "linked.toml", two_discs("linked"));
  const fs::path out = temp_root() / "linked-out";
  ASSERT_EQ(softgrain({"run", scenario.string(), "-o", out.string()}).exit_code, 0);
  const fs::path elsewhere = temp_root() / "elsewhere";
  fs::create_directories(elsewhere);
  for (const char* sub : {"fields", "grains"}) {
    fs::remove_all(out / "linked" / sub);
    fs::create_directory_symlink(elsewhere, out / "linked" / sub);
    expect_refused(softgrain({"run", scenario.string(), "-o", out.string()}),
                   "run folder entry '" + (out / "linked" / sub).string() +
                       "' is a symbolic link: refusing to write through it",
                   sub);
    EXPECT_TRUE(fs::is_empty(elsewhere)) << sub;
    fs::remove(out / "linked" / sub);
    fs::create_directory(out / "linked" / sub);
  }
  // analyze and render write analysis/ and render/: refused through a link too.
  ASSERT_EQ(softgrain({"run", scenario.string(), "-o", out.string()}).exit_code, 0);
  for (const char* sub : {"analysis", "render"}) {
    fs::create_directory_symlink(elsewhere, out / "linked" / sub);
    expect_refused(softgrain({std::string(sub) == "analysis" ? "analyze" : "render",
                              (out / "linked").string()}),
                   "run folder entry '" + (out / "linked" / sub).string() +
                       "' is a symbolic link: refusing to write through it",
                   sub);
    EXPECT_TRUE(fs::is_empty(elsewhere)) << sub;
    fs::remove(out / "linked" / sub);
  }
  // A linked file too (series.csv.partial is appended to, not replaced).
  fs::create_symlink(elsewhere / "rows.csv", out / "linked" / "series.csv.partial");
  expect_refused(softgrain({"run", scenario.string(), "-o", out.string()}),
                 "series.csv.partial' is a symbolic link", "linked series");
  EXPECT_TRUE(fs::is_empty(elsewhere));
}

TEST(HostileCli, AWriteFailingMidRunLeavesNoTemporaryAndRunLogSaysWhy) {
  // Every file capped at 8 kB: run.log (1.4 kB) and the series fit, the first .vtu (20 kB)
  // does not (as on a disk that fills up).
  const fs::path scenario = scenes::write_text_file(temp_root() / "full.toml", two_discs("full"));
  const fs::path out = temp_root() / "full-out";
  const Outcome o = softgrain({"run", scenario.string(), "-o", out.string()}, 8 * 1024);
  expect_refused(o, "failed writing '", "full disk");
  EXPECT_NE(o.err.find(".tmp"), std::string::npos) << o.err;
  int temporaries = 0;
  for (const auto& entry : fs::recursive_directory_iterator(out))
    if (entry.path().extension() == ".tmp") ++temporaries;
  EXPECT_EQ(temporaries, 0);
  const std::string log = read_text(out / "full" / "run.log");
  EXPECT_NE(log.find("# stopped at step "), std::string::npos) << log;
  EXPECT_NE(log.find("failed writing '"), std::string::npos) << log;
}

TEST(HostileCli, ARunIntoAnotherScenariosFolderIsRefusedUnlessOverwrite) {
  const fs::path out = temp_root() / "shared-out";
  const fs::path a = scenes::write_text_file(temp_root() / "a.toml", two_discs("shared"));
  // Another scenario with the same name, snapshots twice as rare.
  const fs::path b = scenes::write_text_file(
      temp_root() / "b.toml",
      scenes::replace_once(two_discs("shared"), "field_period = 0.05", "field_period = 0.1"));
  ASSERT_EQ(softgrain({"run", a.string(), "-o", out.string()}).exit_code, 0);
  const fs::path dir = out / "shared";
  const std::string series = read_text(dir / "series.csv");
  expect_refused(softgrain({"run", b.string(), "-o", out.string()}),
                 "run folder '" + dir.string() + "' holds the run of another scenario ('" +
                     a.string() + "', its run.log), not '" + b.string() + "'",
                 "another scenario");
  EXPECT_EQ(read_text(dir / "series.csv"), series);  // untouched
  EXPECT_TRUE(fs::exists(dir / "fields" / "000010.vtu"));
  // The same scenario again is no problem.
  EXPECT_EQ(softgrain({"run", a.string(), "-o", out.string()}).exit_code, 0);
  // --overwrite clears the old run's outputs: no stale snapshot stays beside the new run's.
  const Outcome o = softgrain({"run", b.string(), "-o", out.string(), "--overwrite"});
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(fs::exists(dir / "fields" / "000005.vtu"));
  EXPECT_FALSE(fs::exists(dir / "fields" / "000010.vtu"));
  EXPECT_NE(read_text(dir / "run.log").find("scenario = " + b.string()), std::string::npos);
}

TEST(HostileCli, ARunFolderInUseIsRefusedNamingTheProcess) {
  const fs::path scenario = scenes::write_text_file(temp_root() / "busy.toml", two_discs("busy"));
  const fs::path out = temp_root() / "busy-out";
  fs::create_directories(out / "busy");
  RunFolderLock lock;  // this process plays the run that writes the folder
  lock.acquire(out / "busy");
  expect_refused(softgrain({"run", scenario.string(), "-o", out.string()}),
                 "run folder '" + (out / "busy").string() + "' is in use: process " +
                     std::to_string(::getpid()),
                 "locked folder");
  EXPECT_FALSE(fs::exists(out / "busy" / "series.csv.partial"));
}

TEST(HostileCli, AnAbsurdStepIsRefusedUnlessAllowed) {
  // A contact stiffness of 1e15 between two touching discs: a step of a few 1e-8 (the
  // issue's case: 2.5e-15), over 10^10 steps for a duration of 1000.
  const std::string grains = R"([[grains]]
center = [0.0, 0.0]
radius = 0.5
material = "soft"
[[grains]]
center = [1.0, 0.0]
radius = 0.5
material = "soft"
[[contact_laws]]
materials = ["soft", "soft"]
law = "frictionless"
normal_stiffness = 1e15
)";
  std::string text =
      scenes::replace_once(two_discs("stiff", grains), "duration = 0.5", "duration = 1000.0");
  const fs::path scenario = scenes::write_text_file(temp_root() / "stiff.toml", text);
  const fs::path out = temp_root() / "stiff-out";
  expect_refused(softgrain({"run", scenario.string(), "-o", out.string()}),
                 "stiff.toml: key 'time.duration': the first step ", "absurd step");
  const Outcome refused = softgrain({"run", scenario.string(), "-o", out.string()});
  EXPECT_NE(refused.err.find("set [time] allow_long_run = true"), std::string::npos) << refused.err;
  const fs::path allowed = scenes::write_text_file(
      temp_root() / "stiff-allowed.toml",
      scenes::replace_once(text, "duration = 1000.0", "duration = 1000.0\nallow_long_run = true"));
  const Outcome o = softgrain({"run", allowed.string(), "-o", out.string(), "--max-steps", "3"});
  EXPECT_EQ(o.exit_code, 0) << o.err;
}

TEST(HostileCli, AStableStepOfZeroIsRefusedNamingTheBodyEvenWhenLongRunsAreAllowed) {
  // young = 1e90 with damping: the damped step limit underflows to 0 (the run would never end).
  // The explicit integrator pinned: by default imex would be chosen (its step, 8e-47, is not
  // limited by the damping) and the run refused as absurdly long instead.
  const std::string text = scenes::replace_once(
      scenes::replace_once(two_discs("zero"), "young = 10.0", "young = 1e90\ndamping = 0.01"),
      "duration = 0.5", "duration = 0.5\nintegrator = \"explicit\"");
  for (const std::string& t :
       {text,
        scenes::replace_once(text, "duration = 0.5", "duration = 0.5\nallow_long_run = true")}) {
    const fs::path scenario = scenes::write_text_file(temp_root() / "zero.toml", t);
    expect_refused(softgrain({"run", scenario.string(), "-o", (temp_root() / "zero-out").string()}),
                   "zero.toml: the stable step estimate is 0 (body 'grain_0', highest frequency ",
                   "zero step");
  }
}

TEST(HostileCli, ResumeDropsSnapshotsDeletedSinceAndSaysSo) {
  const fs::path scenario =
      scenes::write_text_file(temp_root() / "gone.toml",
                              scenes::replace_once(two_discs("gone"), "field_period = 0.05",
                                                   "field_period = 0.05\ncheckpoint_period = 0.1"));
  const fs::path out = temp_root() / "gone-out";
  const fs::path dir = out / "gone";
  // Stopped past the first checkpoint, as a killed run.
  const Outcome stopped =
      softgrain({"run", scenario.string(), "-o", out.string(), "--max-steps", "12"});
  ASSERT_EQ(stopped.exit_code, 0) << stopped.err;
  ASSERT_TRUE(fs::exists(dir / "checkpoint.bin")) << "no checkpoint after 12 steps";
  ASSERT_TRUE(fs::exists(dir / "fields" / "000001.vtu"));
  fs::remove(dir / "fields" / "000001.vtu");
  const Outcome resumed = softgrain({"run", scenario.string(), "-o", out.string(), "--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("softgrain: warning: resume: 1 of the "), std::string::npos)
      << resumed.err;
  EXPECT_NE(resumed.err.find("fields.pvd listed are missing (fields/000001.vtu): fields.pvd "
                             "now lists only the files present"),
            std::string::npos)
      << resumed.err;
  const std::string pvd = read_text(dir / "fields.pvd");
  EXPECT_EQ(pvd.find("000001.vtu"), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("000002.vtu"), std::string::npos) << pvd;
  EXPECT_NE(read_text(dir / "run.log").find("# resume: 1 of the "), std::string::npos);
}

TEST(HostileCli, AStiffnessOverMassBeyondTheArithmeticIsRefusedNamingTheMaterial) {
  // young 1e80 over density 1e-80: the stable-step estimate overflowed and said "cannot
  // estimate its highest frequency (got 0); is the body inverted?", naming no input.
  const std::string text =
      scenes::replace_once(two_discs("light"), "young = 10.0", "young = 1e80\ndensity = 1e-80");
  const fs::path scenario = scenes::write_text_file(temp_root() / "light.toml", text);
  const Outcome o =
      softgrain({"run", scenario.string(), "-o", (temp_root() / "light-out").string()});
  expect_refused(o,
                 "light.toml:10: key 'materials[0].young': material 'soft': young 1e+80 over "
                 "density 1e-80",
                 "young over density");
  EXPECT_NE(o.err.find("expected at most 1e+70"), std::string::npos) << o.err;
  EXPECT_EQ(o.err.find("inverted"), std::string::npos) << o.err;
}

TEST(HostileCli, AHugeDriveVelocityIsRefusedNamingTheKey) {
  // A wall driven at 1e10: the contact grid spanning its reach ended the run at step 1 with
  // "cannot create std::vector larger than max_size()".
  const std::string wall = R"([[walls]]
lower_left = [-2.0, -0.7]
upper_right = [2.0, -0.5]
material = "soft"
velocity = [1e10, 0.0]
[[contact_laws]]
materials = ["soft", "soft"]
law = "frictionless"
normal_stiffness = 100.0
)";
  const fs::path scenario =
      scenes::write_text_file(temp_root() / "fast-wall.toml", two_discs("fast-wall") + wall);
  const fs::path out = temp_root() / "fast-out";
  const Outcome o = softgrain({"run", scenario.string(), "-o", out.string()});
  expect_refused(o, "fast-wall.toml:23: key 'walls[0].velocity': wall 'wall_0': a speed of 1e+10",
                 "wall velocity");
  EXPECT_EQ(o.err.find("max_size"), std::string::npos) << o.err;
  // The same in a drive table, and a thrown grain.
  const fs::path drive = scenes::write_text_file(
      temp_root() / "fast-drive.toml",
      two_discs("fast-drive") + scenes::replace_once(wall, "velocity = [1e10, 0.0]",
                                                     "drive = {y = {velocity = [[0.0, 0.0], "
                                                     "[0.1, -1e12]]}}"));
  expect_refused(softgrain({"run", drive.string(), "-o", out.string()}),
                 "key 'walls[0].drive.y.velocity': wall 'wall_0': a speed of 1e+12", "drive");
  const fs::path thrown = scenes::write_text_file(
      temp_root() / "thrown.toml",
      scenes::replace_once(two_discs("thrown"), "radius = 0.5\nmaterial = \"soft\"\n[[grains]]",
                           "radius = 0.5\nmaterial = \"soft\"\nvelocity = [0.0, 1e9]\n[[grains]]"));
  expect_refused(softgrain({"run", thrown.string(), "-o", out.string()}),
                 "thrown.toml:15: key 'grains[0].velocity': grain 'grain_0': a speed of 1e+09",
                 "thrown grain");
  EXPECT_FALSE(fs::exists(out / "fast-wall" / "series.csv"));
}

}  // namespace
}  // namespace sg
