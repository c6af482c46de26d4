#include "io/run.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/checkpoint.h"
#include "io/contact_vtk.h"
#include "io/grain_snapshot_writer.h"
#include "io/run_directory.h"
#include "io/vtk_writer.h"
#include "model/kinematics.h"
#include "scenario/geometry_checks.h"
#include "solver/explicit_solver.h"
#include "solver/mass_scaling.h"
#include "solver/stable_time_step.h"
#include "solver/state_snapshot.h"
#include "solver/step_controller.h"

namespace sg {

namespace {

void write_run_log(const std::filesystem::path& path, const ScenarioDef& s, const Model& model,
                   const StableStep& stable, double dt, const std::string& mass_scaling_note,
                   const std::string& resume_note) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(10);
    out << "softgrain run log\nscenario = " << s.source.string() << "\nname = " << s.name
        << "\nthreads = " << omp_get_max_threads() << "\n\n[time]\nduration = " << s.duration
        << "\nsafety = " << s.time_step_safety << "\nfixed_step = " << s.fixed_time_step
        << "\nmass_scaling_step = " << s.mass_scaling_step
        << "\n\n[output]\nseries_period = " << s.series_period
        << "\nfield_period = " << s.field_period << "\ncheckpoint_period = " << s.checkpoint_period
        << "\n\n[discretization]\nnode_spacing = " << s.discretization.mesh.spacing
        << "\nmls_neighbours = " << s.discretization.mls.neighbours
        << "\nmls_support_factor = " << s.discretization.mls.support_factor
        << "\ngauss_points = " << s.discretization.gauss_points
        << "\nsmoothing_iterations = " << s.discretization.mesh.smoothing_iterations
        << "\n\n[physics]\ngravity = [" << s.gravity.x() << ", " << s.gravity.y() << "]\n";
    for (const MaterialDef& m : s.materials)
      out << "\n[[materials]]\nname = \"" << m.name << "\"\nlaw = \"" << to_string(m.law)
          << "\"\nyoung = " << m.young << "\npoisson = " << m.poisson << "\ndensity = " << m.density
          << "\ndamping = " << m.damping << "\n";
    out << "\n# model: " << model.bodies.size() << " bodies, " << model.node_count() << " nodes, "
        << model.gauss_point_count() << " Gauss points, " << model.gauss_rows.entries()
        << " shape-function entries\n";
    if (stable.limiting_body >= 0)
      out << "# stable step estimate: omega_max = " << stable.omega_max << " (body '"
          << model.bodies[static_cast<std::size_t>(stable.limiting_body)].name << "'), "
          << (stable.damping_limited ? "damping-limited" : "wave-speed-limited")
          << ", dt = " << stable.dt << "\n";
    out << mass_scaling_note << "# first time step: " << dt
        << " (adaptive: see docs/scenario.md [time])\n"
        << resume_note;
  });
}

std::string format_duration(double seconds) {
  std::ostringstream s;
  if (seconds < 60)
    s << std::fixed << std::setprecision(0) << seconds << "s";
  else if (seconds < 3600)
    s << static_cast<int>(seconds / 60) << "m" << static_cast<int>(std::fmod(seconds, 60)) << "s";
  else
    s << static_cast<int>(seconds / 3600) << "h" << static_cast<int>(std::fmod(seconds, 3600) / 60)
      << "m";
  return s.str();
}

// What a checkpoint must match besides the model: settings that change what the steps
// compute or what the outputs mean.
std::vector<double> run_settings(const ScenarioDef& s, double dt) {
  std::vector<double> v = {dt,
                           s.series_period,
                           s.field_period,
                           s.step_tolerance,
                           static_cast<double>(s.reestimate_interval),
                           s.mass_scaling_step};
  if (!s.contact_laws.empty()) {
    const ContactSettings c = contact_settings(s);
    v.insert(v.end(), {c.cutoff, c.skin});
    for (const ContactLawDef& law : s.contact_laws) {
      const ContactLawParams& p = law.params;
      v.insert(v.end(), {static_cast<double>(p.kind), p.normal_stiffness, p.tangential_stiffness,
                         p.friction, p.adhesion, p.shear_strength});
    }
  }
  return v;
}

// Cuts series.csv.partial back to what it held when the checkpoint was taken (a killed run
// may have written rows after it), after checking that it is the same file.
void cut_series_back(const std::filesystem::path& partial, const RunLoopState& loop) {
  const std::string where = "cannot resume from '" + partial.string() + "': ";
  SG_VERIFY(std::filesystem::exists(partial), where << "the file is missing");
  const std::uintmax_t size = std::filesystem::file_size(partial);
  SG_VERIFY(size >= loop.series_bytes, where << "it has " << size << " bytes, fewer than the "
                                             << loop.series_bytes
                                             << " written when the checkpoint was taken");
  std::string kept(static_cast<std::size_t>(loop.series_bytes), '\0');
  {
    std::ifstream in(partial, std::ios::binary);
    in.read(kept.data(), static_cast<std::streamsize>(kept.size()));
    SG_VERIFY(in, where << "cannot read its first " << loop.series_bytes << " bytes");
  }
  const auto lines = std::count(kept.begin(), kept.end(), '\n');
  SG_VERIFY(!kept.empty() && kept.back() == '\n' && lines == loop.series_rows + 1,
            where << "its first " << loop.series_bytes << " bytes hold " << lines
                  << " lines, the checkpoint expects a header and " << loop.series_rows << " rows");
  std::filesystem::resize_file(partial, loop.series_bytes);
}

}  // namespace

RunSummary run_scenario(const ScenarioDef& scenario, const RunOptions& options) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const std::filesystem::path root =
      options.output_root_override.empty() ? scenario.output_root : options.output_root_override;
  // Checks the name and the folder, removes an old checkpoint unless resuming (run_directory.h).
  const std::filesystem::path dir = prepare_run_directory(root, scenario.name, options.resume);
  const std::filesystem::path checkpoint_path = dir / "checkpoint.bin";
  // series.csv is appended and flushed row by row: rows already written survive a crash.
  // Written first to a temporary name and renamed at the end, so a complete-looking file
  // always means a complete run.
  const std::filesystem::path series_path = dir / "series.csv";
  const std::filesystem::path partial_series = dir / "series.csv.partial";
  if (options.resume) {
    SG_VERIFY(std::filesystem::exists(checkpoint_path),
              "cannot resume '" << dir.string()
                                << "': no checkpoint.bin (the run stopped before its first "
                                   "checkpoint, or never started); run without --resume");
    SG_VERIFY(std::filesystem::exists(partial_series),
              "cannot resume '" << dir.string() << "': no series.csv.partial"
                                << (std::filesystem::exists(series_path)
                                        ? " (the run is complete: series.csv is there)"
                                        : ""));
  }
  std::filesystem::create_directories(dir / "fields");

  Model model = build_model(scenario);
  std::unique_ptr<ContactSystem> contacts;
  if (!scenario.contact_laws.empty())
    contacts = std::make_unique<ContactSystem>(model, contact_law_table(scenario),
                                               contact_settings(scenario));
  // Mass scaling on the built model, before anything is estimated or restored: deterministic,
  // so a resumed run rebuilds the same masses (and the checkpoint fingerprint checks them).
  std::string mass_scaling_note;
  if (scenario.mass_scaling_step > 0.0) {
    const MassScalingReport report =
        apply_mass_scaling(model, scenario.mass_scaling_step, scenario.time_step_safety,
                           contacts ? contacts->max_stiffness() : 0.0);
    mass_scaling_note = "# " + describe(report, model) + "\n";
  }
  // Impossible periodic geometry is refused, suspicious initial states are warned about
  // (scenario/geometry_checks.h); the warnings go to run.log too.
  const std::string initial_state_note =
      check_initial_state(scenario, model, contacts != nullptr, options.progress);
  ExplicitSolver solver(model, contacts.get());
  StepControlParams step_control;
  step_control.on_step_collapse = [&](const StableStep& now, double first_dt) {
    if (options.progress)
      *options.progress << "\nsoftgrain: warning: " << describe_step_collapse(model, now, first_dt)
                        << "\n";
  };
  step_control.safety = scenario.time_step_safety;
  step_control.fixed_step = scenario.fixed_time_step;
  step_control.reestimate_interval = scenario.reestimate_interval;
  step_control.tolerance = scenario.step_tolerance;
  // The controller estimates the critical step of the built (not yet restored) model: the
  // first step, part of the run settings a checkpoint must match.
  StepController controller(solver, contacts.get(), step_control);
  const StableStep stable = controller.last_estimate();
  const double dt = controller.next_step();
  double last_dt = dt;
  const double checkpoint_period =
      scenario.checkpoint_period < 0.0 ? scenario.duration / 10.0 : scenario.checkpoint_period;
  // Computed before any restore: the model's fixed data only.
  const CheckpointFingerprint fingerprint = fingerprint_of(model, run_settings(scenario, dt));

  // Driven bodies (rigid bodies with an imposed velocity or force): the force they receive
  // from the granular system and their position.
  // Deformable first bodies (strips) whose back face is driven (NodeDrive) are driven bodies
  // too: see driven_force() below.
  std::vector<BodyId> driven;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.kind != BodyKind::rigid) {
      if (body.node_drive >= 0 &&
          model.node_drives[static_cast<std::size_t>(body.node_drive)].drives_any())
        driven.push_back(static_cast<BodyId>(b));
      continue;
    }
    const RigidDrive& d = model.rigid.drive[static_cast<std::size_t>(body.rigid_index)];
    if (d.mode[0] != DriveMode::free || d.mode[1] != DriveMode::free)
      driven.push_back(static_cast<BodyId>(b));
  }
  // Shear cells: the friction coefficient seen by the top first body over the second half of
  // the run, mu = mean tangential / mean normal force (the full analysis: softgrain analyze).
  BodyId top_body = -1;
  for (BodyId b : driven)
    if (model.bodies[static_cast<std::size_t>(b)].name == "top") top_body = b;
  // The force columns of a driven body, with the rigid bodies' meaning: the force it receives
  // from the layer. A rigid body: the contact forces it received. A driven strip: minus the
  // drive's reaction R and minus the strip's weight W, i.e. the force the strip transmits to
  // its driven back face (what a load cell there measures), which balances the layer's force
  // on the strip up to the strip's inertia (zero on average in a steady state). Its position
  // columns: the mean physical position of the back-face nodes.
  // Weights of the driven strips (physical mass: gravity acts on it, solver/mass_scaling.h),
  // fixed for the run.
  std::vector<Vec2> strip_weight(model.bodies.size(), Vec2::Zero());
  for (BodyId b : driven) {
    const Body& body = model.bodies[static_cast<std::size_t>(b)];
    if (body.kind == BodyKind::rigid) continue;
    double mass = 0.0;
    for (int i = body.node_begin; i < body.node_end; ++i)
      mass += model.nodes.mass[static_cast<std::size_t>(i)];
    strip_weight[static_cast<std::size_t>(b)] = mass / body.mass_scale * model.gravity;
  }
  auto driven_force = [&](BodyId b) -> Vec2 {
    const Body& body = model.bodies[static_cast<std::size_t>(b)];
    if (body.kind == BodyKind::rigid) {
      const auto r = static_cast<std::size_t>(body.rigid_index);
      return Vec2(model.rigid.fx[r], model.rigid.fy[r]);
    }
    return -model.node_drives[static_cast<std::size_t>(body.node_drive)].reaction -
           strip_weight[static_cast<std::size_t>(b)];
  };
  auto driven_position = [&](BodyId b) -> Vec2 {
    const Body& body = model.bodies[static_cast<std::size_t>(b)];
    if (body.kind == BodyKind::rigid) {
      const auto r = static_cast<std::size_t>(body.rigid_index);
      return Vec2(model.rigid.x[r], model.rigid.y[r]);
    }
    const NodeDrive& d = model.node_drives[static_cast<std::size_t>(body.node_drive)];
    Vec2 sum(0, 0);
    for (int i : d.nodes)
      sum += node_position(model, i);
    return sum / static_cast<double>(d.nodes.size());
  };

  if (contacts) std::filesystem::create_directories(dir / "contacts");
  std::filesystem::create_directories(dir / "grains");
  PvdCollection pvd(dir / "fields.pvd");
  PvdCollection contact_pvd(dir / "contacts.pvd");
  RunLoopState loop;  // what the loop has written and when it writes next (checkpointed)
  loop.next_checkpoint_time = checkpoint_period;
  Checkpoint checkpoint;  // reused: capture_state() fills its buffers in place
  RunSummary summary;
  std::ofstream series;
  std::string resume_note;
  if (options.resume) {
    checkpoint = read_checkpoint(checkpoint_path, fingerprint);
    restore_state(checkpoint.state, solver, contacts.get());
    loop = checkpoint.loop;
    controller.set_state(loop.controller);
    cut_series_back(partial_series, loop);
    series.open(partial_series, std::ios::binary | std::ios::app);
    pvd.restore(loop.field_entries);
    if (contacts) contact_pvd.restore(loop.contact_entries);
    summary.resumed_from_step = solver.state().step;
    std::ostringstream note;
    note << std::setprecision(10) << "# resumed from checkpoint.bin at step " << solver.state().step
         << ", time " << solver.state().time << "\n";
    resume_note = note.str();
  } else {
    series.open(partial_series, std::ios::binary | std::ios::trunc);
  }
  SG_VERIFY(series, "cannot write '" << partial_series.string() << "'");
  write_run_log(dir / "run.log", scenario, model, stable, dt,
                mass_scaling_note + initial_state_note, resume_note);
  if (options.progress && !mass_scaling_note.empty())
    *options.progress << "softgrain: " << mass_scaling_note.substr(2);
  if (options.progress)
    *options.progress << "softgrain: " << model.bodies.size() << " bodies, " << model.node_count()
                      << " nodes, " << model.gauss_point_count() << " Gauss points; dt = " << dt
                      << (stable.damping_limited ? " (damping-limited)" : "") << "; "
                      << omp_get_max_threads() << " threads"
                      << (options.resume ? "; resumed at step " : "")
                      << (options.resume ? std::to_string(solver.state().step) : "") << "\n";

  // Rows are formatted into `row` and appended whole, so that the loop state counts the
  // bytes of series.csv.partial exactly (what a resume cuts it back to).
  std::ostringstream row;
  row << std::setprecision(12);
  auto append_series = [&]() {
    const std::string text = row.str();
    series.write(text.data(), static_cast<std::streamsize>(text.size()));
    series.flush();
    SG_VERIFY(series, "failed writing '" << partial_series.string() << "' (disk full?)");
    loop.series_bytes += text.size();
    row.str("");
  };
  if (!options.resume) {
    row << "time,step,dt,kinetic_energy,elastic_energy,external_work,damping_dissipation,"
           "contact_dissipation,servo_dissipation,energy_residual";
    for (BodyId b : driven) {
      const std::string& name = model.bodies[static_cast<std::size_t>(b)].name;
      row << ',' << name << "_fx," << name << "_fy," << name << "_x," << name << "_y";
    }
    row << '\n';
    append_series();
  }
  // One row describes one instant t_n, that of the step's force evaluation: the ledger (one
  // step behind the positions, solver/explicit_solver.h) and the forces are computed during
  // the step, so the row is written after it, but the positions must be those at t_n, taken
  // before the step (`row_positions`), not the updated ones of t_n+1.
  std::vector<Vec2> row_positions(driven.size());
  auto write_series_row = [&](double t, long s) {
    const EnergyLedger& e = solver.state().energy;
    row << t << ',' << s << ',' << last_dt << ',' << e.kinetic << ',' << e.elastic << ','
        << e.external_work << ',' << e.damping_dissipated << ',' << e.contact_dissipated << ','
        << e.servo_dissipated << ',' << e.residual();
    if (top_body >= 0 && t >= 0.5 * scenario.duration) {
      const Vec2 f = driven_force(top_body);
      loop.top_force_sum_x += f.x();
      loop.top_force_sum_y += f.y();
      ++loop.top_force_rows;
    }
    for (std::size_t k = 0; k < driven.size(); ++k) {
      const Vec2 f = driven_force(driven[k]), x = row_positions[k];
      row << ',' << f.x() << ',' << f.y() << ',' << x.x() << ',' << x.y();
    }
    row << '\n';
    append_series();
    ++loop.series_rows;
  };
  // Snapshot NNNNNN (fields/, grains/, contacts/) describes one instant t_n, its label in
  // fields.pvd and contacts.pvd. The fields and grains are the state at t_n, written before the
  // step (`write_state_files`); the contact network is the step's force evaluation at t_n
  // (ContactSystem::records()), so it is written after the step (`commit_snapshot`), and so
  // are the .pvd entries. A snapshot whose step a rejection rolled back is not committed: it
  // is taken again (same index, files overwritten) when the run is back at its time, like a
  // series row.
  auto snapshot_name = [&](const char* extension) {
    char name[32];
    std::snprintf(name, sizeof name, "%06d.%s", loop.next_snapshot, extension);
    return std::string(name);
  };
  auto write_state_files = [&]() {
    write_vtu_snapshot(model, dir / "fields" / snapshot_name("vtu"));
    write_grain_snapshot(model, dir / "grains" / snapshot_name("csv"));
  };
  auto commit_snapshot = [&](double t) {
    const std::string name = snapshot_name("vtu");
    pvd.add(t, "fields/" + name);
    if (contacts) {
      write_contact_snapshot(*contacts, dir / "contacts" / name);
      contact_pvd.add(t, "contacts/" + name);
    }
    ++loop.next_snapshot;
  };
  auto write_checkpoint_now = [&]() {
    controller.seal();  // no rollback crosses a checkpoint (resumed = uninterrupted, bitwise)
    loop.controller = controller.state();
    capture_state(solver, contacts.get(), checkpoint.state);
    loop.field_entries = pvd.entries();
    loop.contact_entries = contact_pvd.entries();
    checkpoint.fingerprint = fingerprint;
    checkpoint.loop = loop;
    write_checkpoint(checkpoint_path, checkpoint);
    ++summary.checkpoints_written;
  };

  const double tolerance = 1e-12 * scenario.duration;  // "time reached" despite round-off
  const long first_step = solver.state().step;
  const double first_time = solver.state().time;
  auto last_progress = clock::now();
  while (solver.state().time < scenario.duration - tolerance) {
    if (options.stop_after_steps >= 0 &&
        solver.state().step - first_step >= options.stop_after_steps) {
      summary.completed = false;  // as if killed here: no final snapshot, no rename
      break;
    }
    const long s = solver.state().step;
    const double t = solver.state().time;
    // After a rollback the run may be at the time of the last committed snapshot again (when
    // field_period < dt): that instant is in the collection already.
    const bool snapshot_due = t >= loop.next_field_time - tolerance &&
                              (pvd.entries().empty() || t > pvd.entries().back().first);
    if (snapshot_due) write_state_files();
    const bool row_due = t >= loop.next_series_time - tolerance;
    if (row_due)
      for (std::size_t k = 0; k < driven.size(); ++k)
        row_positions[k] = driven_position(driven[k]);
    last_dt = controller.advance();
    // A rejected step may roll back to a state older than (t, s) (step_controller.h); then
    // the step taken did not start here, and the row and the snapshot wait until the run is
    // back at their time. With the energy check a later rejection rolls back to (t, s) at the
    // earliest, so what is written here stays the run's state; a failed step without it rolls
    // back to the last held state, which may be older: rows and snapshots written since then
    // show the abandoned trajectory (step_controller.h).
    const bool step_from_here = solver.state().step == s + 1;
    if (snapshot_due && step_from_here) {
      commit_snapshot(t);
      loop.next_field_time += scenario.field_period;
    }
    if (row_due && step_from_here) {
      write_series_row(t, s);
      loop.next_series_time += scenario.series_period;
    }
    if (checkpoint_period > 0.0 && solver.state().time < scenario.duration - tolerance &&
        solver.state().time >= loop.next_checkpoint_time - tolerance) {
      loop.next_checkpoint_time += checkpoint_period;  // before saving: the saved loop is current
      write_checkpoint_now();
    }
    if (options.progress && clock::now() - last_progress > std::chrono::seconds(1)) {
      last_progress = clock::now();
      const double elapsed = std::chrono::duration<double>(last_progress - start).count();
      const double rate = static_cast<double>(s + 1 - first_step) / elapsed;
      const double time_rate = (solver.state().time - first_time) / elapsed;
      std::ostringstream line;
      line << "\r  t = " << std::setprecision(4) << solver.state().time << " / "
           << scenario.duration << "  (" << std::fixed << std::setprecision(1)
           << 100.0 * solver.state().time / scenario.duration << "%)  " << std::setprecision(0)
           << rate << " steps/s  ETA "
           << format_duration((scenario.duration - solver.state().time) / time_rate) << "   ";
      *options.progress << line.str() << std::flush;
    }
  }
  const long steps_here = solver.state().step - first_step;
  if (summary.completed) {
    // The final state has had no force evaluation: its contact network is evaluated here,
    // on a copy of the state that is put back after (the evaluation moves the contact
    // histories and the rigid bodies' forces on; nothing else of the run changes).
    write_state_files();
    if (contacts) {
      StateSnapshot final_state;
      capture_state(solver, contacts.get(), final_state);
      contacts->add_contact_forces(model);
      commit_snapshot(solver.state().time);
      restore_state(final_state, solver, contacts.get());
    } else {
      commit_snapshot(solver.state().time);
    }
    series.close();
    std::filesystem::rename(partial_series, series_path);
  }

  summary.directory = dir;
  summary.steps = solver.state().step;
  summary.time_step = dt;
  {
    // The step control's record, appended to the run log (rewritten whole, atomically).
    const StepStatistics& st = controller.statistics();
    std::ostringstream note;
    note << resume_note << std::setprecision(6) << "# steps: " << st.accepted << " accepted, "
         << st.rejected << " rejected; dt in [" << st.dt_min << ", " << st.dt_max << "]; "
         << st.estimates << " estimates of the critical step (this session)\n";
    if (!st.last_rejection.empty()) note << "# last rejection: " << st.last_rejection << "\n";
    write_run_log(dir / "run.log", scenario, model, stable, dt,
                  mass_scaling_note + initial_state_note, note.str());
    if (options.progress && (st.rejected > 0 || st.dt_min != st.dt_max))
      *options.progress << "\r  step control: " << st.accepted << " steps accepted, " << st.rejected
                        << " rejected, dt in [" << st.dt_min << ", " << st.dt_max << "]\n";
  }
  summary.nodes = model.node_count();
  summary.wall_seconds = std::chrono::duration<double>(clock::now() - start).count();
  summary.node_steps_per_second =
      static_cast<double>(summary.nodes) * static_cast<double>(steps_here) / summary.wall_seconds;
  if (options.progress && summary.completed) {
    const EnergyLedger& e = solver.state().energy;
    *options.progress << std::defaultfloat << "\r" << std::string(70, ' ')
                      << "\rdone: " << solver.state().step << " steps in "
                      << format_duration(summary.wall_seconds) << "; outputs in " << dir.string()
                      << "\n  energy: kinetic " << e.kinetic << ", elastic " << e.elastic
                      << ", external work " << e.external_work << ", damping dissipated "
                      << e.damping_dissipated << ", contact dissipated " << e.contact_dissipated
                      << ", balance residual " << e.residual() << "\n";
    if (top_body >= 0 && loop.top_force_sum_y != 0.0)
      *options.progress << "  friction coefficient on the top body over t > "
                        << 0.5 * scenario.duration
                        << ": mu = -<Fx>/<Fy> = " << -loop.top_force_sum_x / loop.top_force_sum_y
                        << " (mean normal force "
                        << std::abs(loop.top_force_sum_y) / static_cast<double>(loop.top_force_rows)
                        << ")\n";
  }
  return summary;
}

}  // namespace sg
