#include "io/run.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/contact_vtk.h"
#include "io/grain_snapshot_writer.h"
#include "io/vtk_writer.h"
#include "solver/explicit_solver.h"
#include "solver/stable_time_step.h"

namespace sg {

namespace {

void write_run_log(const std::filesystem::path& path, const ScenarioDef& s, const Model& model,
                   const StableStep& stable, double dt) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(10);
    out << "softgrain run log\nscenario = " << s.source.string() << "\nname = " << s.name
        << "\nthreads = " << omp_get_max_threads() << "\n\n[time]\nduration = " << s.duration
        << "\nsafety = " << s.time_step_safety << "\nfixed_step = " << s.fixed_time_step
        << "\n\n[output]\nseries_period = " << s.series_period
        << "\nfield_period = " << s.field_period
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
    out << "# time step used: " << dt << "\n";
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

}  // namespace

RunSummary run_scenario(const ScenarioDef& scenario, const RunOptions& options) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const std::filesystem::path root =
      options.output_root_override.empty() ? scenario.output_root : options.output_root_override;
  const std::filesystem::path dir = root / scenario.name;
  std::filesystem::create_directories(dir / "fields");

  Model model = build_model(scenario);
  std::unique_ptr<ContactSystem> contacts;
  double contact_stiffness = 0.0;
  if (!scenario.contact_laws.empty()) {
    contacts = std::make_unique<ContactSystem>(model, contact_law_table(scenario),
                                               contact_settings(scenario));
    contact_stiffness = contacts->max_stiffness();
  }
  const StableStep stable =
      estimate_stable_time_step(model, scenario.time_step_safety, contact_stiffness);
  const double dt = scenario.fixed_time_step > 0.0 ? scenario.fixed_time_step : stable.dt;
  write_run_log(dir / "run.log", scenario, model, stable, dt);
  if (options.progress)
    *options.progress << "softgrain: " << model.bodies.size() << " bodies, " << model.node_count()
                      << " nodes, " << model.gauss_point_count() << " Gauss points; dt = " << dt
                      << (stable.damping_limited ? " (damping-limited)" : "") << "; "
                      << omp_get_max_threads() << " threads\n";

  // series.csv is appended and flushed row by row: rows already written survive a crash.
  // Written first to a temporary name and renamed at the end, so a complete-looking file
  // always means a complete run.
  const std::filesystem::path series_path = dir / "series.csv";
  const std::filesystem::path partial_series = dir / "series.csv.partial";
  std::ofstream series(partial_series, std::ios::trunc);
  SG_VERIFY(series, "cannot write '" << partial_series.string() << "'");
  // Driven bodies (rigid bodies with an imposed velocity or force): the force they receive
  // from the granular system and their position.
  std::vector<BodyId> driven;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.kind != BodyKind::rigid) continue;
    const RigidDrive& d = model.rigid.drive[static_cast<std::size_t>(body.rigid_index)];
    if (d.mode[0] != DriveMode::free || d.mode[1] != DriveMode::free)
      driven.push_back(static_cast<BodyId>(b));
  }
  series << "time,step,dt,kinetic_energy,elastic_energy,external_work,damping_dissipation,"
            "contact_dissipation,energy_residual";
  for (BodyId b : driven) {
    const std::string& name = model.bodies[static_cast<std::size_t>(b)].name;
    series << ',' << name << "_fx," << name << "_fy," << name << "_x," << name << "_y";
  }
  series << '\n';
  series << std::setprecision(12);
  PvdCollection pvd(dir / "fields.pvd");

  // Shear cells: the friction coefficient seen by the top first body over the second half of
  // the run, mu = mean tangential / mean normal force (the full analysis: softgrain analyze).
  BodyId top_body = -1;
  for (BodyId b : driven)
    if (model.bodies[static_cast<std::size_t>(b)].name == "top") top_body = b;
  Vec2 top_force_sum = Vec2::Zero();
  long top_force_rows = 0;
  ExplicitSolver solver(model, contacts.get());
  if (contacts) std::filesystem::create_directories(dir / "contacts");
  std::filesystem::create_directories(dir / "grains");
  PvdCollection contact_pvd(dir / "contacts.pvd");
  int snapshot = 0;
  double next_series = 0.0, next_field = 0.0;
  const long total_steps = static_cast<long>(std::ceil(scenario.duration / dt - 1e-9));
  auto last_progress = clock::now();
  auto write_field = [&]() {
    char name[32];
    std::snprintf(name, sizeof name, "%06d.vtu", snapshot++);
    write_vtu_snapshot(model, dir / "fields" / name);
    pvd.add(solver.state().time, std::string("fields/") + name);
    if (contacts) {
      write_contact_snapshot(*contacts, dir / "contacts" / name);
      contact_pvd.add(solver.state().time, std::string("contacts/") + name);
    }
    char grains_name[32];
    std::snprintf(grains_name, sizeof grains_name, "%06d.csv", snapshot - 1);
    write_grain_snapshot(model, dir / "grains" / grains_name);
  };
  for (long s = 0; s < total_steps; ++s) {
    const double t = solver.state().time;
    if (t >= next_field - 1e-12 * scenario.duration) {
      write_field();
      next_field += scenario.field_period;
    }
    solver.step(dt);
    // The ledger describes the state at time t (where the forces were evaluated).
    if (t >= next_series - 1e-12 * scenario.duration) {
      const EnergyLedger& e = solver.state().energy;
      series << t << ',' << s << ',' << dt << ',' << e.kinetic << ',' << e.elastic << ','
             << e.external_work << ',' << e.damping_dissipated << ',' << e.contact_dissipated << ','
             << e.residual();
      if (top_body >= 0 && t >= 0.5 * scenario.duration) {
        const auto r =
            static_cast<std::size_t>(model.bodies[static_cast<std::size_t>(top_body)].rigid_index);
        top_force_sum += Vec2(model.rigid.fx[r], model.rigid.fy[r]);
        ++top_force_rows;
      }
      for (BodyId b : driven) {
        const auto r =
            static_cast<std::size_t>(model.bodies[static_cast<std::size_t>(b)].rigid_index);
        series << ',' << model.rigid.fx[r] << ',' << model.rigid.fy[r] << ',' << model.rigid.x[r]
               << ',' << model.rigid.y[r];
      }
      series << '\n' << std::flush;
      next_series += scenario.series_period;
    }
    if (options.progress && clock::now() - last_progress > std::chrono::seconds(1)) {
      last_progress = clock::now();
      const double elapsed = std::chrono::duration<double>(last_progress - start).count();
      const double rate = static_cast<double>(s + 1) / elapsed;
      std::ostringstream line;
      line << "\r  t = " << std::setprecision(4) << solver.state().time << " / "
           << scenario.duration << "  (" << std::fixed << std::setprecision(1)
           << 100.0 * static_cast<double>(s + 1) / static_cast<double>(total_steps) << "%)  "
           << std::setprecision(0) << rate << " steps/s  ETA "
           << format_duration(static_cast<double>(total_steps - s - 1) / rate) << "   ";
      *options.progress << line.str() << std::flush;
    }
  }
  write_field();
  series.close();
  std::filesystem::rename(partial_series, series_path);

  RunSummary summary;
  summary.directory = dir;
  summary.steps = total_steps;
  summary.time_step = dt;
  summary.nodes = model.node_count();
  summary.wall_seconds = std::chrono::duration<double>(clock::now() - start).count();
  summary.node_steps_per_second =
      static_cast<double>(summary.nodes) * static_cast<double>(total_steps) / summary.wall_seconds;
  if (options.progress) {
    const EnergyLedger& e = solver.state().energy;
    *options.progress << std::defaultfloat << "\r" << std::string(70, ' ')
                      << "\rdone: " << total_steps << " steps in "
                      << format_duration(summary.wall_seconds) << "; outputs in " << dir.string()
                      << "\n  energy: kinetic " << e.kinetic << ", elastic " << e.elastic
                      << ", external work " << e.external_work << ", damping dissipated "
                      << e.damping_dissipated << ", contact dissipated " << e.contact_dissipated
                      << ", balance residual " << e.residual() << "\n";
    if (top_body >= 0 && top_force_sum.y() != 0.0)
      *options.progress << "  friction coefficient on the top body over t > "
                        << 0.5 * scenario.duration
                        << ": mu = -<Fx>/<Fy> = " << -top_force_sum.x() / top_force_sum.y()
                        << " (mean normal force "
                        << std::abs(top_force_sum.y()) / static_cast<double>(top_force_rows)
                        << ")\n";
  }
  return summary;
}

}  // namespace sg
