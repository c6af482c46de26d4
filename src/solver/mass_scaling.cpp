#include "solver/mass_scaling.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "solver/stable_time_step.h"

namespace sg {

double mass_scale_for_step(double omega, double alpha, double target_step) {
  SG_VERIFY(target_step > 0.0,
            "mass scaling: the target step " << target_step << " must be positive");
  if (omega <= 0.0 || critical_time_step(omega, alpha) >= target_step) return 1.0;
  const double omega_target_squared = 1.0 / (target_step * (0.25 * target_step + 0.5 * alpha));
  return omega * omega / omega_target_squared;
}

MassScalingReport apply_mass_scaling(Model& model, double target_step, double safety,
                                     double contact_stiffness, const IntegratorParams& integrator) {
  SG_VERIFY(target_step > 0.0,
            "mass scaling: the target step " << target_step << " must be positive");
  SG_VERIFY(safety > 0.0 && safety <= 1.0,
            "mass scaling: the safety factor " << safety << " must be in (0, 1]");
  MassScalingReport report;
  report.target_step = target_step;
  NodeState& nodes = model.nodes;
  RigidState& rigid = model.rigid;
  std::vector<double> physical_mass(model.bodies.size(), 0.0);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    SG_VERIFY(body.mass_scale == 1.0, "mass scaling: body '" << body.name
                                                             << "' is scaled already (factor "
                                                             << body.mass_scale << ")");
    if (body.kind == BodyKind::rigid) {
      physical_mass[b] = rigid.mass[static_cast<std::size_t>(body.rigid_index)];
    } else {
      for (int k = body.node_begin; k < body.node_end; ++k)
        physical_mass[b] += nodes.mass[static_cast<std::size_t>(k)];
    }
    report.physical_mass += physical_mass[b];
  }
  // A body's frequency also holds its contact partners' contact frequency (stable_time_step.h),
  // which scaling the partners lowers: repeat on the scaled model until every body reaches the
  // target (a pass that scales nothing ends it; the first pass does nearly all the work).
  for (int pass = 0; pass < 4; ++pass) {
    const std::vector<double> omega =
        estimate_body_frequencies(model, contact_stiffness, integrator).omega;
    bool scaled = false;
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      Body& body = model.bodies[b];
      // The controller's step is safety x the critical step: reach T / safety (with a hair of
      // margin so that round-off does not call for another pass).
      const double alpha = body_damping(model, static_cast<BodyId>(b), integrator);
      const double s = mass_scale_for_step(omega[b], alpha, (1.0 + 1e-9) * target_step / safety);
      if (s <= 1.0) continue;
      scaled = true;
      body.mass_scale *= s;
      if (body.kind == BodyKind::rigid) {
        const auto r = static_cast<std::size_t>(body.rigid_index);
        rigid.mass[r] *= s;
        rigid.inertia[r] *= s;
        rigid.mass_scale[r] = body.mass_scale;
      } else {
        for (int k = body.node_begin; k < body.node_end; ++k) {
          const auto i = static_cast<std::size_t>(k);
          nodes.mass[i] *= s;
          nodes.inverse_mass[i] = 1.0 / nodes.mass[i];
        }
      }
    }
    if (!scaled) break;
  }
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const double s = model.bodies[b].mass_scale;
    if (s == 1.0) continue;
    ++report.scaled_bodies;
    report.added_mass += (s - 1.0) * physical_mass[b];
    if (s > report.max_factor) {
      report.max_factor = s;
      report.max_factor_body = static_cast<BodyId>(b);
    }
  }
  return report;
}

std::string describe(const MassScalingReport& report, const Model& model) {
  std::ostringstream out;
  out << std::setprecision(4) << "mass scaling to a step of " << report.target_step << ": "
      << report.scaled_bodies << " of " << model.bodies.size() << " bodies scaled";
  if (report.max_factor_body >= 0)
    out << ", largest factor " << report.max_factor << " (body '"
        << model.body(report.max_factor_body).name << "')";
  out << ", added mass " << 100.0 * report.added_fraction() << "% of " << report.physical_mass;
  return out.str();
}

}  // namespace sg
