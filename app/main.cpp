// softgrain: the command line. Thin: parses options, dispatches to the subcommands
// (app/commands/*.cpp), prints errors once.
#include <omp.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>

#include "command_registry.h"
#include "core/error.h"
#include "core/nearest_name.h"
#include "core/version.h"
#include "core/wait_policy.h"

namespace sg::app {

std::vector<Command>& command_registry() {
  static std::vector<Command> commands;
  return commands;
}

void apply_threads(const GlobalOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
}

// The processes (threads) ready to run on the machine besides this one: the fewest of five
// readings of /proc/loadavg's "running/total" field 2 ms apart (a process that only passes by
// is not a competitor); unknown: as many as there are cores.
int other_runnable() {
  int fewest = -1;
  for (int reading = 0; reading < 5; ++reading) {
    if (reading > 0) usleep(2000);
    std::ifstream in("/proc/loadavg");
    double load1 = 0, load5 = 0, load15 = 0;
    int running = 0;
    if (!(in >> load1 >> load5 >> load15 >> running)) continue;
    if (fewest < 0 || running < fewest) fewest = running;
  }
  if (fewest < 0) return static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  return std::max(0, fewest - 1);  // this process is one of them
}

// How the OpenMP threads wait at barriers (core/wait_policy.h): libgomp reads the variables
// when it is loaded, before main, so unless the user chose (OMP_WAIT_POLICY or
// GOMP_SPINCOUNT), the program sets them and executes itself again, once (if that fails it
// goes on as is). The choice needs the subcommand and the thread count before CLI11 has
// parsed them: the first word of the command line that is neither an option nor the value
// of --threads, and --threads N (--threads=N), else the cores the process may run on.
void choose_omp_wait_policy(int argc, char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  std::string subcommand;
  int threads = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--threads" && i + 1 < argc)
      threads = std::atoi(argv[++i]);
    else if (word.rfind("--threads=", 0) == 0)
      threads = std::atoi(word.c_str() + 10);
    else if (subcommand.empty() && !word.empty() && word.front() != '-')
      subcommand = word;
  }
  cpu_set_t allowed;
  const int usable = sched_getaffinity(0, sizeof allowed, &allowed) == 0 ? CPU_COUNT(&allowed) : 1;
  if (threads <= 0) threads = usable;
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  const sg::WaitPolicyChoice choice =
      sg::choose_wait_policy(subcommand, threads, static_cast<int>(cores), other_runnable());
  if (choice.spin)
    setenv("GOMP_SPINCOUNT", std::to_string(sg::kBarrierSpinCount).c_str(), 1);
  else
    setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
  setenv(sg::kWaitPolicyReasonVariable, choice.reason.c_str(), 1);
  execv("/proc/self/exe", argv);
}

// CLI11 answers a misspelled subcommand ("softgrain rnu x.toml") with "A subcommand is
// required", which does not say what went wrong: the word it did not know is the first
// argument left over, so name it with the nearest subcommand.
int report_parse_error(CLI::App& app, const CLI::ParseError& e) {
  const std::vector<std::string> left = app.remaining();
  if (dynamic_cast<const CLI::RequiredError*>(&e) && app.get_subcommands().empty() &&
      !left.empty() && !left.front().empty() && left.front().front() != '-') {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({}))
      names.push_back(sub->get_name());
    std::cerr << "softgrain: unknown subcommand '" << left.front() << "'; nearest: '"
              << nearest_name(left.front(), names) << "' (subcommands: " << join_names(names)
              << "; softgrain --help)\n";
    return static_cast<int>(CLI::ExitCodes::RequiredError);
  }
  return app.exit(e);
}

}  // namespace sg::app

int main(int argc, char** argv) {
  using namespace sg::app;
  choose_omp_wait_policy(argc, argv);
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
  app.set_version_flag("--version", sg::softgrain_version_line(),
                       "print the version and the git commit it was built from");
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, e);
  }
  try {
    for (auto& [sub, run] : runners)
      if (sub->parsed()) return run();
  } catch (const sg::Error& e) {
    std::cerr << "\nsoftgrain: error: " << e.what() << "\n";
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // Something a user can cause (a file where a folder should be, no permission, a full
    // disk): an error, not an "unexpected" one. Its text names the paths.
    std::cerr << "\nsoftgrain: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "\nsoftgrain: error: out of memory: the input asks for more memory than "
                 "this machine has (a count, a size or a node spacing too large for it; "
                 "`softgrain info` estimates the memory of a scenario)\n";
    return 1;
  } catch (const std::length_error& e) {
    std::cerr << "\nsoftgrain: error: out of memory: the input asks for a container larger "
                 "than can be allocated ("
              << e.what() << "; a count, a size or a velocity far too large?)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "\nsoftgrain: unexpected error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
