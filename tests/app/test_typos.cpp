// A typo on the command line is answered with the name meant: an unknown subcommand names
// the nearest one, a misspelled render --field lists the valid fields (coherence included), a
// campaign's misspelt analyze option stops the sweep before its first run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "app/command_output.h"
#include "core/nearest_name.h"

namespace sg {
namespace {

using test::run_command;
using test::softgrain;

TEST(NearestName, EditDistanceCountsInsertionsDeletionsSubstitutions) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("run", ""), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // k->s, e->i, +g
  EXPECT_EQ(edit_distance("rnu", "run"), 2u);         // a transposition is two edits
  EXPECT_EQ(edit_distance("analyse", "analyze"), 1u);
}

TEST(NearestName, PicksTheClosestIgnoringCase) {
  const std::vector<std::string> commands = {"generate", "run",    "info",
                                             "analyze",  "render", "sweep"};
  EXPECT_EQ(nearest_name("analyse", commands), "analyze");
  EXPECT_EQ(nearest_name("RUN", commands), "run");
  EXPECT_EQ(nearest_name("swep", commands), "sweep");
  EXPECT_EQ(nearest_name("rendr", commands), "render");
  EXPECT_EQ(nearest_name("x", {}), "");
}

TEST(CommandLine, AnUnknownSubcommandNamesTheNearest) {
  const auto out = run_command(softgrain() + " analyse some/run");
  EXPECT_NE(out.status, 0);
  EXPECT_NE(out.text.find("unknown subcommand 'analyse'; nearest: 'analyze'"), std::string::npos)
      << out.text;
  EXPECT_EQ(out.text.find("A subcommand is required"), std::string::npos) << out.text;
  // After a global option too.
  const auto threads = run_command(softgrain() + " --threads 1 swep c.toml");
  EXPECT_NE(threads.status, 0);
  EXPECT_NE(threads.text.find("unknown subcommand 'swep'; nearest: 'sweep'"), std::string::npos)
      << threads.text;
}

TEST(CommandLine, NoSubcommandStillSaysOneIsRequired) {
  const auto out = run_command(softgrain());
  EXPECT_NE(out.status, 0);
  EXPECT_NE(out.text.find("A subcommand is required"), std::string::npos) << out.text;
}

TEST(CommandLine, AMisspelledRenderFieldListsTheChoices) {
  // Checked before the run folder is read: no folder is needed to get the answer.
  const auto out = run_command(softgrain() + " render /nonexistent --field velocty");
  EXPECT_NE(out.status, 0);
  EXPECT_NE(out.text.find("unknown field 'velocty'; nearest: 'velocity'"), std::string::npos)
      << out.text;
  for (const char* field : {"von_mises", "strain_rate", "coherence", "body", "sigma_xy"})
    EXPECT_NE(out.text.find(field), std::string::npos) << field << " missing in " << out.text;
}

TEST(CommandLine, AMisspeltAnalyzeOptionStopsTheCampaignBeforeItsRuns) {
  // Each run would otherwise simulate, then fail its analysis.
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("softgrain-analyze-options-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "c.toml") << "name = \"typo\"\n"
                                << "scenario = \"" << SOFTGRAIN_SOURCE_DIR
                                << "/examples/free-grains.toml\"\n"
                                << "output = \"out\"\n"
                                << "analyze_options = [\"--no-agglomeratez\"]\n"
                                << "[grid]\n\"materials.0.young\" = [10.0, 20.0]\n";
  const auto out = run_command(softgrain() + " sweep '" + (dir / "c.toml").string() + "'");
  EXPECT_NE(out.status, 0);
  EXPECT_NE(out.text.find("c.toml:4: key 'analyze_options'"), std::string::npos) << out.text;
  EXPECT_NE(out.text.find("--no-agglomeratez"), std::string::npos) << out.text;
  EXPECT_FALSE(fs::exists(dir / "out")) << "the sweep wrote its campaign folder";
  // The same campaign with the option spelt right starts (a dry run: nothing simulated).
  const auto good =
      run_command("sed -i 's/agglomeratez/agglomerates/' '" + (dir / "c.toml").string() + "' && " +
                  softgrain() + " sweep --dry-run --no-plan '" + (dir / "c.toml").string() + "'");
  EXPECT_EQ(good.status, 0) << good.text;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sg
