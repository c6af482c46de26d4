// The tiny run of tiny_run.h (no tests here).
#include <filesystem>
#include <fstream>

#include "io/run.h"
#include "scenario/scenario.h"
#include "tiny_run.h"

#include <unistd.h>

#include <string>

namespace sg::test {
namespace {

namespace fs = std::filesystem;

const char* kTiny = R"(
name = "tiny"
[time]
duration = 0.06
[output]
series_period = 0.002
field_period = 0.02
[discretization]
node_spacing = 0.15
[[materials]]
name = "soft"
young = 10.0
poisson = 0.3
damping = 0.01
[[materials]]
name = "hard"
young = 100.0
[[contact_laws]]
materials = ["soft", "hard"]
law = "coulomb"
normal_stiffness = 1000.0
friction = 0.3
[[contact_laws]]
materials = ["soft", "soft"]
law = "cohesive"
normal_stiffness = 1000.0
cohesion = 0.5
[[contact_laws]]
materials = ["hard", "hard"]
law = "frictionless"
normal_stiffness = 1000.0
[[walls]]
name = "floor"
lower_left = [-2.0, -1.0]
upper_right = [2.0, -0.5]
material = "hard"
[[grains]]
center = [0.0, 0.0]
radius = 0.5
material = "soft"
velocity = [0.0, -1.0]
[[grains]]
center = [1.2, 0.0]
radius = 0.4
material = "hard"
rigid = true
)";

}  // namespace

const fs::path& tiny_run_dir() {
  static const fs::path dir = [] {
    // One folder per process: ctest runs the tests of this binary in parallel processes.
    const fs::path root =
        fs::temp_directory_path() / ("softgrain_test_render_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root);
    const fs::path scenario = root / "tiny.toml";
    std::ofstream(scenario) << kTiny;
    RunOptions options;
    options.output_root_override = root / "out";
    return run_scenario(load_scenario(scenario), options).directory;
  }();
  return dir;
}

}  // namespace sg::test
