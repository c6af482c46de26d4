#include "campaign/campaign_plan.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "campaign/slurm_settings.h"
#include "campaign/sweep.h"
#include "run/simulation.h"
#include "scenario/scenario.h"

namespace sg {
namespace {

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point start) {
  return std::chrono::duration<double>(clock_type::now() - start).count();
}

}  // namespace

std::string format_wall_time(double s) {
  std::ostringstream out;
  out << std::setprecision(3);
  if (s < 120)
    out << s << " s";
  else if (s < 7200)
    out << s / 60 << " min";
  else
    out << s / 3600 << " h";
  return out.str();
}

namespace {

// Restores the OpenMP thread count on the way out.
class ThreadCount {
 public:
  explicit ThreadCount(int threads) : previous_(omp_get_max_threads()) {
    omp_set_num_threads(threads);
  }
  ~ThreadCount() { omp_set_num_threads(previous_); }
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

 private:
  int previous_;
};

}  // namespace

RunPlan plan_run(const std::filesystem::path& scenario_file, int threads) {
  const ThreadCount thread_count(threads);
  const ScenarioDef scenario = load_scenario(scenario_file);
  RunPlan plan;
  plan.duration = scenario.duration;
  const auto build_start = clock_type::now();
  Simulation sim(scenario);
  plan.build_seconds = seconds_since(build_start);
  plan.nodes = sim.model.node_count();
  plan.gauss_points = sim.model.gauss_point_count();
  plan.step = sim.first_dt;
  // As the run loop steps (run/run.cpp), without its outputs.
  const double tolerance = 1e-12 * scenario.duration;
  const double t0 = sim.solver.state().time;
  const long first_step = sim.solver.state().step;
  const auto start = clock_type::now();
  while (sim.solver.state().time < scenario.duration - tolerance &&
         (seconds_since(start) < kMeasureSeconds || sim.solver.state().step - first_step < 10))
    sim.controller.advance();
  const double simulated = sim.solver.state().time - t0;
  plan.measured_steps = sim.solver.state().step - first_step;
  plan.seconds_per_time_unit = simulated > 0 ? seconds_since(start) / simulated : 0.0;
  return plan;
}

double CampaignPlan::core_hours() const {
  double seconds = 0;
  for (const RunPlan& r : runs)
    seconds += r.projected_seconds();
  return seconds * threads / 3600.0;
}

double CampaignPlan::longest_seconds() const {
  double longest = 0;
  for (const RunPlan& r : runs)
    longest = std::max(longest, r.projected_seconds());
  return longest;
}

std::string CampaignPlan::time_limit(double time_margin) const {
  return format_slurm_time(time_margin * longest_seconds() + kAnalysisAllowance);
}

CampaignPlan plan_campaign(const CampaignDef& campaign, const std::filesystem::path& folder,
                           int threads, std::ostream* out) {
  CampaignPlan plan;
  plan.threads = threads;
  if (out)
    *out << "plan: each run built and stepped for " << kMeasureSeconds
         << " s from its initial state on " << threads << " thread" << (threads > 1 ? "s" : "")
         << "\n"
         << "  " << std::left << std::setw(34) << "run" << std::right << std::setw(9) << "nodes"
         << std::setw(13) << "Gauss points" << std::setw(11) << "step" << std::setw(15)
         << "s/time unit" << std::setw(10) << "duration"
         << "  projected wall time\n";
  for (const CampaignRun& run : campaign.runs) {
    const RunPlan r = plan_run(campaign_run_folder(folder, run) / "scenario.toml", threads);
    plan.runs.push_back(r);
    if (out)
      *out << "  " << std::left << std::setw(34) << run.id << std::right << std::setw(9) << r.nodes
           << std::setw(13) << r.gauss_points << std::setw(11) << std::setprecision(3) << r.step
           << std::setw(15) << std::setprecision(3) << r.seconds_per_time_unit << std::setw(10)
           << std::setprecision(4) << r.duration << "  " << format_wall_time(r.projected_seconds())
           << std::endl;
  }
  if (out)
    *out << "campaign: " << std::fixed << std::setprecision(2) << plan.core_hours()
         << " core-hours projected (" << campaign.runs.size() << " runs x " << threads << " thread"
         << (threads > 1 ? "s" : "") << "); the longest run "
         << format_wall_time(plan.longest_seconds()) << std::defaultfloat << "\n";
  return plan;
}

}  // namespace sg
