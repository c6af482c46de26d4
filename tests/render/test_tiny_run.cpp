// The tiny run of tiny_run.h (no tests here).
#include <filesystem>
#include <fstream>

#include "io/run.h"
#include "scenario/scenario.h"
#include "scenes/tiny_scenario.h"
#include "tiny_run.h"

#include <omp.h>
#include <unistd.h>

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

const std::string kTinyShear = R"(
name = "tiny-shear"
[time]
duration = 4.0
[output]
series_period = 0.01
field_period = 0.1
[discretization]
node_spacing = 0.25
[[materials]]
name = "soft"
young = 10.0
poisson = 0.3
density = 1.0
damping = 0.01
[[materials]]
name = "first_body"
young = 1000.0
density = 1.0
[[contact_laws]]
materials = ["soft", "soft"]
law = "cohesive"
normal_stiffness = 1000.0
cohesion = 0.1
[[contact_laws]]
materials = ["soft", "first_body"]
law = "cohesive"
normal_stiffness = 1000.0
cohesion = 0.1
[[contact_laws]]
materials = ["first_body", "first_body"]
law = "frictionless"
normal_stiffness = 1000.0
[shear_cell]
length = 8.0
grains = 20
diameter = [0.85, 1.15]
grain_material = "soft"
first_body_material = "first_body"
roughness_rms = 0.2
gap = 2.6
compaction_time = 1.5
velocity = 1.0
seed = 3
)";

fs::path simulate(const std::string& tag, const std::string& scenario_text) {
  // One folder per process: ctest runs the tests of this binary in parallel processes.
  const fs::path root =
      fs::temp_directory_path() / ("softgrain_test_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path scenario = root / (tag + ".toml");
  std::ofstream(scenario) << scenario_text;
  RunOptions options;
  options.output_root_override = root / "out";
  // One thread: ctest runs test processes side by side on a small machine, and spinning
  // OpenMP threads competing for its cores made a half-second run take a minute.
  omp_set_num_threads(1);
  return run_scenario(load_scenario(scenario), options).directory;
}

}  // namespace

const fs::path& tiny_shear_run_dir() {
  static const fs::path dir = simulate("render_shear", kTinyShear);
  return dir;
}

const fs::path& tiny_run_dir() {
  static const fs::path dir = simulate("render", kTiny);
  return dir;
}

}  // namespace sg::test
