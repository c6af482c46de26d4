#include "analysis/energy_budget.h"

#include "analysis/run_parameters.h"
#include "core/error.h"

namespace sg {

EnergyBudget compute_energy_budget(const Series& series, const TimeWindow& window, double mu,
                                   double normal_force, double velocity) {
  const auto time = series.column("time");
  const auto damp = series.column("damping_dissipation");
  const auto cont = series.column("contact_dissipation");
  const auto work = series.column("external_work");
  const auto residual = series.column("energy_residual");
  SG_VERIFY(window.last < series.size() && window.first < window.last,
            series.path << ": window rows [" << window.first << ", " << window.last
                        << "] outside the series of " << series.size() << " rows");
  const std::size_t a = window.first, b = window.last;
  EnergyBudget e;
  e.duration = time[b] - time[a];
  const double bulk = damp[b] - damp[a];
  const double contact = cont[b] - cont[a];
  SG_VERIFY(bulk >= 0.0 && contact >= 0.0,
            series.path << ": cumulative dissipation decreases over the window (damping " << bulk
                        << ", contact " << contact
                        << "): energy given back, which no damping or contact law does; the "
                           "run's time integration was unstable there (a step beyond the "
                           "stable one: see its run.log)");
  SG_VERIFY(bulk + contact > 0.0, series.path << ": no energy dissipated over the window ["
                                              << time[a] << ", " << time[b]
                                              << "]; the energy budget is undefined");
  e.bulk_power = bulk / e.duration;
  e.contact_power = contact / e.duration;
  e.external_power = (work[b] - work[a]) / e.duration;
  e.bulk_share = bulk / (bulk + contact);                  // p_wb, paper 001 §3.3
  e.contact_share = contact / (bulk + contact);            // p_ws
  e.bulk_friction = e.bulk_share * mu;                     // mu_b, paper 001 eq. 5
  e.contact_friction = e.contact_share * mu;               // mu_s, paper 001 eq. 6
  const double reference_power = normal_force * velocity;  // Fn_bar V
  if (reference_power > 0.0) {
    e.mu_from_dissipation = (e.bulk_power + e.contact_power) / reference_power;
    e.mu_from_work = e.external_power / reference_power;
  } else {
    e.mu_from_dissipation = RunParameters::kUnknown;
    e.mu_from_work = RunParameters::kUnknown;
  }
  e.residual_drift = residual[b] - residual[a];
  return e;
}

}  // namespace sg
