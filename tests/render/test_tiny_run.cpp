// The tiny run of tiny_run.h (no tests here).
#include <filesystem>
#include <fstream>

#include "io/run.h"
#include "scenario/scenario.h"
#include "scenes/tiny_scenario.h"
#include "tiny_run.h"

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
