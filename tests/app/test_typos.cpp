// A typo on the command line is answered with the name meant: an unknown subcommand names
// the nearest one, a misspelled render --field lists the valid fields (coherence included).
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sg
