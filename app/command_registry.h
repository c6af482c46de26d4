#pragma once
// Each subcommand lives in its own file under app/commands/ and registers itself here with a
// static Registration object, so commands can be added without touching main.cpp.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace sg::app {

struct GlobalOptions {
  int threads = 0;  // 0: all cores
};

struct Command {
  std::string name;
  // Adds the subcommand to `app` and returns the function that runs it once parsed.
  std::function<std::function<int()>(CLI::App& app, const GlobalOptions& options)> setup;
  int order = 100;  // position in --help
};

std::vector<Command>& command_registry();

struct Registration {
  explicit Registration(Command command) { command_registry().push_back(std::move(command)); }
};

// Applies --threads.
void apply_threads(const GlobalOptions& options);

}  // namespace sg::app
