// The tiny compaction-box run of tiny_compaction_run.h (no tests here).
#include <omp.h>

#include <string>
#include <system_error>

#include "report/sample_report.h"
#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"
#include "tiny_compaction_run.h"

namespace sg::test {
namespace {

namespace fs = std::filesystem;

const std::string kTinyBox = R"(name = "tiny-box"
[time]
duration = 2.51
[output]
series_period = 0.05
field_period = 0.25
)" + std::string(scenes::kSoftHardCoulomb) +
                             R"([compaction_box]
width = 3.0
grains = 8
grain_material = "soft"
wall_material = "hard"
lid_velocity = 0.5
lid_ramp_time = 0.2
final_height = 2.7
seed = 3
[[compaction_box.components]]
name = "rigid"
shape = "fourier"
fraction = 2.0
diameter = [0.8, 1.2]
elongation = 0.15
irregularity = 0.06
material = "hard"
rigid = true
[[compaction_box.components]]
name = "soft"
shape = "disc"
fraction = 1.0
diameter = [0.8, 1.2]
material = "soft"
)";

TinyCompactionRun simulate() {
  const fs::path root = scenes::process_temp_dir("compaction_run");
  const ScenarioDef s = load_scenario(scenes::write_text_file(root / "tiny-box.toml", kTinyBox));
  RunOptions options;
  options.output_root_override = root / "out";
  omp_set_num_threads(1);  // see test_tiny_run.cpp
  TinyCompactionRun run;
  run.dir = run_scenario(s, options).directory;
  // `softgrain generate` (app/commands/generate_command.cpp): the sample as built, measured.
  Model model = build_model(s);
  write_sample(model, measure_sample(s, model), run.dir / "sample");
  // The builder's own account of the lid: where and when it stops.
  Model fresh;
  for (const MaterialDef& m : s.materials)
    fresh.add_material(m);
  const CompactionBoxInfo info =
      add_compaction_box(fresh, *s.compaction_box, 0, 1, s.discretization);
  run.width = s.compaction_box->width;
  run.final_height = info.final_height;
  run.stop_time = info.stop_time;
  run.lid_velocity = s.compaction_box->lid_velocity;
  run.lid_ramp_time = s.compaction_box->lid_ramp_time;
  return run;
}

}  // namespace

const TinyCompactionRun& tiny_compaction_run() {
  static const TinyCompactionRun run = simulate();
  // The folder goes when the test process ends (ctest runs each test in a process of its own,
  // each simulating the box into its own folder; they used to pile up in the temp directory).
  struct RemovedAtExit {
    fs::path root;
    ~RemovedAtExit() {
      std::error_code ignored;
      fs::remove_all(root, ignored);
    }
  };
  static const RemovedAtExit cleanup{run.dir.parent_path().parent_path()};  // <root>/out/<name>
  return run;
}

}  // namespace sg::test
