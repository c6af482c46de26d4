// Checkpoints and exact restart through the whole run (run/run.h, io/checkpoint.h): a run
// stopped after a checkpoint (as a killed run leaves its folder) and resumed ends with a
// folder byte-identical to an uninterrupted run's; a damaged checkpoint, or one written for
// another scenario or other run settings, is refused with one line naming the file and why.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/checkpoint.h"
#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/shear_cell_scenario.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// A small periodic shear cell: rough rigid first bodies, 8 soft cohesive grains, compaction
// then shear; grains touch, bond and cross the seam within the run.
std::string shear_cell(const std::string& name, int grains = 8, const std::string& extra = "") {
  scenes::CohesiveShearCell c;
  c.name = name;
  c.duration = 0.6;
  c.extra_time = extra;
  c.checkpoint_period = 0.2;
  c.grains = grains;
  c.compaction_time = 0.15;
  c.velocity = 4.0;
  return scenes::shear_cell_scenario(c);
}

fs::path temp_root() {
  return scenes::process_temp_dir("io");
}

ScenarioDef scenario_file(const std::string& file, const std::string& text) {
  return load_scenario(scenes::write_text_file(temp_root() / file, text));
}

RunSummary run(const ScenarioDef& s, const fs::path& out, bool resume = false,
               long stop_after = -1) {
  RunOptions options;
  options.output_root_override = out;
  options.resume = resume;
  options.stop_after_steps = stop_after;
  return run_scenario(s, options);
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// Every file of `a` (but run.log, which notes the resume) is in `b` with the same bytes,
// and `b` has no other file. Returns the number of files compared.
int expect_same_files(const fs::path& a, const fs::path& b) {
  int compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), a);
    // run.log notes the resume; run.lock is the folder's (empty) lock file (io/run_lock.h).
    if (relative == "run.log" || relative == "run.lock") continue;
    EXPECT_TRUE(fs::exists(b / relative)) << relative;
    EXPECT_TRUE(read_bytes(entry.path()) == read_bytes(b / relative)) << relative << " differs";
    ++compared;
  }
  for (const auto& entry : fs::recursive_directory_iterator(b)) {
    if (entry.is_regular_file()) {
      EXPECT_TRUE(fs::exists(a / fs::relative(entry.path(), b))) << entry.path() << " is extra";
    }
  }
  return compared;
}

// Position of the n-th comma (1-based) of a CSV line.
std::size_t nth_comma(const std::string& line, int n) {
  std::size_t p = std::string::npos;
  for (int k = 0; k < n; ++k)
    p = line.find(',', p + 1);
  return p;
}

// The message of the sg::Error thrown by f ("" if none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A folder left by a run stopped between its second and third checkpoints (at 0.4 and 0.6
// of the duration): rows and snapshots written after the checkpoint are still there.
struct StoppedRun {
  ScenarioDef scenario;
  fs::path out;
  fs::path dir;
  long steps = 0;  // of the whole run
};

const StoppedRun& stopped_shear_cell() {
  static const StoppedRun stopped = [] {
    StoppedRun s;
    s.scenario = scenario_file("cell.toml", shear_cell("cell"));
    s.out = temp_root() / "stopped";
    const RunSummary probe = run(s.scenario, temp_root() / "probe", false, 0);
    const long total = static_cast<long>(std::ceil(0.6 / probe.time_step - 1e-9));
    s.steps = total;
    const RunSummary summary = run(s.scenario, s.out, false, (total * 3) / 5);
    s.dir = summary.directory;
    EXPECT_FALSE(summary.completed);
    EXPECT_EQ(summary.checkpoints_written, 1);  // at t = 0.2 (0.4 comes after the stop)
    return s;
  }();
  return stopped;
}

TEST(CheckpointRestart, StoppedAndResumedRunIsByteIdenticalToAnUninterruptedOne) {
  const StoppedRun& stopped = stopped_shear_cell();
  const fs::path resumed_out = temp_root() / "resumed";
  fs::copy(stopped.out, resumed_out, fs::copy_options::recursive);
  const fs::path dir = resumed_out / "cell";
  // The stopped folder is what a killed run leaves: a partial series with rows written
  // after the checkpoint (0.36 time units of rows, the checkpoint holds 0.2), no series.csv.
  ASSERT_TRUE(fs::exists(dir / "series.csv.partial"));
  ASSERT_FALSE(fs::exists(dir / "series.csv"));
  ASSERT_TRUE(fs::exists(dir / "checkpoint.bin"));
  ASSERT_TRUE(fs::exists(dir / "fields" / "000003.vtu"));  // t = 0.3, after the checkpoint

  const RunSummary resumed = run(stopped.scenario, resumed_out, true);
  EXPECT_TRUE(resumed.completed);
  EXPECT_GT(resumed.resumed_from_step, 0);
  EXPECT_LT(resumed.resumed_from_step, stopped.steps / 2);
  EXPECT_EQ(resumed.steps, stopped.steps);

  const RunSummary whole = run(stopped.scenario, temp_root() / "whole");
  EXPECT_EQ(whole.resumed_from_step, -1);
  EXPECT_EQ(whole.checkpoints_written, 2);
  // series.csv, fields/, contacts/, grains/, the .pvd indexes, checkpoint.bin.
  const int files = expect_same_files(whole.directory, dir);
  EXPECT_EQ(files, 1 + 3 * 7 + 2 + 1);  // 7 snapshots: t = 0, 0.1, ..., 0.5 and the end
  // The run did what makes a restart hard: contacts carry energy, the series has every row.
  const std::string series = read_bytes(dir / "series.csv");
  EXPECT_EQ(std::count(series.begin(), series.end(), '\n'), 1 + 60);
  EXPECT_NE(read_bytes(dir / "run.log").find("resumed from checkpoint.bin at step"),
            std::string::npos);
}

// Runs `s` whole, and stopped at `stop` x its steps then resumed; the two folders must
// match. Returns the resumed run's folder.
fs::path expect_resume_identical(const ScenarioDef& s, const std::string& tag, double stop) {
  const RunSummary whole = run(s, temp_root() / (tag + "_whole"));
  const RunSummary stopped = run(s, temp_root() / (tag + "_resumed"), false,
                                 static_cast<long>(stop * static_cast<double>(whole.steps)));
  EXPECT_FALSE(stopped.completed);
  EXPECT_GE(stopped.checkpoints_written, 2);  // t = 0.05, 0.1, ...
  const RunSummary resumed = run(s, temp_root() / (tag + "_resumed"), true);
  EXPECT_GT(resumed.resumed_from_step, 0);
  EXPECT_TRUE(resumed.completed);
  EXPECT_EQ(expect_same_files(whole.directory, stopped.directory), 1 + 3 * 5 + 2 + 1);
  return stopped.directory;
}

std::string seam_scene(const std::string& time_keys) {
  return std::string(R"(
name = "seam"
[time]
duration = 0.2
)") + time_keys +
         R"(
[output]
series_period = 0.002
field_period = 0.05
checkpoint_period = 0.05
)" + scenes::kTinyScenarioBody +
         scenes::kSeamGrains;
}

TEST(CheckpointRestart, GrainCrossingTheSeamResumesExactly) {
  // The tiny scene (floor, soft and rigid discs, three laws) made periodic, with two more
  // soft grains that meet across the seam x = 3 and bond; stopped after the crossing.
  const ScenarioDef s = scenario_file("seam.toml", seam_scene(""));
  const fs::path whole = expect_resume_identical(s, "seam", 0.7);  // identical to the whole run
  // The crossing grain wrapped (its centre went from x = 2.4 moving +x to x < 0), and
  // contacts dissipated or stored energy (the ledger's contact column is not 0).
  const std::string grains = read_bytes(whole / "grains" / "000004.csv");
  std::istringstream lines(grains);
  std::string line;
  std::getline(lines, line);  // header
  std::vector<double> x;
  while (std::getline(lines, line))
    x.push_back(std::stod(line.substr(line.find(',') + 1)));
  ASSERT_EQ(x.size(), 5u);
  EXPECT_LT(x[2], 0.0) << grains;  // bodies: the tiny scene's 2 grains, ours, the floor
  const std::string series = read_bytes(whole / "series.csv");
  const std::string last = series.substr(series.rfind('\n', series.size() - 2) + 1);
  EXPECT_NE(std::stod(last.substr(nth_comma(last, 7) + 1)), 0.0) << last;
}

TEST(CheckpointRestart, RunWithRejectedStepsResumesExactly) {
  // The same scene with the step control's energy check tight enough to reject a step: at
  // tolerance 0.0006 the collision of the two grains at t = 0.1058 (step 45 of 123) changes
  // the residual by 0.0016 in one step of 0.00235; the step is retried at half, which is
  // accepted, and grows back 50 steps later. Stopped at half the steps, after the rejection:
  // the resumed run starts from the checkpoint at t = 0.1 and repeats the rejection, the
  // retried step and the smaller steps after it identically. Measured with the
  // variable-step update (solver/stepper.h) and the contact-consistent contour rows
  // (meshfree/contour_rows.h): one rejection at every tolerance from 0.0003 to 0.0008
  // (0.0003-0.0006 at t = 0.1058, 0.0007-0.0008 at t = 0.1105), three at 0.0001. Before the
  // variable-step update (v_n+1/2 = v_n-1/2 + dt_n+1/2 a_n), every tolerance up to 0.0006
  // failed outright at the collision: a retried step showed the same residual change
  // whatever its size (-0.0096 at 0.0006 after 9 halvings to dt = 8.6e-6), the first-order
  // energy error 1/2 (dt_+ - dt_-) v . f of changing the step.
  const ScenarioDef s = scenario_file("seam_rejected.toml", seam_scene("step_tolerance = 0.0006"));
  const fs::path resumed = expect_resume_identical(s, "rejected", 0.5);
  const std::string log = read_bytes(resumed / "run.log");
  const std::string note = "resumed from checkpoint.bin at step ";
  ASSERT_NE(log.find(note), std::string::npos) << log;
  const std::string after = log.substr(log.find(note));
  EXPECT_LT(std::stod(after.substr(after.find(", time ") + 7)), 0.1057) << log;
  EXPECT_NE(log.find(" 1 rejected"), std::string::npos) << log;
  EXPECT_NE(log.find("last rejection: t = 0.1057"), std::string::npos) << log;
}

TEST(CheckpointRestart, DamagedCheckpointIsRefusedNamingTheFileAndTheReason) {
  const StoppedRun& stopped = stopped_shear_cell();
  const fs::path original = stopped.dir / "checkpoint.bin";
  const std::string bytes = read_bytes(original);
  ASSERT_GT(bytes.size(), 1000u);
  const fs::path out = temp_root() / "damaged";
  const fs::path checkpoint = out / "cell" / "checkpoint.bin";
  auto resume_with = [&](const std::string& content) {
    fs::remove_all(out);
    fs::copy(stopped.out, out, fs::copy_options::recursive);
    write_bytes(checkpoint, content);
    return error_of([&] { run(stopped.scenario, out, true); });
  };
  const std::string named = "checkpoint '" + checkpoint.string() + "': ";

  std::string flipped = bytes;
  flipped[bytes.size() / 2] = static_cast<char>(flipped[bytes.size() / 2] ^ 0x01);
  std::string message = resume_with(flipped);
  EXPECT_NE(message.find(named + "corrupted (the checksum"), std::string::npos) << message;

  message = resume_with(bytes.substr(0, bytes.size() - 100));
  EXPECT_NE(message.find(named + "truncated"), std::string::npos) << message;
  message = resume_with(bytes.substr(0, 10));
  EXPECT_NE(message.find(named + "truncated"), std::string::npos) << message;

  std::string other = bytes;
  other[0] = 'X';
  message = resume_with(other);
  EXPECT_NE(message.find(named + "not a softgrain checkpoint"), std::string::npos) << message;

  std::string version = bytes;
  version[8] = static_cast<char>(version[8] + 1);
  message = resume_with(version);
  EXPECT_NE(message.find(named + "format version"), std::string::npos) << message;

  // The intact file still resumes (the refusals came from the damage, not the setup).
  EXPECT_EQ(resume_with(bytes), "");
  // One line.
  EXPECT_EQ(resume_with(flipped).find('\n'), std::string::npos);
}

TEST(CheckpointRestart, CheckpointOfAnotherScenarioIsRefused) {
  const StoppedRun& stopped = stopped_shear_cell();
  auto resume_other = [&](const std::string& file, const std::string& text) {
    const ScenarioDef other = scenario_file(file, text);
    const fs::path out = temp_root() / ("other_" + other.name);
    fs::remove_all(out);
    fs::create_directories(out);
    fs::copy(stopped.out / "cell", out / other.name, fs::copy_options::recursive);
    return error_of([&] { run(other, out, true); });
  };
  // Another sample: 9 grains instead of 8.
  std::string message = resume_other("nine.toml", shear_cell("nine", 9));
  EXPECT_NE(message.find("checkpoint.bin': written for another model ("), std::string::npos)
      << message;
  // Same sizes, other material: the counts agree, the model hash does not.
  const std::string stiffer =
      scenes::replace_once(shear_cell("stiffer"), "young = 10.0", "young = 12.0");
  message = resume_other("stiffer.toml", stiffer);
  EXPECT_NE(message.find("written for another model (same sizes"), std::string::npos) << message;
  // Same model, another time step.
  message = resume_other("step.toml", shear_cell("step", 8, "fixed_step = 0.0005"));
  EXPECT_NE(message.find("written with other run settings"), std::string::npos) << message;
}

TEST(CheckpointRestart, ResumeNeedsACheckpointAndAnUnfinishedRun) {
  const StoppedRun& stopped = stopped_shear_cell();
  const fs::path out = temp_root() / "no_checkpoint";
  fs::copy(stopped.out, out, fs::copy_options::recursive);
  fs::remove(out / "cell" / "checkpoint.bin");
  std::string message = error_of([&] { run(stopped.scenario, out, true); });
  EXPECT_NE(message.find("no checkpoint.bin"), std::string::npos) << message;

  // A completed run (resumed to the end) has nothing left to resume.
  fs::copy(stopped.out, out, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  ASSERT_TRUE(run(stopped.scenario, out, true).completed);
  message = error_of([&] { run(stopped.scenario, out, true); });
  EXPECT_NE(message.find("the run is complete"), std::string::npos) << message;
}

}  // namespace
}  // namespace sg

namespace sg {
namespace {

// The IMEX integrator on the shear cell (the objective model, whose preconditioners are built
// at reference states of the grains, and the reference-stiffness model, whose viscous forces
// the solves carry from step to step; solver/implicit_viscosity.h): a run stopped after a
// checkpoint and resumed ends byte-identical to an uninterrupted one, and 1 and 2 threads
// give the same bytes; with the objective model's split solve (the default) and its exact one.
// `solve`: "split", "exact" or "reference_stiffness".
std::string imex_shear_cell(const std::string& name, const std::string& solve) {
  scenes::CohesiveShearCell c;
  c.name = name;
  c.duration = 0.6;
  if (solve == "reference_stiffness") {
    c.extra_time = "integrator = \"imex\"";
    c.damping_model = solve;
  } else {
    c.extra_time = "integrator = \"imex\"\nimex_objective = \"" + solve + "\"";
  }
  c.checkpoint_period = 0.2;
  c.compaction_time = 0.15;
  c.velocity = 4.0;
  c.damping = 0.05;  // explicit limit 5x below the undamped one at this spacing
  return scenes::shear_cell_scenario(c);
}

void expect_imex_run_resumes_exactly(const std::string& solve) {
  const ScenarioDef s = scenario_file("imex_" + solve + ".toml", imex_shear_cell("imex", solve));
  omp_set_num_threads(2);
  const RunSummary whole = run(s, temp_root() / ("imex_whole_" + solve));
  const fs::path resumed_out = temp_root() / ("imex_resumed_" + solve);
  const RunSummary stopped = run(s, resumed_out, false, (whole.steps * 3) / 5);
  EXPECT_FALSE(stopped.completed);
  EXPECT_EQ(stopped.checkpoints_written, 1);
  const RunSummary resumed = run(s, resumed_out, true);
  EXPECT_TRUE(resumed.completed);
  EXPECT_GT(resumed.resumed_from_step, 0);
  const int files = expect_same_files(whole.directory, resumed.directory);
  EXPECT_EQ(files, 1 + 3 * 7 + 2 + 1);

  omp_set_num_threads(1);
  const RunSummary one_thread = run(s, temp_root() / ("imex_one_thread_" + solve));
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_EQ(expect_same_files(whole.directory, one_thread.directory), files);

  // The run used what makes IMEX hard to repeat: rebuilt references and (exact solve)
  // iterations; carried viscous forces (reference_stiffness).
  const std::string log = read_bytes(whole.directory / "run.log");
  const std::size_t at = log.find("# imex: ");
  ASSERT_NE(at, std::string::npos) << log;
  const std::string note = log.substr(at, log.find('\n', at) - at);
  std::printf("%s\n", note.c_str());
  if (solve == "reference_stiffness") {
    EXPECT_NE(note.find(" carried viscous forces"), std::string::npos) << note;
    return;
  }
  const auto count_before = [&](const std::string& what) {
    const std::size_t end = note.find(what);
    const std::size_t begin = note.rfind(", ", end) + 2;
    return std::stol(note.substr(begin, end - begin));
  };
  EXPECT_GT(count_before(" reassemblies"), 8);  // more than one per grain
  const long iterations = std::stol(note.substr(note.find("solves, ") + 8));
  if (solve == "exact")
    EXPECT_GT(iterations, 0) << note;
  else
    EXPECT_EQ(iterations, 0) << note;
}

TEST(CheckpointRestart, ImexRunResumesExactlyAndIsThreadIndependent) {
  for (const std::string solve : {"split", "exact", "reference_stiffness"}) {
    SCOPED_TRACE(solve);
    expect_imex_run_resumes_exactly(solve);
  }
}

}  // namespace
}  // namespace sg
