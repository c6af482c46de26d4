#include "run/integration_checks.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "solver/stable_time_step.h"

namespace sg {

std::string check_fixed_step(double fixed_step, const Model& model, double contact_stiffness,
                             const IntegratorParams& integrator) {
  if (!(fixed_step > 0.0)) return "";
  const StableStep critical = estimate_stable_time_step(model, 1.0, contact_stiffness, integrator);
  if (critical.limiting_body < 0 || !(fixed_step > critical.dt)) return "";
  std::ostringstream s;
  s << std::setprecision(3) << "fixed_step " << fixed_step << " is " << fixed_step / critical.dt
    << " times the estimated stability limit " << critical.dt << " (body '"
    << model.body(critical.limiting_body).name << "', highest frequency " << critical.omega_max
    << "; " << contact_share_note(critical)
    << "): beyond it the contacts or the bulk can gain energy without bound; watch the energy "
       "balance at the end of the run, or leave fixed_step out for the estimated step";
  return s.str();
}

std::string check_energy_balance(const EnergyLedger& e, double tolerance) {
  const double received = std::abs(e.external_work) + e.initial_kinetic + e.initial_elastic;
  const double residual = e.residual();
  if (!(received > 0.0) || !(std::abs(residual) > tolerance * received)) return "";
  std::ostringstream s;
  s << std::setprecision(3) << "the energy balance is off by " << 100.0 * residual / received
    << "% of the energy the run received (residual " << residual << " of " << received
    << "; more than " << 100.0 * tolerance << "%)";
  if (e.contact_dissipated < -tolerance * received)
    s << "; the contacts gave back " << -e.contact_dissipated
      << " more than they took, which no contact law does";
  s << ": the time integration did not keep the energy, so the dissipation shares and the "
       "friction read from this run are suspect; a step beyond the stable one (fixed_step) or "
       "an imex step without the energy check (step_tolerance = 0) through violent events "
       "does this";
  return s.str();
}

}  // namespace sg
