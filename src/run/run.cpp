#include "run/run.h"

#include <omp.h>

#include <chrono>
#include <iomanip>
#include <new>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "io/run_directory.h"
#include "model/force_kernel.h"
#include "run/checkpoint_output.h"
#include "run/progress_output.h"
#include "run/run_length.h"
#include "run/run_log.h"
#include "run/series_output.h"
#include "run/snapshot_output.h"

namespace sg {

namespace {

using clock = std::chrono::steady_clock;

// Checks the name and the folder, removes an old checkpoint unless resuming
// (io/run_directory.h): a run writes and deletes only inside <output root>/<name>/.
// The folder is locked (io/run_lock.h) for the whole run: a second run there is refused.
RunFolder run_folder(const ScenarioDef& scenario, const RunOptions& options, RunFolderLock& lock) {
  const std::filesystem::path root =
      options.output_root_override.empty() ? scenario.output_root : options.output_root_override;
  return RunFolder{prepare_run_directory(root, scenario.name, options.resume, scenario.source,
                                         options.overwrite, &lock)};
}

// Checks what a resume needs, then creates the folders of the outputs.
void prepare_folder(const RunFolder& folder, const ScenarioDef& scenario, bool resume) {
  const std::string dir = folder.dir.string();
  if (resume) {
    SG_VERIFY(std::filesystem::exists(folder.checkpoint()),
              "cannot resume '" << dir
                                << "': no checkpoint.bin (the run stopped before its first "
                                   "checkpoint, or never started); run without --resume");
    SG_VERIFY(std::filesystem::exists(folder.partial_series()),
              "cannot resume '" << dir << "': no series.csv.partial"
                                << (std::filesystem::exists(folder.series())
                                        ? " (the run is complete: series.csv is there)"
                                        : ""));
  }
  // Real folders inside the run folder, never links (io/run_directory.h).
  make_run_subfolder(folder.dir, "fields");
  make_run_subfolder(folder.dir, "grains");
  if (!scenario.contact_laws.empty()) make_run_subfolder(folder.dir, "contacts");
}

std::string describe_resume(const SolverState& state) {
  std::ostringstream note;
  note << std::setprecision(10) << "# resumed from checkpoint.bin at step " << state.step
       << ", time " << state.time << "\n";
  return note.str();
}

void announce_start(std::ostream& out, const Simulation& sim, bool resumed) {
  if (!sim.mass_scaling_note.empty()) out << "softgrain: " << sim.mass_scaling_note.substr(2);
  out << "softgrain: " << sim.model.bodies.size() << " bodies, " << sim.model.node_count()
      << " nodes, " << sim.model.gauss_point_count() << " Gauss points; dt = " << sim.first_dt
      << (sim.first_estimate.damping_limited ? " (damping-limited)" : "") << "; "
      << omp_get_max_threads() << " threads, " << force_kernel().isa << " force kernel"
      << (resumed ? "; resumed at step " + std::to_string(sim.solver.state().step) : "") << "\n";
}

void announce_end(std::ostream& out, const Simulation& sim, const RunSummary& summary,
                  const SeriesOutput& series, double duration) {
  const StepStatistics& st = sim.controller.statistics();
  if (st.rejected > 0 || st.dt_min != st.dt_max)
    out << "\r  step control: " << st.accepted << " steps accepted, " << st.rejected
        << " rejected, dt in [" << st.dt_min << ", " << st.dt_max << "]\n";
  if (!summary.completed) return;
  const EnergyLedger& e = sim.solver.state().energy;
  out << std::defaultfloat << "\r" << std::string(70, ' ') << "\rdone: " << sim.solver.state().step
      << " steps in " << format_duration(summary.wall_seconds) << "; outputs in "
      << summary.directory.string() << "\n  energy: kinetic " << e.kinetic << ", elastic "
      << e.elastic << ", external work " << e.external_work << ", damping dissipated "
      << e.damping_dissipated << ", contact dissipated " << e.contact_dissipated
      << ", balance residual " << e.residual() << "\n";
  double mu = 0.0, normal_force = 0.0;
  if (series.top_friction(mu, normal_force))
    out << "  friction coefficient on the top body over t > " << 0.5 * duration
        << ": mu = -<Fx>/<Fy> = " << mu << " (mean normal force " << normal_force << ")\n";
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

// A run stopped by an error (a diverging step, a full disk, memory): run.log, where a user
// looks first, says where and why (issue #26), then the error goes on to the caller. On a
// full disk the log may not be writable either: the error still reaches the user.
[[noreturn]] void stop_with_error(const RunFolder& folder, const ScenarioDef& scenario,
                                  const Simulation& sim, const std::string& notes,
                                  const std::exception& error) {
  std::string why = error.what();
  if (dynamic_cast<const std::bad_alloc*>(&error)) why = "out of memory (" + why + ")";
  std::ostringstream note;
  note << std::setprecision(10) << "# stopped at step " << sim.solver.state().step << ", time "
       << sim.solver.state().time << ": ";
  for (char c : why)
    note << (c == '\n' ? ' ' : c);
  note << "\n";
  try {
    write_run_log(folder.run_log(), scenario, sim,
                  notes + describe_step_control(sim.controller.statistics()) + note.str());
  } catch (const std::exception&) {
    // the original error says more than this one
  }
  if (dynamic_cast<const Error*>(&error)) throw;
  SG_THROW("run '" << scenario.name << "' stopped at step " << sim.solver.state().step << ": "
                   << why);
}

}  // namespace

RunSummary run_scenario(const ScenarioDef& scenario, const RunOptions& options) {
  const clock::time_point start = clock::now();
  RunFolderLock lock;
  const RunFolder folder = run_folder(scenario, options, lock);
  prepare_folder(folder, scenario, options.resume);
  Simulation sim(scenario, options.progress);
  refuse_endless_run(scenario, sim);
  RunLoopState loop;  // what the outputs have written and when they write next (checkpointed)
  RunContext context{scenario, folder, sim, loop, 1e-12 * scenario.duration};

  // The outputs, in the order they observe each step: a checkpoint saves what the series and
  // the snapshots have committed for the same step.
  SnapshotOutput snapshots(context);
  SeriesOutput series(context);
  CheckpointOutput checkpoints(context);
  ProgressOutput progress(context, options.progress, options.profile);
  std::vector<RunObserver*> outputs = {&snapshots, &series, &checkpoints, &progress};
  outputs.insert(outputs.end(), options.observers.begin(), options.observers.end());

  RunSummary summary;
  std::string resume_note;
  if (options.resume) {
    resume_from_checkpoint(context);
    summary.resumed_from_step = sim.solver.state().step;
    resume_note = describe_resume(sim.solver.state());
  }
  for (RunObserver* output : outputs)
    output->begin(options.resume);
  if (!snapshots.resume_note().empty()) {
    resume_note += snapshots.resume_note();
    if (options.progress)
      for (const std::string& line : split_lines(snapshots.resume_note()))
        *options.progress << "softgrain: warning: " << line.substr(2) << "\n";
  }
  write_run_log(folder.run_log(), scenario, sim, resume_note);
  if (options.progress) announce_start(*options.progress, sim, options.resume);

  // The loop: step, accept or roll back (the controller), let each output observe.
  StepProfile& profile = sim.solver.profile();
  const long first_step = sim.solver.state().step;
  try {
    while (sim.solver.state().time < scenario.duration - context.time_tolerance) {
      if (options.stop_after_steps >= 0 &&
          sim.solver.state().step - first_step >= options.stop_after_steps) {
        summary.completed = false;  // as if killed here: no final snapshot, no rename
        break;
      }
      PhaseTimer timer(profile);
      const RunInstant now{sim.solver.state().time, sim.solver.state().step};
      for (RunObserver* output : outputs)
        output->prepare(now);
      timer.stamp(StepPhase::outputs);
      const StepProfile before = profile;
      const double dt = sim.controller.advance();
      // The controller's own time: the call less the steps it took (they stamped their phases).
      timer.stamp(StepPhase::step_control);
      profile.seconds[static_cast<std::size_t>(StepPhase::step_control)] -=
          profile.total() - before.total() -
          (profile[StepPhase::step_control] - before[StepPhase::step_control]);
      const StepTaken taken{now, dt, sim.solver.state().step == now.step + 1};
      if (taken.from_start)
        for (RunObserver* output : outputs)
          output->commit(taken);
      for (RunObserver* output : outputs)
        output->after_step(taken);
      timer.stamp(StepPhase::outputs);
    }
    if (summary.completed)
      for (RunObserver* output : outputs)
        output->finish();
  } catch (const std::exception& error) {
    stop_with_error(folder, scenario, sim, resume_note, error);
  }

  summary.directory = folder.dir;
  summary.steps = sim.solver.state().step;
  summary.time_step = sim.first_dt;
  summary.checkpoints_written = checkpoints.written();
  summary.nodes = sim.model.node_count();
  summary.wall_seconds = std::chrono::duration<double>(clock::now() - start).count();
  summary.node_steps_per_second = static_cast<double>(summary.nodes) *
                                  static_cast<double>(sim.solver.state().step - first_step) /
                                  summary.wall_seconds;
  summary.profile = profile;
  write_run_log(folder.run_log(), scenario, sim,
                resume_note + describe_step_control(sim.controller.statistics()) +
                    describe_viscous_solves(sim.solver.viscous_statistics()) +
                    describe_profile(profile, summary.wall_seconds));
  if (options.progress) announce_end(*options.progress, sim, summary, series, scenario.duration);
  return summary;
}

}  // namespace sg
