#pragma once
// Is the window steady? Checks of what the averages over the steady-state window assume
// (paper 001 §2.3: "time averages on the whole duration of the steady-state sliding"), each
// a warning in summary.json when it fails, never a silent pass (issue #29: on the
// agglomerates example mu_from_dissipation 0.239 against mu_from_work 0.204, and top and
// bottom normal stresses 15% apart, went unnoticed):
//
//  stress_imbalance   the mean normal stresses on the top and the bottom differ by more than
//                     `stress_imbalance` of their mean: the layer is not in equilibrium on
//                     average (it settles, dilates, or the top still sinks);
//  energy_estimates   mu_from_work - mu_from_dissipation (energy_budget.h) beyond
//                     `significance` times its scatter, and beyond `relative_floor` of mu; the
//                     difference is the change over the window of X = W_ext - W_diss (the
//                     stored kinetic + elastic energy plus the ledger's residual) over
//                     Fn_bar V T, and in a steady state that change, the difference of two
//                     values of X, scatters by sqrt(2) times X's standard deviation about its
//                     least-squares line (issue #29's agglomerates run: X fell by 2.5 over the
//                     window against a scatter of 0.47);
//  kinetic_drift,     the least-squares trend of the kinetic or elastic energy changes it over
//  elastic_drift      the window by more than `significance` standard errors (residuals'
//                     autocorrelation counted, autocorrelation.h) and by more than
//                     `relative_floor` of the energy dissipated in the window;
//  mu_trend           the trend of mu(t) = Ft(t)/Fn(t) changes it over the window by more than
//                     `significance` standard errors and `relative_floor` of mu;
//  energy_residual    the ledger's residual changes over the window by more than
//                     `ledger_residual` of the energy dissipated in it: the time integration
//                     did not keep the energy there, and the shares p_wb, p_ws and
//                     mu_from_dissipation are off by as much (a step beyond the stable one:
//                     fixed_step at 1.75 times the estimated step took 1.7% on the papers'
//                     shear cell, bench/results/debian12-2core/step_margin.csv).
// The floors keep a trend that is significant but negligible for the averages (a long, smooth
// series) from crying wolf.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/driven_body.h"
#include "analysis/energy_budget.h"
#include "analysis/friction.h"
#include "analysis/series.h"
#include "analysis/steady_state.h"

namespace sg {

struct SteadinessThresholds {
  double stress_imbalance = 0.05;  // |sigma_top - sigma_bottom| / mean
  double significance = 3.0;       // standard errors
  double relative_floor = 0.02;    // of mu, or of the energy dissipated in the window
  double ledger_residual = 0.01;   // of the energy dissipated in the window
  // |sigma_loaded / p - 1| under pressure loading (analysis/pressure_loading.h)
  double pressure_mismatch = 0.1;
};

struct SteadinessWarning {
  std::string check;    // stress_imbalance, energy_estimates, kinetic_drift, ... (above)
  std::string message;  // what was measured against which threshold
};

// The failed checks over `window`, in the order above. `bodies` and `friction` as given to and
// returned by compute_friction (two bodies for the stresses; mu(t) of their row-by-row mean
// forces), `energy` from compute_energy_budget (absent: no energy checks), `velocity` V (NaN:
// no energy_estimates). A check whose inputs are missing is skipped, not failed.
std::vector<SteadinessWarning> check_steadiness(const Series& series, const TimeWindow& window,
                                                std::span<const DrivenBody> bodies,
                                                const FrictionResult& friction,
                                                const std::optional<EnergyBudget>& energy,
                                                double velocity,
                                                const SteadinessThresholds& thresholds = {});

}  // namespace sg
