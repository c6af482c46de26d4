#include "campaign/slurm_campaign.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>

#include "campaign/campaign_table.h"
#include "campaign/slurm_commands.h"
#include "campaign/slurm_script.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/text_file.h"
#include "scenario/scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

// The last non-empty line of a text file (its last 64 KiB), "" if none.
std::string last_line(const fs::path& path, bool errors_only = false) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const std::streamoff size = in.tellg();
  const std::streamoff from = std::max<std::streamoff>(0, size - 65536);
  in.seekg(from);
  std::string text(static_cast<std::size_t>(size - from), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  std::istringstream lines(text);
  std::string last, last_error;
  for (std::string line; std::getline(lines, line);) {
    line = trimmed(line);
    if (line.empty()) continue;
    last = line;
    std::string lower = line;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower.find("error") != std::string::npos) last_error = line;
  }
  return errors_only ? last_error : last;
}

// ---------------------------------------------------------------------------------------
// slurm-jobs.txt: "<job id> <array> <UTC time>" per submission, oldest first

struct JobRecord {
  std::string job_id;
  std::vector<std::size_t> indices;
};

std::vector<std::size_t> parse_array_indices(std::string spec) {
  spec = spec.substr(0, spec.find('%'));
  std::vector<std::size_t> indices;
  std::istringstream in(spec);
  for (std::string part; std::getline(in, part, ',');) {
    const auto dash = part.find('-');
    try {
      const std::size_t a = std::stoul(part.substr(0, dash));
      const std::size_t b = dash == std::string::npos ? a : std::stoul(part.substr(dash + 1));
      for (std::size_t i = a; i <= b; ++i)
        indices.push_back(i);
    } catch (const std::exception&) {
      // A hand-edited line: ignored.
    }
  }
  return indices;
}

std::vector<JobRecord> read_job_records(const fs::path& folder) {
  std::vector<JobRecord> records;
  std::istringstream in(read_text_or_empty(folder / kSlurmJobsFile));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    JobRecord r;
    std::string array;
    if (fields >> r.job_id >> array) {
      r.indices = parse_array_indices(array);
      records.push_back(r);
    }
  }
  return records;
}

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

void record_job(const fs::path& folder, const std::string& job_id, const std::string& array) {
  std::string text = read_text_or_empty(folder / kSlurmJobsFile);
  if (text.empty())
    text = "# softgrain sweep --slurm: one line per submission: job id, array (run indices), UTC\n";
  text += job_id + " " + array + " " + utc_now() + "\n";
  write_file_atomically(folder / kSlurmJobsFile, text);
}

// ---------------------------------------------------------------------------------------
// A run's state

std::string mu_detail(const fs::path& dir) {
  CampaignRow row;
  try {
    row.summary = read_summary_record(dir / "analysis" / "summary.json");
  } catch (const Error&) {
    return "";
  }
  const double mu = row_quantity(row, "mu");
  if (!row.summary.unmeasured.empty()) return "without mu: " + row.summary.unmeasured;
  if (!std::isfinite(mu)) return "mu = -";
  std::ostringstream s;
  s << "mu = " << std::setprecision(3) << mu;
  return s.str();
}

// "t = 0.4 / 1 (40%)" from the last row of series.csv.partial, or "" before its first row.
std::string progress_detail(const fs::path& dir) {
  const std::string line = last_line(dir / "series.csv.partial");
  if (line.empty() || line.rfind("time", 0) == 0) return "";
  double t = 0;
  try {
    t = std::stod(line.substr(0, line.find(',')));
  } catch (const std::exception&) {
    return "";
  }
  std::ostringstream s;
  s << std::setprecision(4) << "t = " << t;
  try {
    const double duration = load_scenario(dir / "scenario.toml").duration;
    s << " / " << duration << " (" << std::lround(100.0 * t / duration) << "%)";
  } catch (const Error&) {
  }
  return s.str();
}

// Why a run failed: sweep.failed (which command, its status), then the last error line of
// its log (sweep.log: softgrain's stdout and stderr).
std::string failure_detail(const fs::path& dir) {
  std::string why = trimmed(read_text_or_empty(dir / "sweep.failed"));
  why = why.substr(0, why.find('\n'));
  const std::string error = last_line(dir / "sweep.log", true);
  if (!error.empty()) why += (why.empty() ? "" : ": ") + error;
  if (why.empty()) why = last_line(dir / "sweep.log");
  return why;
}

SlurmRunStatus from_task(const SlurmTask& task, const fs::path& dir) {
  SlurmRunStatus s;
  s.core_seconds = task.elapsed * task.cpus;
  const std::string& st = task.state;
  if (st == "PENDING" || st == "REQUEUED" || st == "REQUEUE_HOLD" || st == "REQUEUE_FED" ||
      st == "RESV_DEL_HOLD") {
    s.state = SlurmRunState::pending;
    s.detail = task.reason == "None" ? "" : "reason: " + task.reason;
  } else if (st == "RUNNING" || st == "CONFIGURING" || st == "COMPLETING" || st == "SUSPENDED" ||
             st == "STAGE_OUT" || st == "SIGNALING" || st == "RESIZING") {
    s.state = SlurmRunState::running;
    s.detail = progress_detail(dir);
  } else if (st == "TIMEOUT" || st == "DEADLINE") {
    s.state = SlurmRunState::timed_out;
    s.detail = progress_detail(dir);
  } else if (st == "CANCELLED") {
    s.state = SlurmRunState::cancelled;
    s.detail = progress_detail(dir);
  } else if (st == "PREEMPTED") {
    s.state = SlurmRunState::preempted;
    s.detail = progress_detail(dir);
  } else {
    // COMPLETED without a summary, FAILED, NODE_FAIL, OUT_OF_MEMORY, BOOT_FAIL, ...
    s.state = SlurmRunState::failed;
    const std::string why = failure_detail(dir);
    s.detail = (st == "COMPLETED" || st == "FAILED" ? "" : st + (why.empty() ? "" : ": ")) + why;
  }
  return s;
}

// How the planned time limit was chosen, for the terminal.
std::string planned_limit_note(const CampaignPlan& plan, double margin) {
  std::ostringstream s;
  s << "time limit per task " << plan.time_limit(margin) << ": " << margin
    << " x the longest projected run (" << format_wall_time(plan.longest_seconds()) << ") + "
    << kAnalysisAllowance / 60 << " min for start-up and analysis ([slurm] time or --time sets it)";
  return s.str();
}

void write_script(const fs::path& folder, const std::string& script) {
  write_file_atomically(folder / kSlurmScriptFile, script);
  fs::permissions(folder / kSlurmScriptFile, fs::perms::owner_exec | fs::perms::group_exec,
                  fs::perm_options::add);
}

}  // namespace

const char* slurm_run_state_name(SlurmRunState state) {
  switch (state) {
    case SlurmRunState::done:
      return "done";
    case SlurmRunState::pending:
      return "pending";
    case SlurmRunState::running:
      return "running";
    case SlurmRunState::failed:
      return "failed";
    case SlurmRunState::timed_out:
      return "timed out";
    case SlurmRunState::cancelled:
      return "cancelled";
    case SlurmRunState::preempted:
      return "preempted";
    case SlurmRunState::stopped:
      return "stopped";
    default:
      return "not submitted";
  }
}

std::size_t SlurmCampaignStatus::count(SlurmRunState state) const {
  return static_cast<std::size_t>(std::count_if(
      runs.begin(), runs.end(), [&](const SlurmRunStatus& r) { return r.state == state; }));
}

double SlurmCampaignStatus::core_hours() const {
  double seconds = 0;
  for (const SlurmRunStatus& r : runs)
    seconds += r.core_seconds;
  return seconds / 3600.0;
}

std::string SlurmCampaignStatus::summary() const {
  std::ostringstream s;
  s << runs.size() << (runs.size() == 1 ? " run" : " runs");
  const char* separator = ": ";
  for (SlurmRunState st :
       {SlurmRunState::done, SlurmRunState::running, SlurmRunState::pending, SlurmRunState::failed,
        SlurmRunState::timed_out, SlurmRunState::cancelled, SlurmRunState::preempted,
        SlurmRunState::stopped, SlurmRunState::not_submitted}) {
    if (const std::size_t n = count(st)) {
      s << separator << n << " " << slurm_run_state_name(st);
      separator = ", ";
    }
  }
  s << "; " << std::fixed << std::setprecision(2) << core_hours()
    << " core-hours used by the tasks Slurm reports";
  return s.str();
}

SlurmCampaignStatus slurm_campaign_status(const CampaignDef& campaign, const fs::path& folder) {
  SlurmCampaignStatus status;
  status.folder = folder;
  const std::vector<JobRecord> records = read_job_records(folder);
  std::map<std::string, std::optional<std::map<std::size_t, SlurmTask>>> tasks_of_job;
  for (const CampaignRun& run : campaign.runs) {
    const fs::path dir = campaign_run_folder(folder, run);
    // The latest submission holding this run.
    const JobRecord* latest = nullptr;
    for (const JobRecord& r : records)
      if (std::find(r.indices.begin(), r.indices.end(), run.index) != r.indices.end()) latest = &r;
    std::optional<SlurmTask> task;
    if (latest) {
      auto it = tasks_of_job.find(latest->job_id);
      if (it == tasks_of_job.end())
        it = tasks_of_job.emplace(latest->job_id, query_array_tasks(latest->job_id)).first;
      if (it->second) {
        const auto t = it->second->find(run.index);
        if (t != it->second->end()) task = t->second;
      }
    }
    SlurmRunStatus s;
    if (campaign_run_finished(dir)) {
      s.state = SlurmRunState::done;
      s.detail = mu_detail(dir);
      if (task) s.core_seconds = task->elapsed * task->cpus;
    } else if (task) {
      s = from_task(*task, dir);
    } else if (fs::exists(dir / "sweep.failed")) {
      s.state = SlurmRunState::failed;
      s.detail = failure_detail(dir);
    } else if (latest) {
      s.state = SlurmRunState::stopped;
      s.detail = progress_detail(dir);
      if (s.detail.empty()) s.detail = "no output";
    }
    if (latest) s.task = latest->job_id + "_" + std::to_string(run.index);
    status.runs.push_back(s);
  }
  return status;
}

void print_slurm_status(const CampaignDef& campaign, const SlurmCampaignStatus& status,
                        std::ostream& out) {
  out << "campaign '" << campaign.name << "' in " << status.folder.string() << "\n";
  for (std::size_t i = 0; i < campaign.runs.size(); ++i) {
    const SlurmRunStatus& s = status.runs[i];
    out << "  " << std::left << std::setw(13) << slurm_run_state_name(s.state) << std::right
        << campaign.runs[i].id;
    if (!s.task.empty()) out << "  [" << s.task << "]";
    if (!s.detail.empty()) out << "  " << s.detail;
    out << "\n";
  }
  out << status.summary() << "\n";
}

int slurm_threads(const CampaignDef& campaign, const SweepOptions& options) {
  return options.threads > 0 ? options.threads : campaign.threads > 0 ? campaign.threads : 1;
}

SlurmSubmission submit_campaign_to_slurm(const CampaignDef& campaign, const SweepOptions& options) {
  const SlurmSettings& settings = campaign.slurm;
  SlurmSubmission submission;
  submission.folder = prepare_campaign_folder(campaign, options);
  const fs::path& folder = submission.folder;
  std::ostream* out = options.out;

  // Neither done nor already waiting or running in the scheduler (submitting those again
  // would run them twice at once).
  std::size_t done = 0, active = 0;
  std::vector<std::size_t> runs;
  const bool submitted_before = fs::exists(folder / kSlurmJobsFile);
  const SlurmCampaignStatus before =
      submitted_before ? slurm_campaign_status(campaign, folder) : SlurmCampaignStatus{};
  for (std::size_t i = 0; i < campaign.runs.size(); ++i) {
    const SlurmRunState state =
        submitted_before ? before.runs[i].state
                         : (campaign_run_finished(campaign_run_folder(folder, campaign.runs[i]))
                                ? SlurmRunState::done
                                : SlurmRunState::not_submitted);
    if (state == SlurmRunState::done)
      ++done;
    else if (state == SlurmRunState::pending || state == SlurmRunState::running)
      ++active;
    else
      runs.push_back(i);
  }
  const int threads = slurm_threads(campaign, options);
  SlurmScriptSpec spec;
  spec.executable = options.executable;
  spec.threads = threads;
  spec.array =
      slurm_array_spec(runs.empty() ? std::vector<std::size_t>{0} : runs, settings.max_running);
  spec.time_limit = settings.time;
  if (spec.time_limit.empty() && !runs.empty()) {
    CampaignPlan plan;
    plan.threads = threads;
    if (out)
      *out << "measuring the runs to plan the time limit (" << kMeasureSeconds << " s each)\n";
    for (std::size_t i : runs)
      plan.runs.push_back(
          plan_run(campaign_run_folder(folder, campaign.runs[i]) / "scenario.toml", threads));
    spec.time_limit = plan.time_limit(settings.time_margin);
    if (out) *out << planned_limit_note(plan, settings.time_margin) << "\n";
  }
  submission.script = slurm_array_script(campaign, settings, spec);
  write_script(folder, submission.script);

  if (out)
    *out << "campaign '" << campaign.name << "': " << campaign.runs.size() << " runs, " << done
         << " done, " << active << " queued or running, " << runs.size() << " to submit -> "
         << folder.string() << "\n";
  if (runs.empty()) {
    if (out) *out << "nothing to submit\n";
    return submission;
  }
  // Slurm does not create the folder of --output files: the task would fail at once.
  fs::create_directories(folder / kSlurmOutputFolder);
  submission.job_id = sbatch_submit(folder, {"--array=" + spec.array}, kSlurmScriptFile);
  submission.submitted = runs;
  record_job(folder, submission.job_id, spec.array);
  if (out)
    *out << "submitted job array " << submission.job_id << " (--array=" << spec.array
         << ", --cpus-per-task=" << threads
         << (spec.time_limit.empty() ? std::string() : ", --time=" + spec.time_limit)
         << "); recorded in " << kSlurmJobsFile << "\n"
         << "follow it with: softgrain sweep " << campaign.file.string() << " --status\n";
  return submission;
}

}  // namespace sg

namespace sg {

void print_slurm_plan(const CampaignDef& campaign, const SweepOptions& options,
                      const fs::path& folder, const CampaignPlan& plan, std::ostream& out) {
  const SlurmSettings& settings = campaign.slurm;
  SlurmScriptSpec spec;
  spec.executable = options.executable;
  spec.threads = slurm_threads(campaign, options);
  std::vector<std::size_t> all(campaign.runs.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = i;
  spec.array = slurm_array_spec(all, settings.max_running);
  spec.time_limit = settings.time.empty() ? plan.time_limit(settings.time_margin) : settings.time;
  if (settings.time.empty()) out << planned_limit_note(plan, settings.time_margin) << "\n";
  const std::string script = slurm_array_script(campaign, settings, spec);
  write_script(folder, script);
  out << "sbatch script (" << (folder / kSlurmScriptFile).string()
      << "; `sweep --slurm` submits the unfinished runs with --array=<their indices>):\n"
      << script;
  const std::optional<long> limit = parse_slurm_time(spec.time_limit);
  if (!limit || *limit < 0) return;
  std::size_t too_long = 0;
  for (std::size_t i = 0; i < campaign.runs.size(); ++i) {
    const double projected = plan.runs[i].projected_seconds();
    if (projected > static_cast<double>(*limit)) {
      ++too_long;
      out << "WARNING: run " << campaign.runs[i].id << ": projected wall time "
          << format_wall_time(projected) << " does not fit the time limit " << spec.time_limit
          << " (it would be stopped and resumed from its checkpoint at every resubmission)\n";
    } else if (projected * settings.time_margin > static_cast<double>(*limit)) {
      out << "warning: run " << campaign.runs[i].id << ": projected wall time "
          << format_wall_time(projected) << " is within the margin (" << settings.time_margin
          << " x) of the time limit " << spec.time_limit << "\n";
    }
  }
  if (too_long)
    out << "WARNING: " << too_long << " of " << campaign.runs.size()
        << " runs cannot finish within the time limit " << spec.time_limit << "\n";
}

}  // namespace sg
