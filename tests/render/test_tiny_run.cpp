// The tiny run of tiny_run.h (no tests here).
#include <filesystem>
#include <fstream>

#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/shear_cell_scenario.h"
#include "scenes/tiny_scenario.h"
#include "tiny_run.h"

#include <omp.h>

#include <string>

namespace sg::test {
namespace {

namespace fs = std::filesystem;

const std::string kTiny = std::string(R"(
name = "tiny"
[time]
duration = 0.06
[output]
series_period = 0.002
field_period = 0.02
)") + scenes::kTinyScenarioBody;

// 20 soft cohesive grains, L = 8, D = 2.6, V = 1, 4 time units (see tiny_run.h).
std::string tiny_shear() {
  scenes::CohesiveShearCell c;
  c.name = "tiny-shear";
  c.duration = 4.0;
  c.poisson = 0.3;
  c.normal_stiffness = 1000.0;
  c.length = 8.0;
  c.grains = 20;
  c.gap = 2.6;
  c.compaction_time = 1.5;
  return scenes::shear_cell_scenario(c);
}

fs::path simulate(const std::string& tag, const std::string& scenario_text) {
  const fs::path root = scenes::process_temp_dir(tag);
  const fs::path scenario = scenes::write_text_file(root / (tag + ".toml"), scenario_text);
  RunOptions options;
  options.output_root_override = root / "out";
  // One thread: ctest runs test processes side by side on a small machine, and spinning
  // OpenMP threads competing for its cores made a half-second run take a minute.
  omp_set_num_threads(1);
  return run_scenario(load_scenario(scenario), options).directory;
}

}  // namespace

const fs::path& tiny_shear_run_dir() {
  static const fs::path dir = simulate("render_shear", tiny_shear());
  return dir;
}

const fs::path& tiny_run_dir() {
  static const fs::path dir = simulate("render", kTiny);
  return dir;
}

}  // namespace sg::test
