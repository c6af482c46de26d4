#include "campaign/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>

#include "campaign/campaign_table.h"
#include "campaign/paper_coordinates.h"
#include "campaign/run_queue.h"
#include "campaign/slurm_campaign.h"
#include "campaign/slurm_script.h"
#include "core/error.h"
#include "core/exit_status.h"
#include "io/atomic_file.h"
#include "io/run_lock.h"
#include "io/text_file.h"
#include "scenario/scenario.h"

#ifndef SOFTGRAIN_PLOT_CAMPAIGN_SCRIPT
#define SOFTGRAIN_PLOT_CAMPAIGN_SCRIPT "scripts/plot_campaign.py"
#endif

namespace sg {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFailedMarker = "sweep.failed";
constexpr const char* kSummary = "analysis/summary.json";
constexpr const char* kPython = "/usr/bin/python3";  // Debian's, with numpy and matplotlib

// POSIX shell single quotes: safe for any path.
std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s)
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string format_seconds(double s) {
  std::ostringstream out;
  if (s < 120)
    out << static_cast<long>(std::lround(s)) << " s";
  else if (s < 7200)
    out << std::fixed << std::setprecision(1) << s / 60 << " min";
  else
    out << std::fixed << std::setprecision(1) << s / 3600 << " h";
  return out.str();
}

std::string format_mu(const CampaignRow& row) {
  const double mu = row_quantity(row, "mu");
  if (!std::isfinite(mu)) return "mu = -";
  std::ostringstream out;
  out << "mu = " << std::setprecision(3) << mu;
  return out.str();
}

enum class RunState { done, failed, pending };

RunState run_state(const fs::path& dir) {
  if (fs::exists(dir / kSummary)) return RunState::done;
  if (fs::exists(dir / kFailedMarker)) return RunState::failed;
  return RunState::pending;
}

const char* state_name(RunState s) {
  switch (s) {
    case RunState::done:
      return "done";
    case RunState::failed:
      return "failed";
    default:
      return "pending";
  }
}

CampaignRow make_row(const CampaignRun& run, const fs::path& dir, RunState state) {
  CampaignRow row{run.id, run.values, state_name(state), {}};
  if (state == RunState::done) row.summary = read_summary_record(dir / kSummary);
  return row;
}

// Writes each run's scenario.toml, refusing to mix runs of a campaign that changed since its
// folders were written (the same id would then name two different simulations).
void write_run_scenarios(const CampaignDef& campaign, const fs::path& folder) {
  for (const CampaignRun& run : campaign.runs) {
    const fs::path file = campaign_run_folder(folder, run) / "scenario.toml";
    // Results exist once the folder holds more than the scenario (a run was started).
    const auto started = [&] {
      for (const auto& entry : fs::directory_iterator(file.parent_path()))
        if (entry.path().filename() != "scenario.toml") return true;
      return false;
    };
    if (fs::exists(file) && read_text_or_empty(file) != run.scenario_text && started()) {
      SG_THROW(campaign.file.string()
               << ": run " << run.id << ": '" << file.string()
               << "' differs from what the campaign now gives (the campaign file or its "
                  "base scenario changed since the run folders were written); give the "
                  "campaign another name, or delete '"
               << folder.string() << "' to start over");
    }
    if (!fs::exists(file) || read_text_or_empty(file) != run.scenario_text)
      write_file_atomically(file, run.scenario_text);
  }
  // Every run's scenario must read: an out-of-range value (say young = -1) is reported now,
  // naming the run's file and key, not after the other runs have taken hours.
  for (const CampaignRun& run : campaign.runs) {
    try {
      load_scenario(campaign_run_folder(folder, run) / "scenario.toml");
    } catch (const Error& e) {
      SG_THROW(campaign.file.string() << ": run " << run.id << ": " << e.what());
    }
  }
  std::string ids;
  for (const CampaignRun& run : campaign.runs)
    ids += run.id + "\n";
  write_file_atomically(folder / "runs.txt", ids);
}

bool python_imports(const std::string& modules) {
  return std::system(
             (std::string(kPython) + " -c 'import " + modules + "' >/dev/null 2>&1").c_str()) == 0;
}

// Draws mu over the first two parameters and, with SciPy (interpolation, correlations), the
// campaign figures (scripts/plot_campaign.py --all), if Debian's python with matplotlib is
// there; otherwise says how to do it.
void plot(const fs::path& folder, std::ostream* out) {
  const fs::path script = SOFTGRAIN_PLOT_CAMPAIGN_SCRIPT;
  const fs::path table = folder / "campaign.csv", map = folder / "mu_map.png";
  const bool available = fs::exists(script) && fs::exists(kPython) && python_imports("matplotlib");
  if (!available) {
    if (out)
      *out << "map: no " << kPython << " with matplotlib here; draw it elsewhere with\n  python3 "
           << "scripts/plot_campaign.py " << table.string() << " -o " << map.string() << " --all\n";
    return;
  }
  const bool figures = python_imports("scipy");
  if (!figures && out)
    *out << "figures: " << kPython << " has no scipy (Debian: python3-scipy): only the map\n";
  const std::string command = std::string(kPython) + " " + shell_quoted(script.string()) + " " +
                              shell_quoted(table.string()) + " -o " + shell_quoted(map.string()) +
                              (figures ? " --all" : "");
  const fs::path log = folder / "plot.log";
  const int status = std::system((command + " > " + shell_quoted(log.string()) + " 2>&1").c_str());
  if (out) {
    if (status == 0)
      *out << "map: " << map.string()
           << (figures ? "; figures: campaign_points.png, mu_vs_stress.png, "
                         "bulk_share_vs_cohesion.png, maps*.png, correlations.png, "
                         "correlations.csv"
                       : "")
           << "\n";
    else
      *out << "map: plot_campaign.py failed (see " << log.string() << "):\n  " << command << "\n";
  }
}

}  // namespace

fs::path campaign_run_folder(const fs::path& campaign_folder, const CampaignRun& run) {
  return campaign_folder / kCampaignRunsFolder / run.id;
}

bool campaign_run_finished(const fs::path& run_folder) {
  return fs::exists(run_folder / kSummary);
}

int sweep_threads(const CampaignDef& campaign, const SweepOptions& options) {
  const int parallel = options.parallel > 0 ? options.parallel : campaign.parallel;
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return options.threads > 0    ? options.threads
         : campaign.threads > 0 ? campaign.threads
                                : std::max(1, cores / parallel);
}

fs::path campaign_folder(const CampaignDef& campaign, const SweepOptions& options) {
  const fs::path root = options.output_root.empty() ? campaign.output_root : options.output_root;
  return fs::absolute(root / campaign.name).lexically_normal();
}

fs::path prepare_campaign_folder(const CampaignDef& campaign, const SweepOptions& options) {
  const fs::path folder = campaign_folder(campaign, options);
  fs::create_directories(folder);
  write_file_atomically(folder / "campaign.toml", read_text_or_empty(campaign.file));
  write_run_scenarios(campaign, folder);
  write_requested_coordinates(campaign, folder);  // for the runs' summary.json
  return folder;
}

namespace {

// What the sweep knows of every run: its row of campaign.csv and its state.
struct CampaignProgress {
  std::vector<std::string> keys;  // the varied parameters' keys (campaign.csv columns)
  std::vector<CampaignRow> rows;
  std::vector<RunState> states;

  std::size_t count(RunState s) const {
    return static_cast<std::size_t>(std::count(states.begin(), states.end(), s));
  }
  // Done, but the analysis could not measure what the run asks for (mu).
  bool unmeasured(std::size_t i) const {
    return states[i] == RunState::done && !rows[i].summary.unmeasured.empty();
  }
  std::size_t count_unmeasured() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < states.size(); ++i)
      n += unmeasured(i) ? 1 : 0;
    return n;
  }
};

CampaignProgress read_progress(const CampaignDef& campaign, const fs::path& folder) {
  CampaignProgress progress;
  // A paper coordinate's column says it is the requested value: summary.json's quantity of
  // the same name (also a column) is the realized one.
  for (const CampaignParameter& p : campaign.parameters)
    progress.keys.push_back(p.paper_coordinate ? p.key + "_requested" : p.key);
  for (const CampaignRun& run : campaign.runs) {
    const fs::path dir = campaign_run_folder(folder, run);
    progress.states.push_back(run_state(dir));
    progress.rows.push_back(make_row(run, dir, progress.states.back()));
  }
  return progress;
}

void count_states(const CampaignProgress& progress, SweepResult& result) {
  result.done = progress.count(RunState::done);
  result.failed = progress.count(RunState::failed);
  result.pending = progress.count(RunState::pending);
  result.done_without_mu = progress.count_unmeasured();
}

void list_runs(const CampaignDef& campaign, const fs::path& folder,
               const CampaignProgress& progress, std::ostream& out) {
  out << "campaign '" << campaign.name << "': " << campaign.runs.size()
      << (campaign.runs.size() == 1 ? " run in " : " runs in ") << folder.string() << "\n";
  for (std::size_t i = 0; i < campaign.runs.size(); ++i)
    out << "  " << std::left << std::setw(8) << state_name(progress.states[i])
        << campaign.runs[i].id << "\n";
  out << "written: runs/<id>/scenario.toml, runs.txt, slurm-array.sh (nothing run)\n";
}

// The process jobs of the unfinished runs: simulate (from scratch, or resumed from the
// checkpoint) unless series.csv is there, then analyse.
struct CampaignJobs {
  std::vector<ProcessJob> jobs;
  std::vector<std::size_t> run_of;  // job -> run index
  std::vector<bool> resumed;
};

ProcessJob run_job(const CampaignDef& campaign, const CampaignRun& run, const fs::path& folder,
                   const SweepOptions& options, int threads, bool& resumed) {
  const fs::path dir = campaign_run_folder(folder, run);
  const std::string exe = options.executable.string();
  const std::string thread_count = std::to_string(threads);
  const std::string rel = std::string(kCampaignRunsFolder) + "/" + run.id;
  fs::remove(dir / kFailedMarker);
  ProcessJob job;
  job.working_directory = folder;
  job.log = dir / "sweep.log";
  std::vector<std::string> simulate = {
      exe, "--threads", thread_count, "run", rel + "/scenario.toml", "-o", kCampaignRunsFolder};
  resumed = false;
  if (fs::exists(dir / "series.csv")) {
    // The simulation finished, its analysis did not: analyse only.
  } else if (options.resume_from_checkpoints && fs::exists(dir / "checkpoint.bin") &&
             fs::exists(dir / "series.csv.partial")) {
    simulate.push_back("--resume");
    job.steps.push_back(simulate);
    resumed = true;
  } else {
    // From scratch: nothing of an interrupted attempt may survive into the new one.
    std::vector<fs::path> stale;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().filename() != "scenario.toml" && entry.path().filename() != kRunLockFile)
        stale.push_back(entry.path());  // (the lock file stays: io/run_lock.h)
    for (const fs::path& p : stale)
      fs::remove_all(p);
    job.steps.push_back(simulate);
  }
  std::vector<std::string> analyze = {exe, "--threads", thread_count, "analyze", rel};
  analyze.insert(analyze.end(), campaign.analyze_options.begin(), campaign.analyze_options.end());
  job.steps.push_back(analyze);
  return job;
}

CampaignJobs make_jobs(const CampaignDef& campaign, const fs::path& folder,
                       const CampaignProgress& progress, const SweepOptions& options, int threads) {
  CampaignJobs jobs;
  for (std::size_t i = 0; i < campaign.runs.size(); ++i) {
    if (progress.states[i] == RunState::done) continue;
    bool resumed = false;
    jobs.jobs.push_back(run_job(campaign, campaign.runs[i], folder, options, threads, resumed));
    jobs.run_of.push_back(i);
    jobs.resumed.push_back(resumed);
  }
  return jobs;
}

// Why a job failed, for sweep.failed and the terminal; a resumed run that failed loses its
// checkpoint (it would fail the same way every time).
std::string failure_reason(const JobOutcome& o, const CampaignJobs& jobs, const fs::path& dir) {
  const bool analyze_step = o.step + 1 == jobs.jobs[o.job].steps.size();
  std::ostringstream why;
  why << "`softgrain " << (analyze_step ? "analyze" : "run") << "` ";
  if (o.success)
    why << "wrote no " << kSummary;
  else if (o.signal)
    why << "was killed by signal " << o.signal;
  else
    why << "exited with status " << o.exit_code;
  why << " after " << format_seconds(o.seconds) << "; log: " << (dir / "sweep.log").string();
  if (jobs.resumed[o.job] && !analyze_step) {
    // Moved aside (they show what went wrong) and out of the way: with no checkpoint and no
    // series.csv the next sweep starts the run from scratch, whose clean-up removes them.
    // (A complete but damaged series.csv used to make every next sweep re-analyse it.)
    for (const char* name : {"checkpoint.bin", "series.csv", "series.csv.partial"}) {
      std::error_code error;
      if (fs::exists(dir / name, error))
        fs::rename(dir / name, dir / (std::string(name) + ".damaged"), error);
    }
    why << " (resuming failed: checkpoint.bin and series.csv* moved aside as *.damaged; the "
           "next sweep starts it from scratch)";
  }
  return why.str();
}

// Runs the jobs `parallel` at a time, rewriting campaign.csv after each; false if interrupted.
bool run_jobs(const CampaignDef& campaign, const fs::path& folder, CampaignProgress& progress,
              const CampaignJobs& jobs, int parallel, const fs::path& table, std::ostream* out) {
  write_campaign_table(table, progress.keys, progress.rows);
  const auto status = [&](std::size_t running) {
    std::ostringstream s;
    s << "[" << progress.count(RunState::done) << "/" << campaign.runs.size() << " done";
    if (const std::size_t without = progress.count_unmeasured())
      s << " (" << without << " without mu)";
    const std::size_t failed = progress.count(RunState::failed);
    if (failed) s << ", " << failed << " failed";
    s << ", " << running << " running]";
    return s.str();
  };
  QueueEvents events;
  events.started = [&](std::size_t job, std::size_t running) {
    const std::size_t i = jobs.run_of[job];
    progress.states[i] = RunState::pending;
    if (out)
      *out << status(running) << " " << campaign.runs[i].id
           << (jobs.resumed[job] ? " resumed from its checkpoint" : " started") << std::endl;
  };
  events.finished = [&](const JobOutcome& o, std::size_t running) {
    const std::size_t i = jobs.run_of[o.job];
    const CampaignRun& run = campaign.runs[i];
    const fs::path dir = campaign_run_folder(folder, run);
    std::string message;
    // `analyze` exits with kExitUnmeasured when it wrote the summary without mu: done, but
    // not as a success (core/exit_status.h).
    const bool analyzed_without_mu =
        !o.success && o.step + 1 == jobs.jobs[o.job].steps.size() && o.exit_code == kExitUnmeasured;
    if ((o.success || analyzed_without_mu) && fs::exists(dir / kSummary)) {
      progress.states[i] = RunState::done;
      progress.rows[i] = make_row(run, dir, RunState::done);
      message =
          "finished in " + format_seconds(o.seconds) + " (" + format_mu(progress.rows[i]) + ")";
      if (progress.unmeasured(i)) {
        // "mu: <reason>": named by what is missing (mu, or a compaction box's curve).
        const std::string& what = progress.rows[i].summary.unmeasured;
        message = "finished WITHOUT " + what.substr(0, what.find(':')) + " in " +
                  format_seconds(o.seconds) + ": " + what;
      }
    } else {
      progress.states[i] = RunState::failed;
      progress.rows[i] = make_row(run, dir, RunState::failed);
      const std::string why = failure_reason(o, jobs, dir);
      write_file_atomically(dir / kFailedMarker, why + "\n");
      message = "FAILED: " + why;
    }
    write_campaign_table(table, progress.keys, progress.rows);
    if (out) *out << status(running) << " " << run.id << " " << message << std::endl;
  };
  return run_process_queue(jobs.jobs, parallel, events);
}

void report_gathered(const CampaignDef& campaign, const fs::path& folder,
                     const CampaignProgress& progress, const SweepResult& result,
                     std::ostream& out) {
  out << "campaign '" << campaign.name << "': " << result.done - result.done_without_mu << " of "
      << result.runs << " runs done";
  if (result.done_without_mu) out << ", " << result.done_without_mu << " done without mu";
  if (result.failed) out << ", " << result.failed << " failed";
  if (result.pending) out << ", " << result.pending << " not run";
  out << "\ntable: " << result.table.string() << "\n";
  for (std::size_t i = 0; i < campaign.runs.size(); ++i)
    if (progress.unmeasured(i))
      out << "  done without mu: " << campaign.runs[i].id << ": "
          << progress.rows[i].summary.unmeasured << "\n";
  // Runs whose window failed a steadiness check: their averages are suspect.
  for (std::size_t i = 0; i < campaign.runs.size(); ++i)
    if (progress.states[i] == RunState::done && !progress.rows[i].summary.warnings.empty())
      out << "  warnings: " << campaign.runs[i].id << ": " << progress.rows[i].summary.warnings
          << " (" << kSummary << ")\n";
  for (std::size_t i = 0; i < campaign.runs.size(); ++i)
    if (progress.states[i] == RunState::failed)
      out << "  failed: " << campaign.runs[i].id << ": "
          << read_text_or_empty(campaign_run_folder(folder, campaign.runs[i]) / kFailedMarker);
  for (std::size_t i = 0; i < campaign.runs.size(); ++i)
    if (progress.states[i] == RunState::pending)
      out << "  missing: " << campaign.runs[i].id << " (not finished)\n";
}

}  // namespace

SweepResult sweep_campaign(const CampaignDef& campaign, const SweepOptions& options) {
  std::ostream* out = options.out;
  // One sweep of a campaign at a time: a second one would clean up and start the runs the
  // first one is running (io/run_lock.h; issue #26).
  fs::create_directories(campaign_folder(campaign, options));
  RunFolderLock lock;
  lock.acquire(campaign_folder(campaign, options), std::chrono::milliseconds(3000), kSweepLockFile,
               "campaign folder");
  const fs::path folder = prepare_campaign_folder(campaign, options);
  const int parallel = options.parallel > 0 ? options.parallel : campaign.parallel;
  const int threads = sweep_threads(campaign, options);

  SweepResult result;
  result.folder = folder;
  result.table = folder / "campaign.csv";
  result.runs = campaign.runs.size();
  CampaignProgress progress = read_progress(campaign, folder);

  if (options.mode == SweepOptions::Mode::dry_run) {
    // The script `sweep --slurm` would submit (all runs; it submits only the unfinished).
    SlurmScriptSpec spec;
    spec.executable = options.executable;
    spec.threads = slurm_threads(campaign, options);
    std::vector<std::size_t> all(campaign.runs.size());
    for (std::size_t i = 0; i < all.size(); ++i)
      all[i] = i;
    spec.array = slurm_array_spec(all, campaign.slurm.max_running);
    spec.time_limit = campaign.slurm.time;
    write_file_atomically(folder / kSlurmScriptFile,
                          slurm_array_script(campaign, campaign.slurm, spec));
    fs::create_directories(folder / kSlurmOutputFolder);  // sbatch by hand: Slurm won't make it
    if (out) list_runs(campaign, folder, progress, *out);
    count_states(progress, result);
    return result;
  }

  if (options.mode == SweepOptions::Mode::run) {
    const CampaignJobs jobs = make_jobs(campaign, folder, progress, options, threads);
    if (out) {
      *out << "campaign '" << campaign.name << "': " << campaign.runs.size()
           << (campaign.runs.size() == 1 ? " run (" : " runs (") << progress.count(RunState::done)
           << " done, " << jobs.jobs.size() << " to run), " << parallel << " at a time, " << threads
           << " thread" << (threads > 1 ? "s" : "") << " each -> " << folder.string() << "\n";
    }
    result.interrupted = !run_jobs(campaign, folder, progress, jobs, parallel, result.table, out);
    if (result.interrupted && out)
      *out << "interrupted: the unfinished runs start again with the next `softgrain sweep "
           << campaign.file.string() << "`\n";
  }

  // Gather (again: a --gather after cluster jobs sees runs this process did not start).
  for (std::size_t i = 0; i < campaign.runs.size(); ++i) {
    const fs::path dir = campaign_run_folder(folder, campaign.runs[i]);
    const RunState now = run_state(dir);
    if (now != progress.states[i]) progress.rows[i] = make_row(campaign.runs[i], dir, now);
    progress.states[i] = now;
  }
  write_campaign_table(result.table, progress.keys, progress.rows);
  count_states(progress, result);
  if (out) report_gathered(campaign, folder, progress, result, *out);
  if (options.plot && result.done > 0) plot(folder, out);
  return result;
}

}  // namespace sg
