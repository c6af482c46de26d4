#pragma once
// Energy budget over the steady-state window (paper 001 §3.3).
//
// Mechanical energy leaves the layer two ways only: bulk damping (the Rayleigh term,
// series column damping_dissipation) and the contact laws (contact_dissipation). Both
// columns are cumulative, so their mean rates over the window are increments / duration:
//   P_b = [W_damp(t_end) - W_damp(t_begin)] / (t_end - t_begin)
//   P_s = [W_cont(t_end) - W_cont(t_begin)] / (t_end - t_begin)
//   p_wb = P_b / (P_b + P_s),  p_ws = P_s / (P_b + P_s)       (paper 001 §3.3, p_wb + p_ws = 1)
//   mu_b = p_wb mu,  mu_s = p_ws mu                             (paper 001 eqs 5-6)
// Cross-checks of the engine's bookkeeping, reported beside them: in steady state the
// dissipated power equals the power of the driving, Ft_bar V, so
//   mu_dissipation = (P_b + P_s) / (Fn_bar V)  and  mu_work = P_ext / (Fn_bar V)
// should both be close to mu; and the energy residual's drift over the window.
#include "analysis/series.h"
#include "analysis/steady_state.h"

namespace sg {

struct EnergyBudget {
  double duration = 0.0;             // t_end - t_begin (time)
  double bulk_power = 0.0;           // P_b, mean damping dissipation rate (energy/time)
  double contact_power = 0.0;        // P_s, mean contact dissipation rate (energy/time)
  double external_power = 0.0;       // P_ext, mean rate of external work (energy/time)
  double bulk_share = 0.0;           // p_wb
  double contact_share = 0.0;        // p_ws
  double bulk_friction = 0.0;        // mu_b = p_wb mu
  double contact_friction = 0.0;     // mu_s = p_ws mu
  double mu_from_dissipation = 0.0;  // (P_b + P_s)/(Fn_bar V); NaN if V unknown
  double mu_from_work = 0.0;         // P_ext/(Fn_bar V); NaN if V unknown
  double residual_drift = 0.0;       // energy_residual(t_end) - energy_residual(t_begin) (energy)
};

// `mu` and `normal_force` from compute_friction (the "mean" body), `velocity` = V (NaN
// if unknown). Throws sg::Error if the total dissipation over the window is not positive
// or a cumulative dissipation decreases (a bookkeeping bug upstream).
EnergyBudget compute_energy_budget(const Series& series, const TimeWindow& window, double mu,
                                   double normal_force, double velocity);

}  // namespace sg
