// softgrain: the command line. Thin: parses options, dispatches to the subcommands
// (app/commands/*.cpp), prints errors once.
#include <omp.h>

#include <algorithm>
#include <iostream>

#include "command_registry.h"
#include "core/error.h"

namespace sg::app {

std::vector<Command>& command_registry() {
  static std::vector<Command> commands;
  return commands;
}

void apply_threads(const GlobalOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
}

}  // namespace sg::app

int main(int argc, char** argv) {
  using namespace sg::app;
  CLI::App app{
      "softgrain: 2D simulation of rigid and highly deformable grains (multibody meshfree)"};
  app.footer(
      "Examples:\n"
      "  softgrain run examples/free-grains.toml            simulate; outputs in out/<name>/\n"
      "  softgrain run examples/free-grains.toml --threads 2\n"
      "  softgrain info examples/free-grains.toml           bodies, nodes, step, memory\n"
      "  softgrain generate examples/compaction-box.toml    build the sample only: "
      "out/<name>/sample/\n"
      "Each subcommand has its own --help.");
  app.require_subcommand(1);
  // Global options (--threads) are accepted after the subcommand too: subcommands created
  // below inherit this and pass options they do not know to the main app.
  app.fallthrough();
  GlobalOptions options;
  app.add_option("--threads", options.threads, "OpenMP threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  std::vector<Command> commands = command_registry();
  std::sort(commands.begin(), commands.end(),
            [](const Command& a, const Command& b) { return a.order < b.order; });
  std::vector<std::pair<CLI::App*, std::function<int()>>> runners;
  for (const Command& c : commands) {
    const std::size_t before = app.get_subcommands({}).size();
    std::function<int()> run = c.setup(app, options);
    CLI::App* sub = app.get_subcommands({})[before];
    runners.emplace_back(sub, std::move(run));
  }
  CLI11_PARSE(app, argc, argv);
  try {
    for (auto& [sub, run] : runners)
      if (sub->parsed()) return run();
  } catch (const sg::Error& e) {
    std::cerr << "\nsoftgrain: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "\nsoftgrain: unexpected error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
