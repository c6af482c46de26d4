#include "run/run_log.h"

#include <omp.h>

#include <iomanip>
#include <sstream>

#include "core/version.h"
#include "core/wait_policy.h"
#include "io/atomic_file.h"
#include "model/force_kernel.h"

namespace sg {

namespace {

void write_parameters(std::ostream& out, const ScenarioDef& s, const IntegratorChoice& integrator) {
  out << "softgrain run log\nsoftgrain = \"" << softgrain_version() << "\"\ncommit = \""
      << softgrain_commit() << "\"\nscenario = " << s.source.string() << "\nname = " << s.name
      << "\nthreads = " << omp_get_max_threads() << "\nomp_wait = \"" << current_wait_policy()
      << "\"  # " << wait_policy_reason() << "\nforce_kernel = \"" << force_kernel().isa
      << "\"\n\n[time]\nduration = " << s.duration << "\nsafety = " << s.time_step_safety
      << "\nfixed_step = " << s.fixed_time_step << "\nmass_scaling_step = " << s.mass_scaling_step
      << "\nintegrator = \"" << integrator.params.name() << "\""
      << (integrator.by_default ? "  # default: " + integrator.reason : "")
      << "\nstep_tolerance = " << integrator.step_tolerance
      << "\nimex_tolerance = " << s.imex_tolerance
      << "\nimex_refactor_threshold = " << s.imex_refactor_threshold
      << "\nimex_dense_factors = " << (s.imex_dense_factors ? "true" : "false")
      << "\nimex_objective = \"" << (s.imex_objective_split ? "split" : "exact") << "\""
      << "\n\n[output]\nseries_period = " << s.series_period
      << "\nfield_period = " << s.field_period << "\nfield_format = \""
      << (s.field_format == FieldFormat::ascii ? "ascii" : "binary")
      << "\"\ncheckpoint_period = " << s.checkpoint_period
      << "\n\n[discretization]\nnode_spacing = " << s.discretization.mesh.spacing;
  // Graded node density (issue #32): written only when set, so a uniform run's log is as it was.
  if (s.discretization.mesh.interior_spacing > 0.0)
    out << "\ninterior_spacing = " << s.discretization.mesh.interior_spacing;
  out << "\nmls_neighbours = " << s.discretization.mls.neighbours
      << "\nmls_support_factor = " << s.discretization.mls.support_factor
      << "\ngauss_points = " << s.discretization.gauss_points
      << "\nsmoothing_iterations = " << s.discretization.mesh.smoothing_iterations
      << "\n\n[physics]\ngravity = [" << s.gravity.x() << ", " << s.gravity.y() << "]\n";
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    const MaterialDef& m = s.materials[i];
    out << "\n[[materials]]\nname = \"" << m.name << "\"\nlaw = \"" << to_string(m.law)
        << "\"\nyoung = " << m.young << "\npoisson = " << m.poisson << "\ndensity = " << m.density
        << "\ndamping = " << m.damping << "\ndamping_model = \"" << to_string(m.damping_model)
        << "\"\n";
    // Written only when set (issue #31), so a standard run's log is as it was.
    if (m.volumetric != VolumetricFormulation::standard)
      out << "volumetric = \"" << to_string(m.volumetric) << "\"\n";
    // A material's own node spacings, when they differ from [discretization]'s.
    if (i < s.material_spacing.size()) {
      const NodeSpacing& own = s.material_spacing[i];
      if (own.contour != s.discretization.mesh.spacing ||
          own.interior != s.discretization.mesh.interior_spacing)
        out << "node_spacing = " << own.contour << "\ninterior_spacing = " << own.interior << "\n";
    }
  }
}

void write_model(std::ostream& out, const ScenarioDef& scenario, const Simulation& sim) {
  const Model& model = sim.model;
  const StableStep& stable = sim.first_estimate;
  out << "\n# model: " << model.bodies.size() << " bodies, " << model.node_count() << " nodes, "
      << model.gauss_point_count() << " Gauss points, " << model.gauss_rows.entries()
      << " shape-function entries\n";
  if (stable.limiting_body >= 0)
    out << "# stable step estimate: omega_max = " << stable.omega_max << " (body '"
        << model.body(stable.limiting_body).name << "'), "
        << (stable.damping_limited ? "damping-limited" : "wave-speed-limited")
        << ", dt = " << stable.dt << "; " << contact_share_note(stable) << "\n";
  out << sim.mass_scaling_note << sim.initial_state_note << sim.fixed_step_note
      << "# first time step: " << sim.first_dt
      << (scenario.fixed_time_step > 0.0 ? " (fixed_step: no step control)"
                                         : " (adaptive: see docs/scenario.md [time])")
      << "\n";
}

}  // namespace

void write_run_log(const std::filesystem::path& path, const ScenarioDef& scenario,
                   const Simulation& simulation, const std::string& notes) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(10);
    write_parameters(out, scenario, simulation.integrator);
    write_model(out, scenario, simulation);
    out << notes;
  });
}

std::string describe_viscous_solves(const ViscousSolveStatistics& st) {
  if (st.solves == 0) return "";
  std::ostringstream note;
  note << std::setprecision(4) << "# imex: " << st.solves << " body solves, " << st.iterations
       << " conjugate-gradient iterations ("
       << static_cast<double>(st.iterations) / static_cast<double>(st.solves) << " per solve), "
       << st.factorizations << " factorizations, " << st.reassemblies
       << " reassemblies of the objective operator";
  if (st.carried_forces > 0)
    note << ", " << st.carried_forces << " carried viscous forces (the kernel's skipped)";
  if (st.dense_bodies > 0) note << "; dense factors for " << st.dense_bodies << " bodies";
  note << "; factors and operators " << st.matrix_bytes / 1048576.0 << " MiB";
  note << "\n";
  return note.str();
}

std::string describe_contacts(const ContactSystem* contacts, long steps) {
  if (contacts == nullptr) return "";
  const int builds = contacts->broad_phase().build_count();
  std::ostringstream note;
  note << std::setprecision(3) << "# contacts: " << builds << " broad-phase builds in " << steps
       << " steps";
  if (builds > 0) note << " (one every " << static_cast<double>(steps) / builds << " steps)";
  note << ", " << contacts->broad_phase().candidates().size() << " candidate pairs at the last\n";
  return note.str();
}

std::string describe_step_control(const StepStatistics& st) {
  std::ostringstream note;
  note << std::setprecision(6) << "# steps: " << st.accepted << " accepted, " << st.rejected
       << " rejected; dt in [" << st.dt_min << ", " << st.dt_max << "]; " << st.estimates
       << " estimates of the critical step (this session)\n";
  if (!st.last_rejection.empty()) note << "# last rejection: " << st.last_rejection << "\n";
  return note.str();
}

std::string describe_profile(const StepProfile& profile, double wall_seconds) {
  std::ostringstream s;
  const double total = profile.total();
  s << std::fixed << std::setprecision(3) << "# profile (wall seconds of this session, "
    << omp_get_max_threads() << " threads): " << wall_seconds << " s in all, " << total
    << " s in the loop";
  if (profile.steps > 0)
    s << std::setprecision(1) << ", " << 1e6 * total / static_cast<double>(profile.steps)
      << " us per force evaluation";
  s << "\n";
  for (std::size_t p = 0; p < kStepPhaseCount; ++p)
    s << "#   " << std::left << std::setw(16) << phase_name(static_cast<StepPhase>(p)) << std::right
      << std::setprecision(3) << std::setw(10) << profile.seconds[p] << " s  "
      << std::setprecision(1) << std::setw(5)
      << (total > 0.0 ? 100.0 * profile.seconds[p] / total : 0.0) << "%\n";
  return s.str();
}

}  // namespace sg
