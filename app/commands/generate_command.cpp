// softgrain generate SCENARIO: build the sample exactly as `run` would (build_model, same
// seed) and write <run folder>/sample/: sample.vtu, sample.json, sample.png, plus a table on
// the terminal (report/sample_report.h).
#include <iostream>

#include "command_registry.h"
#include "core/error.h"
#include "render/sample_picture.h"
#include "report/sample_report.h"

namespace sg::app {
namespace {

struct GenerateArguments {
  std::string scenario;
  std::string output;
  bool picture = true;
};

int generate(const GenerateArguments& args) {
  const ScenarioDef scenario = load_scenario(args.scenario);
  const std::filesystem::path root =
      args.output.empty() ? scenario.output_root : std::filesystem::path(args.output);
  const std::filesystem::path dir = root / scenario.name / "sample";
  Model model = build_model(scenario);
  // The files first (t = 0 as built), then the measurements that mass scaling may touch.
  std::filesystem::create_directories(dir);
  const SampleReport report = measure_sample(scenario, model);
  write_sample(model, report, dir);
  std::string picture;
  if (args.picture) {
    try {
      picture = draw_sample_picture(model, dir, scenario.name + " (sample, t = 0)").string();
    } catch (const Error& e) {
      picture = std::string("none (") + e.what() + ")";
    }
  }
  std::cout << sample_table(report) << "  files           " << (dir / "sample.vtu").string() << ", "
            << (dir / "sample.json").string();
  if (!picture.empty()) std::cout << ", " << picture;
  std::cout << "\n";
  return report.overlapping_pairs > 0 ? 1 : 0;
}

const Registration registration(
    {"generate",
     [](CLI::App& app, const GlobalOptions& options) {
       auto args = std::make_shared<GenerateArguments>();
       CLI::App* sub = app.add_subcommand(
           "generate",
           "Build the sample as run would (same seed) and write <run folder>/sample/: "
           "sample.vtu, sample.json (counts, solid fraction, sizes with their KS distance to "
           "the requested law, roughness RMS and spectral slope, smallest gap, step, memory), "
           "sample.png");
       sub->add_option("scenario", args->scenario, "scenario TOML file")->required();
       sub->add_option("-o,--output", args->output,
                       "output root folder (overrides [output] directory)");
       sub->add_flag("!--no-picture", args->picture, "skip sample.png");
       return std::function<int()>([args, &options] {
         apply_threads(options);
         return generate(*args);
       });
     },
     5});

}  // namespace
}  // namespace sg::app
