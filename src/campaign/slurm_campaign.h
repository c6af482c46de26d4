#pragma once
// A campaign through Slurm (docs/campaigns.md "On a cluster"):
//   softgrain sweep CAMPAIGN --slurm    submit the runs that are not done and not already
//                                       queued or running, as one job array
//   softgrain sweep CAMPAIGN --status   each run's state from the scheduler and its files
// Every submission is recorded in <campaign>/slurm-jobs.txt (job id, the array of run
// indices, UTC time); --status asks the scheduler about the latest job that holds each run.
// A run is done iff its analysis/summary.json exists, whatever the scheduler says; a finished
// run is never submitted again, and its task would leave it untouched anyway.
#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "campaign/campaign_def.h"
#include "campaign/campaign_plan.h"
#include "campaign/slurm_settings.h"
#include "campaign/sweep.h"

namespace sg {

inline constexpr const char* kSlurmJobsFile = "slurm-jobs.txt";
inline constexpr const char* kSlurmScriptFile = "slurm-array.sh";

enum class SlurmRunState {
  done,           // analysis/summary.json
  pending,        // queued (or re-queued)
  running,        // its task runs
  failed,         // its task ended without a summary (a command failed, the node failed, OOM)
  timed_out,      // its task hit the time limit
  cancelled,      // scancel
  preempted,      // taken off its node for another job
  stopped,        // not finished, and the scheduler no longer reports its task
  not_submitted,  // never submitted
};
const char* slurm_run_state_name(SlurmRunState state);  // "done", "timed out", ...

struct SlurmRunStatus {
  SlurmRunState state = SlurmRunState::not_submitted;
  std::string task;           // "<job>_<index>" of the latest submission holding it, or ""
  std::string detail;         // "mu = 0.31", "t = 0.4 / 1 (40%)", "Priority", an error line
  double core_seconds = 0.0;  // CPU time allocated to that task, as far as the scheduler says
};

struct SlurmCampaignStatus {
  std::filesystem::path folder;
  std::vector<SlurmRunStatus> runs;  // one per campaign run, in order
  std::size_t count(SlurmRunState state) const;
  double core_hours() const;
  std::string summary() const;  // "4 runs: 2 done, 1 running, 1 cancelled; 0.01 core-hours"
};

// The state of every run (the campaign folder must have been prepared: runs.txt).
SlurmCampaignStatus slurm_campaign_status(const CampaignDef& campaign,
                                          const std::filesystem::path& folder);

// Prints the status: one line per run, then the summary.
void print_slurm_status(const CampaignDef& campaign, const SlurmCampaignStatus& status,
                        std::ostream& out);

struct SlurmSubmission {
  std::filesystem::path folder;
  std::string job_id;                  // empty: nothing to submit
  std::vector<std::size_t> submitted;  // run indices = array task ids
  std::string script;                  // the script's text
};

// Prepares the campaign folder (campaign/sweep.h), writes slurm-array.sh (campaign.slurm's
// settings) and submits the runs that are neither done nor pending or running in the
// scheduler; records the job. Without a time limit ([slurm] time, --time), the runs to submit
// are measured first (campaign_plan.h) and the planned limit is used. options: executable,
// output_root, threads (> 0: replaces the campaign's; default 1), out.
SlurmSubmission submit_campaign_to_slurm(const CampaignDef& campaign, const SweepOptions& options);

// `sweep --dry-run --slurm`, after the plan: writes slurm-array.sh as --slurm would submit it
// (all runs; the time limit given, or planned), prints it, and warns about every run whose
// projected wall time does not fit the time limit.
void print_slurm_plan(const CampaignDef& campaign, const SweepOptions& options,
                      const std::filesystem::path& folder, const CampaignPlan& plan,
                      std::ostream& out);

// The threads (= --cpus-per-task) of each run on Slurm: options.threads, else the campaign's
// `threads`, else 1 (the submitting machine's core count says nothing about the nodes).
int slurm_threads(const CampaignDef& campaign, const SweepOptions& options);

}  // namespace sg
