// `sweep --slurm` without a cluster: the [slurm] table and its command-line overrides (every
// malformed key or option named in the error), the job-array script, and the parsers of
// sbatch, squeue and sacct output. The submission itself is tested against a running Slurm
// in tests/slurm/.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "campaign/campaign_def.h"
#include "campaign/slurm_campaign.h"
#include "campaign/slurm_commands.h"
#include "campaign/slurm_script.h"
#include "campaign/slurm_settings.h"
#include "core/error.h"
#include "core/wait_policy.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// The test folder goes when the test process ends (ctest runs each test in a process).
class RemoveTestFolder : public ::testing::Environment {
 public:
  void TearDown() override { fs::remove_all(scenes::process_temp_dir("slurm_settings")); }
};
[[maybe_unused]] const auto* const kRemoveTestFolder =
    ::testing::AddGlobalTestEnvironment(new RemoveTestFolder);

fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = scenes::process_temp_dir("slurm_settings") / name;
  std::ofstream(p) << text;
  return p;
}

// A campaign of two runs with `slurm` as its [slurm] table (from line 5 on).
fs::path campaign_with(const std::string& slurm) {
  write("base.toml", std::string("name = \"tiny\"\n[time]\nduration = 0.05\n[output]\n"
                                 "series_period = 0.01\n") +
                         scenes::kTinyScenarioBody);
  return write(
      "c.toml",
      "scenario = \"base.toml\"\n[grid]\n\"materials.0.young\" = [10.0, 20.0]\n[slurm]\n" + slurm);
}

std::string error_of(const fs::path& campaign) {
  try {
    load_campaign(campaign);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SlurmSettings, TableIsReadWithItsDefaults) {
  const CampaignDef c = load_campaign(campaign_with(R"(partition = "compute"
account = "lab42"
qos = "normal"
time = "1-12:00:00"
memory = "4G"
max_running = 20
requeue = false
time_margin = 2.0
extra = ["--constraint=avx2", "#SBATCH --exclusive"]
)"));
  EXPECT_EQ(c.slurm.partition, "compute");
  EXPECT_EQ(c.slurm.account, "lab42");
  EXPECT_EQ(c.slurm.qos, "normal");
  EXPECT_EQ(c.slurm.time, "1-12:00:00");
  EXPECT_EQ(c.slurm.memory, "4G");
  EXPECT_EQ(c.slurm.max_running, 20);
  EXPECT_FALSE(c.slurm.requeue);
  EXPECT_EQ(c.slurm.time_margin, 2.0);
  EXPECT_EQ(c.slurm.extra, (std::vector<std::string>{"--constraint=avx2", "--exclusive"}));

  const CampaignDef d = load_campaign(campaign_with(""));
  EXPECT_TRUE(d.slurm.partition.empty());
  EXPECT_TRUE(d.slurm.time.empty());
  EXPECT_EQ(d.slurm.max_running, 0);
  EXPECT_TRUE(d.slurm.requeue);
}

TEST(SlurmSettings, MalformedKeyIsNamedWithItsLine) {
  const auto expect_error = [](const std::string& table, const std::string& expected) {
    const std::string e = error_of(campaign_with(table));
    EXPECT_NE(e.find(expected), std::string::npos) << table << "\n -> " << e;
    EXPECT_NE(e.find("c.toml:5:"), std::string::npos) << table << "\n -> " << e;
  };
  expect_error("time = \"twelve hours\"\n", "key 'slurm.time': expected a Slurm time limit");
  expect_error("time = \"12:60:00:00\"\n", "key 'slurm.time'");
  expect_error("time = 720\n", "key 'slurm.time': expected a string, got 720");
  expect_error("memory = \"4 GB\"\n", "key 'slurm.memory': expected a memory size");
  expect_error("max_running = 0\n", "key 'slurm.max_running': expected at least 1");
  expect_error("max_running = \"4\"\n", "key 'slurm.max_running': expected an integer");
  expect_error("partition = \"a b\"\n", "key 'slurm.partition': expected one word");
  expect_error("requeue = \"yes\"\n", "key 'slurm.requeue': expected true or false");
  expect_error("time_margin = 0.5\n", "key 'slurm.time_margin': expected a factor of at least 1");
  expect_error("extra = [\"constraint=avx2\"]\n", "key 'slurm.extra': expected sbatch options");
  expect_error("extra = [\"--array=0-9\"]\n", "key 'slurm.extra': \"--array=0-9\": sweep sets");
  expect_error("partion = \"compute\"\n", "key 'slurm.partion': unknown key; expected partition");
  const std::string not_table = error_of(write("t.toml",
                                               "scenario = \"base.toml\"\nslurm = 3\n[grid]\n"
                                               "\"materials.0.young\" = [10.0]\n"));
  EXPECT_NE(not_table.find("t.toml:2: key 'slurm': expected a table"), std::string::npos)
      << not_table;
}

TEST(SlurmSettings, CommandLineOverridesAreCheckedAndNamed) {
  SlurmSettings base;
  base.partition = "compute";
  base.extra = {"--exclusive"};
  SlurmOverrides o;
  o.time = "30";
  o.memory = "500";
  o.extra = {"--constraint=avx2"};
  const SlurmSettings s = apply_slurm_overrides(base, o);
  EXPECT_EQ(s.partition, "compute");
  EXPECT_EQ(s.time, "30");
  EXPECT_EQ(s.memory, "500");
  EXPECT_EQ(s.extra, (std::vector<std::string>{"--exclusive", "--constraint=avx2"}));

  const auto error_of_override = [&](const SlurmOverrides& bad) -> std::string {
    try {
      apply_slurm_overrides(base, bad);
    } catch (const Error& e) {
      return e.what();
    }
    return "(no error)";
  };
  SlurmOverrides bad_time;
  bad_time.time = "soon";
  EXPECT_NE(error_of_override(bad_time).find("option --time: expected a Slurm time limit"),
            std::string::npos)
      << error_of_override(bad_time);
  SlurmOverrides bad_running;
  bad_running.max_running = -2;
  EXPECT_NE(error_of_override(bad_running).find("option --max-running: expected at least 1"),
            std::string::npos);
  SlurmOverrides bad_line;
  bad_line.extra = {"exclusive"};
  EXPECT_NE(error_of_override(bad_line).find("option --sbatch: expected sbatch options"),
            std::string::npos);
}

TEST(SlurmSettings, TimeLimitsInSlurmsFormats) {
  EXPECT_EQ(parse_slurm_time("90"), 5400);
  EXPECT_EQ(parse_slurm_time("10:30"), 630);
  EXPECT_EQ(parse_slurm_time("12:00:00"), 43200);
  EXPECT_EQ(parse_slurm_time("2-0"), 172800);
  EXPECT_EQ(parse_slurm_time("1-02:30"), 95400);
  EXPECT_EQ(parse_slurm_time("1-00:00:01"), 86401);
  EXPECT_EQ(parse_slurm_time("UNLIMITED"), -1);
  for (const char* bad : {"", "0", "1:2:3:4", "a", "-5", "1-", "1h", "12:00:xx", "1--2"})
    EXPECT_FALSE(parse_slurm_time(bad)) << bad;
  EXPECT_EQ(format_slurm_time(1), "00:01:00");
  EXPECT_EQ(format_slurm_time(3601), "01:01:00");
  EXPECT_EQ(format_slurm_time(86400 + 7200), "1-02:00:00");
  EXPECT_EQ(parse_slurm_time(format_slurm_time(12345)), 12360);
}

TEST(SlurmScript, ArraySpecCompressesRunsIntoRanges) {
  EXPECT_EQ(slurm_array_spec({0, 1, 2, 3}, 0), "0-3");
  EXPECT_EQ(slurm_array_spec({0, 1, 2, 3}, 2), "0-3%2");
  EXPECT_EQ(slurm_array_spec({1, 3, 4, 5, 9}, 0), "1,3-5,9");
  EXPECT_EQ(slurm_array_spec({7}, 20), "7%20");
}

TEST(SlurmScript, ScriptCarriesTheSettingsAndRunsEachTaskLikeALocalSweep) {
  CampaignDef c = load_campaign(campaign_with(R"(partition = "compute"
memory = "4G"
extra = ["--constraint=avx2"]
)"));
  c.analyze_options = {"--window", "5", "15"};
  SlurmScriptSpec spec;
  spec.executable = "/opt/soft grain/bin/softgrain";
  spec.threads = 4;
  spec.array = "0-1%1";
  spec.time_limit = "02:00:00";
  const std::string s = slurm_array_script(c, c.slurm, spec);
  for (const char* line :
       {"#SBATCH --array=0-1%1\n", "#SBATCH --cpus-per-task=4\n", "#SBATCH --time=02:00:00\n",
        "#SBATCH --partition=compute\n", "#SBATCH --mem=4G\n", "#SBATCH --constraint=avx2\n",
        "#SBATCH --requeue\n", "#SBATCH --output=slurm/%A_%a.out\n",
        "SOFTGRAIN=${SOFTGRAIN:-'/opt/soft grain/bin/softgrain'}\n",
        "analyze \"$dir\" '--window' '5' '15'"})
    EXPECT_NE(s.find(line), std::string::npos) << line << "\n" << s;
  // A finished run is left alone; a run with a checkpoint resumes; any other starts over.
  EXPECT_LT(s.find("analysis/summary.json\" ]; then"), s.find("-o runs --resume"));
  EXPECT_NE(s.find("-o runs --resume"), std::string::npos);
  EXPECT_NE(s.find("! -name scenario.toml -exec rm -rf"), std::string::npos);
  EXPECT_EQ(s.find("#SBATCH --account"), std::string::npos) << "not set, not written";
  // analyze's status 3 (done, mu not measured) is not a failed task; any other failure is.
  EXPECT_NE(s.find("[ $analyze_status -eq 0 ] || [ $analyze_status -eq 3 ] || failed analyze"),
            std::string::npos)
      << s;
}

// The job inherits the environment of the sweep that submitted it: a wait policy softgrain
// chose there (with its reason beside it) is dropped so that the run chooses on its own
// cores; one the user set is kept (core/wait_policy.h).
TEST(SlurmScript, TheRunChoosesItsWaitPolicyAgainUnlessTheUserChoseIt) {
  const CampaignDef c = load_campaign(campaign_with(""));
  SlurmScriptSpec spec;
  spec.executable = "softgrain";
  const std::string s = slurm_array_script(c, c.slurm, spec);
  const std::string reason = kWaitPolicyReasonVariable;
  const auto begin = s.find("if [ -n \"${" + reason);
  ASSERT_NE(begin, std::string::npos) << s;
  const std::string snippet = s.substr(begin, s.find("fi\n", begin) + 3 - begin);
  const auto policy_after = [&](const std::string& environment) {
    const fs::path file = fs::temp_directory_path() / "softgrain_wait_policy_snippet.sh";
    std::ofstream(file) << snippet << "echo \"[${OMP_WAIT_POLICY:-}|${GOMP_SPINCOUNT:-}]\"\n";
    FILE* pipe = ::popen(("env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u " + reason + " " +
                          environment + " bash " + file.string())
                             .c_str(),
                         "r");
    std::string out(64, '\0');
    out.resize(std::fread(out.data(), 1, out.size(), pipe));
    ::pclose(pipe);
    fs::remove(file);
    return out;
  };
  EXPECT_EQ(policy_after("OMP_WAIT_POLICY=PASSIVE " + reason + "=sweep"), "[|]\n");
  EXPECT_EQ(policy_after("OMP_WAIT_POLICY=PASSIVE"), "[PASSIVE|]\n");
  EXPECT_EQ(policy_after("GOMP_SPINCOUNT=100"), "[|100]\n");
}

TEST(SlurmCommands, ParsesSbatchSqueueAndSacct) {
  EXPECT_EQ(parse_sbatch_job_id("1234\n"), "1234");
  EXPECT_EQ(parse_sbatch_job_id("1234;cluster\n"), "1234");
  EXPECT_EQ(parse_sbatch_job_id("note from a site filter\n77\n"), "77");
  EXPECT_FALSE(parse_sbatch_job_id("sbatch: error: invalid partition\n"));
  EXPECT_FALSE(parse_sbatch_job_id(""));

  const auto tasks = parse_squeue_tasks(
      "12|1|PENDING|0:00|1|JobArrayTaskLimit\n"
      "12|0|RUNNING|1:02:03|4|None\n"
      "13|0|RUNNING|0:05|1|None\n"  // another job: ignored
      "12|3|CANCELLED|2-00:00:10|2|None\n"
      "garbage\n",
      "12");
  ASSERT_EQ(tasks.size(), 3u);
  EXPECT_EQ(tasks.at(1).state, "PENDING");
  EXPECT_EQ(tasks.at(1).reason, "JobArrayTaskLimit");
  EXPECT_EQ(tasks.at(0).state, "RUNNING");
  EXPECT_EQ(tasks.at(0).elapsed, 3723.0);
  EXPECT_EQ(tasks.at(0).cpus, 4);
  EXPECT_EQ(tasks.at(3).elapsed, 172810.0);

  const auto accounted = parse_sacct_tasks(
      "12_0|COMPLETED|3600|4\n12_1|CANCELLED by 0|60|4\n12_[2-5]|PENDING|0|4\n", "12");
  ASSERT_EQ(accounted.size(), 2u);
  EXPECT_EQ(accounted.at(1).state, "CANCELLED");
  EXPECT_EQ(accounted.at(0).elapsed, 3600.0);
  EXPECT_EQ(parse_squeue_elapsed("5:07"), 307.0);
  EXPECT_EQ(parse_squeue_elapsed("INVALID"), 0.0);
}

}  // namespace
}  // namespace sg

namespace sg {
namespace {

// --status from the runs' own files, before any submission (no scheduler is asked): a done
// run with its mu, a failed run with its failed command and the last error line of its log,
// a run never submitted. (The scheduler's states are tested against Slurm in tests/slurm/.)
TEST(SlurmStatus, RunsFilesGiveDoneFailedAndNotSubmitted) {
  campaign_with("");  // writes base.toml
  CampaignDef c = load_campaign(write("s.toml",
                                      "scenario = \"base.toml\"\noutput = \"out\"\n"
                                      "[grid]\n\"materials.0.young\" = [10.0, 20.0, "
                                      "30.0]\n"));
  SweepOptions o;
  const fs::path folder = prepare_campaign_folder(c, o);
  const fs::path done = campaign_run_folder(folder, c.runs[0]);
  fs::create_directories(done / "analysis");
  std::ofstream(done / "analysis" / "summary.json")
      << R"({"format": "softgrain-analysis-summary", "version": 1,
            "quantities": {"mu": {"value": 0.3125}}})";
  const fs::path failed = campaign_run_folder(folder, c.runs[1]);
  std::ofstream(failed / "sweep.failed") << "`softgrain run` exited with status 1 after 3 s\n";
  std::ofstream(failed / "sweep.log")
      << "softgrain: 3 bodies\n\nsoftgrain: error: step 12: non-finite position\nbye\n";

  const SlurmCampaignStatus s = slurm_campaign_status(c, folder);
  ASSERT_EQ(s.runs.size(), 3u);
  EXPECT_EQ(s.runs[0].state, SlurmRunState::done);
  EXPECT_EQ(s.runs[0].detail, "mu = 0.312");
  EXPECT_EQ(s.runs[1].state, SlurmRunState::failed);
  EXPECT_EQ(s.runs[1].detail,
            "`softgrain run` exited with status 1 after 3 s: softgrain: error: step 12: "
            "non-finite position");
  EXPECT_EQ(s.runs[2].state, SlurmRunState::not_submitted);
  EXPECT_EQ(s.runs[2].task, "");
  EXPECT_EQ(s.summary(),
            "3 runs: 1 done, 1 failed, 1 not submitted; 0.00 core-hours used by the tasks Slurm "
            "reports");
  std::ostringstream printed;
  print_slurm_status(c, s, printed);
  EXPECT_NE(printed.str().find("  failed       run-001_young=20  `softgrain run` exited"),
            std::string::npos)
      << printed.str();
}

}  // namespace
}  // namespace sg
