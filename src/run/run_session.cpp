#include "run/run_session.h"

#include <omp.h>

#include <iomanip>
#include <new>
#include <sstream>

#include "core/error.h"
#include "core/wait_policy.h"
#include "io/run_directory.h"
#include "model/force_kernel.h"
#include "run/checkpoint_output.h"
#include "run/integration_checks.h"
#include "run/progress_output.h"
#include "run/run_length.h"
#include "run/run_log.h"
#include "run/series_output.h"
#include "run/snapshot_output.h"

namespace sg {

namespace {

// Checks what a resume needs, then creates the folders of the outputs.
// `checkpoint`: the file a resume reads (the folder's checkpoint.bin unless another is given).
void prepare_folder(const RunFolder& folder, const ScenarioDef& scenario, bool resume,
                    const std::filesystem::path& checkpoint) {
  const std::string dir = folder.dir.string();
  if (resume) {
    SG_VERIFY(std::filesystem::exists(checkpoint),
              "cannot resume '" << dir << "': no " << checkpoint.filename().string()
                                << " (the run stopped before its first "
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

// The checkpoint a resume reads.
std::filesystem::path resume_checkpoint(const RunFolder& folder, const RunOptions& options) {
  return options.resume_checkpoint.empty() ? folder.checkpoint() : options.resume_checkpoint;
}

// Checks the name and the folder, removes an old checkpoint unless resuming
// (io/run_directory.h): a run writes and deletes only inside <output root>/<name>/. Then
// checks what a resume needs and creates the folders of the outputs. Without outputs: no
// folder (an empty path). The folder is locked (io/run_lock.h) while `lock` lives: a second
// run there is refused.
RunFolder open_run_folder(const ScenarioDef& scenario, const RunOptions& options,
                          RunFolderLock& lock) {
  if (!options.write_outputs) return RunFolder{};
  const std::filesystem::path root =
      options.output_root_override.empty() ? scenario.output_root : options.output_root_override;
  RunFolder folder{prepare_run_directory(root, scenario.name, options.resume, scenario.source,
                                         options.overwrite, &lock)};
  prepare_folder(folder, scenario, options.resume, resume_checkpoint(folder, options));
  return folder;
}

std::string describe_resume(const SolverState& state) {
  std::ostringstream note;
  note << std::setprecision(10) << "# resumed from checkpoint.bin at step " << state.step
       << ", time " << state.time << "\n";
  return note.str();
}

void announce_start(std::ostream& out, const Simulation& sim, bool resumed) {
  out << "softgrain: integrator: " << describe(sim.integrator) << "\n";
  if (!sim.mass_scaling_note.empty()) out << "softgrain: " << sim.mass_scaling_note.substr(2);
  out << "softgrain: " << sim.model.bodies.size() << " bodies, " << sim.model.node_count()
      << " nodes, " << sim.model.gauss_point_count() << " Gauss points; dt = " << sim.first_dt
      << (sim.first_estimate.damping_limited ? " (damping-limited)" : "") << "; "
      << omp_get_max_threads() << " threads (barriers: " << current_wait_policy() << "), "
      << force_kernel().isa << " force kernel"
      << (resumed ? "; resumed at step " + std::to_string(sim.solver.state().step) : "") << "\n";
}

// `series`: null without outputs (no friction line). `energy_warning`: the ledger's
// (run/integration_checks.h check_energy_balance), empty when it closes.
void announce_end(std::ostream& out, bool terminal, const Simulation& sim,
                  const RunSummary& summary, const SeriesOutput* series, double duration,
                  const std::string& energy_warning) {
  const StepStatistics& st = sim.controller.statistics();
  // On a terminal the progress line is still there, without its line break: overwrite it.
  const std::string clear_line = terminal ? "\r" + std::string(70, ' ') + "\r" : "";
  if (st.rejected > 0 || st.dt_min != st.dt_max)
    out << clear_line << "  step control: " << st.accepted << " steps accepted, " << st.rejected
        << " rejected, dt in [" << st.dt_min << ", " << st.dt_max << "]\n";
  if (!summary.completed) return;
  const EnergyLedger& e = sim.solver.state().energy;
  out << std::defaultfloat << (st.rejected > 0 || st.dt_min != st.dt_max ? "" : clear_line)
      << "done: " << sim.solver.state().step << " steps in "
      << format_duration(summary.wall_seconds) << "; outputs in " << summary.directory.string()
      << "\n  energy: kinetic " << e.kinetic << ", elastic " << e.elastic << ", external work "
      << e.external_work << ", damping dissipated " << e.damping_dissipated
      << ", contact dissipated " << e.contact_dissipated << ", balance residual " << e.residual()
      << "\n";
  if (!energy_warning.empty()) out << "  warning: " << energy_warning << "\n";
  double mu = 0.0, normal_force = 0.0;
  if (series && series->top_friction(mu, normal_force))
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

}  // namespace

RunSession::RunSession(const ScenarioDef& scenario, const RunOptions& options)
    : scenario_(scenario),
      options_(options),
      start_(clock::now()),
      folder_(open_run_folder(scenario_, options_, lock_)),
      simulation_(std::make_unique<Simulation>(scenario_, options_.progress)),
      context_{scenario_, folder_, *simulation_, loop_, 1e-12 * scenario_.duration} {
  SG_VERIFY(options_.write_outputs || !options_.resume || !options_.resume_checkpoint.empty(),
            "a run without outputs resumes from a checkpoint file: none given");
  refuse_endless_run(scenario_, *simulation_);
  // The outputs, in the order they observe each step: a checkpoint saves what the series and
  // the snapshots have committed for the same step.
  if (options_.write_outputs) {
    auto snapshots = std::make_unique<SnapshotOutput>(context_);
    snapshots_ = snapshots.get();
    own_outputs_.push_back(std::move(snapshots));
    auto series = std::make_unique<SeriesOutput>(context_);
    series_ = series.get();
    own_outputs_.push_back(std::move(series));
    auto checkpoints = std::make_unique<CheckpointOutput>(context_);
    checkpoints_ = checkpoints.get();
    own_outputs_.push_back(std::move(checkpoints));
  }
  own_outputs_.push_back(std::make_unique<ProgressOutput>(
      context_, options_.progress, options_.profile, options_.progress_on_terminal));
  for (const auto& output : own_outputs_)
    observers_.push_back(output.get());
  observers_.insert(observers_.end(), options_.observers.begin(), options_.observers.end());

  Simulation& sim = *simulation_;
  if (options_.resume) {
    resume_from_checkpoint(context_, resume_checkpoint(folder_, options_));
    summary_.resumed_from_step = sim.solver.state().step;
    resume_note_ = describe_resume(sim.solver.state());
  }
  for (RunObserver* observer : observers_)
    observer->begin(options_.resume);
  // Snapshots the .pvd indexes listed but the folder no longer holds (a resume drops them).
  if (snapshots_ && !snapshots_->resume_note().empty()) {
    resume_note_ += snapshots_->resume_note();
    if (options_.progress)
      for (const std::string& line : split_lines(snapshots_->resume_note()))
        *options_.progress << "softgrain: warning: " << line.substr(2) << "\n";
  }
  if (options_.write_outputs) write_run_log(folder_.run_log(), scenario_, sim, resume_note_);
  if (options_.progress) announce_start(*options_.progress, sim, options_.resume);
  first_step_ = sim.solver.state().step;
}

RunSession::~RunSession() = default;

bool RunSession::reached_end() const {
  return simulation_->solver.state().time >= scenario_.duration - context_.time_tolerance;
}

// The loop's body: step, accept or roll back (the controller), let each output observe.
void RunSession::step() {
  SG_VERIFY(!closed_, "run '" << scenario_.name << "': a step after the run was closed");
  Simulation& sim = *simulation_;
  StepProfile& profile = sim.solver.profile();
  PhaseTimer timer(profile);
  const RunInstant now{sim.solver.state().time, sim.solver.state().step};
  for (RunObserver* observer : observers_)
    observer->prepare(now);
  timer.stamp(StepPhase::outputs);
  const double dt = sim.controller.advance();  // times its phase and the step's
  timer.skip();
  const StepTaken taken{now, dt, sim.solver.state().step == now.step + 1};
  if (taken.from_start)
    for (RunObserver* observer : observers_)
      observer->commit(taken);
  for (RunObserver* observer : observers_)
    observer->after_step(taken);
  timer.stamp(StepPhase::outputs);
}

RunSummary RunSession::close() {
  SG_VERIFY(!closed_, "run '" << scenario_.name << "': closed twice");
  closed_ = true;
  Simulation& sim = *simulation_;
  RunSummary& summary = summary_;
  // Stopped before its duration: as if killed here (no final snapshot, no rename).
  summary.completed = reached_end();
  if (summary.completed)
    for (RunObserver* observer : observers_)
      observer->finish();

  const StepProfile& profile = sim.solver.profile();
  summary.directory = folder_.dir;
  summary.steps = sim.solver.state().step;
  summary.time_step = sim.first_dt;
  summary.checkpoints_written = checkpoints_ ? checkpoints_->written() : 0;
  summary.nodes = sim.model.node_count();
  summary.wall_seconds = std::chrono::duration<double>(clock::now() - start_).count();
  summary.node_steps_per_second = static_cast<double>(summary.nodes) *
                                  static_cast<double>(sim.solver.state().step - first_step_) /
                                  summary.wall_seconds;
  summary.profile = profile;
  const std::string energy_warning = check_energy_balance(sim.solver.state().energy);
  if (options_.write_outputs)
    write_run_log(folder_.run_log(), scenario_, sim,
                  resume_note_ + describe_step_control(sim.controller.statistics()) +
                      describe_viscous_solves(sim.solver.viscous_statistics()) +
                      describe_contacts(sim.contacts.get(), sim.solver.state().step) +
                      (energy_warning.empty() ? "" : "# warning: " + energy_warning + "\n") +
                      describe_profile(profile, summary.wall_seconds));
  if (options_.progress)
    announce_end(*options_.progress, options_.progress_on_terminal, sim, summary, series_,
                 scenario_.duration, energy_warning);
  lock_.release();  // the folder is complete (or left as a killed run leaves it)
  return summary;
}

// A run stopped by an error (a diverging step, a full disk, memory): run.log, where a user
// looks first, says where and why (issue #26), then the error goes on to the caller. On a
// full disk the log may not be writable either: the error still reaches the user.
void RunSession::stop_with_error(const std::exception& error) {
  const Simulation& sim = *simulation_;
  std::string why = error.what();
  if (dynamic_cast<const std::bad_alloc*>(&error)) why = "out of memory (" + why + ")";
  std::ostringstream note;
  note << std::setprecision(10) << "# stopped at step " << sim.solver.state().step << ", time "
       << sim.solver.state().time << ": ";
  for (const char c : why)
    note << (c == '\n' ? ' ' : c);
  note << "\n";
  if (options_.write_outputs) {
    try {
      write_run_log(folder_.run_log(), scenario_, sim,
                    resume_note_ + describe_step_control(sim.controller.statistics()) + note.str());
    } catch (const std::exception&) {
      // the original error says more than this one
    }
  }
  if (dynamic_cast<const Error*>(&error)) throw;
  SG_THROW("run '" << scenario_.name << "' stopped at step " << sim.solver.state().step << ": "
                   << why);
}

void RunSession::write_checkpoint(const std::filesystem::path& path) {
  write_run_checkpoint(context_, path, checkpoint_scratch_);
}

}  // namespace sg
