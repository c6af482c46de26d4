// How softgrain's threads wait at barriers (core/wait_policy.h): a run spins briefly only where
// each of its threads has a free core, everything else sleeps, a user's choice is kept, and
// run.log says which policy the run had and why.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "app/command_output.h"
#include "core/wait_policy.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;
using test::run_command;
using test::softgrain;

TEST(WaitPolicy, ARunSpinsOnlyWhenEveryThreadHasAFreeCore) {
  EXPECT_TRUE(choose_wait_policy("run", 2, 2, 0).spin);
  EXPECT_FALSE(choose_wait_policy("run", 2, 2, 1).spin);  // a busy process beside it
  EXPECT_TRUE(choose_wait_policy("run", 2, 3, 1).spin);
  EXPECT_TRUE(choose_wait_policy("run", 4, 64, 60).spin);  // a cluster node's other jobs
  EXPECT_FALSE(choose_wait_policy("run", 8, 64, 60).spin);
  const WaitPolicyChoice shared = choose_wait_policy("run", 2, 2, 3);
  EXPECT_NE(shared.reason.find("3 other runnable processes, 2 threads on 2 cores"),
            std::string::npos)
      << shared.reason;
}

TEST(WaitPolicy, OneThreadAndOtherSubcommandsSleep) {
  EXPECT_FALSE(choose_wait_policy("run", 1, 2, 0).spin);
  // A sweep's runs inherit its choice: several runs share the cores.
  EXPECT_FALSE(choose_wait_policy("sweep", 2, 2, 0).spin);
  EXPECT_FALSE(choose_wait_policy("analyze", 2, 2, 0).spin);
  // info times steps to predict a run's cost: it waits as a run would.
  EXPECT_TRUE(choose_wait_policy("info", 2, 2, 0).spin);
  EXPECT_FALSE(choose_wait_policy("", 2, 2, 0).spin);
}

// A tiny run of the real executable with the given environment prefix; returns its run.log.
std::string run_log_with(const std::string& environment, const std::string& label) {
  const fs::path dir = scenes::process_temp_dir("wait_policy_" + label);
  scenes::write_text_file(dir / "tiny.toml", scenes::tiny_scenario("0.01"));
  const auto run = run_command("env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u " +
                               std::string(kWaitPolicyReasonVariable) + " " + environment + " " +
                               softgrain() + " --threads 1 run '" + (dir / "tiny.toml").string() +
                               "' -o '" + (dir / "out").string() + "'");
  EXPECT_EQ(run.status, 0) << run.text;
  const std::string log = scenes::read_text_file(dir / "out" / "tiny" / "run.log");
  fs::remove_all(dir);
  return log;
}

TEST(WaitPolicy, RunLogSaysWhichPolicyTheRunHadAndWhy) {
  // The program's own choice: one thread sleeps.
  EXPECT_NE(run_log_with("", "chosen")
                .find("omp_wait = \"passive\"  # one thread: no barrier to wait at"),
            std::string::npos);
  // The user's choices are kept.
  EXPECT_NE(run_log_with("GOMP_SPINCOUNT=500", "spin")
                .find("omp_wait = \"spin 500\"  # set in the environment"),
            std::string::npos);
  EXPECT_NE(run_log_with("OMP_WAIT_POLICY=ACTIVE", "active")
                .find("omp_wait = \"active\"  # set in the environment"),
            std::string::npos);
}

}  // namespace
}  // namespace sg
