#include "analysis/steadiness.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "analysis/autocorrelation.h"

namespace sg {
namespace {

std::string percent(double share) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(share < 0.1 ? 1 : 0) << 100.0 * share << "%";
  return s.str();
}

std::string number(double v) {
  std::ostringstream s;
  s << std::setprecision(3) << v;
  return s.str();
}

std::span<const double> in_window(std::span<const double> column, const TimeWindow& w) {
  return column.subspan(w.first, w.size());
}

void check_stresses(const FrictionResult& friction, const SteadinessThresholds& th,
                    std::vector<SteadinessWarning>& out) {
  if (friction.bodies.size() != 2) return;
  const FrictionStats& a = friction.bodies[0];
  const FrictionStats& b = friction.bodies[1];
  const double mean = 0.5 * (a.normal_force + b.normal_force);
  if (!std::isfinite(mean) || !(mean > 0.0)) return;
  const double imbalance = std::abs(a.normal_force - b.normal_force) / mean;
  if (!(imbalance > th.stress_imbalance)) return;
  // Stresses when L is known (as summary.json shows them), else the forces.
  const bool stresses = std::isfinite(a.normal_stress) && std::isfinite(b.normal_stress);
  out.push_back({"stress_imbalance",
                 "the mean normal " + std::string(stresses ? "stresses" : "forces") + " on '" +
                     a.body + "' and '" + b.body + "' differ by " + percent(imbalance) + " (" +
                     number(stresses ? a.normal_stress : a.normal_force) + " against " +
                     number(stresses ? b.normal_stress : b.normal_force) + "; more than " +
                     percent(th.stress_imbalance) +
                     "): the layer is not in equilibrium on average over the window"});
}

// mu_from_work - mu_from_dissipation = [X(t_end) - X(t_begin)] / (Fn_bar V T) with X = W_ext -
// W_diss, the stored energy plus the ledger's residual. In a steady state X fluctuates about a
// constant, and the difference of two of its values (far apart) scatters by sqrt(2) times its
// standard deviation, taken about its least-squares line so that a drift does not inflate it.
void check_energy_estimates(const Series& series, const TimeWindow& w, double mu,
                            const EnergyBudget& e, double normal_force, double velocity,
                            const SteadinessThresholds& th, std::vector<SteadinessWarning>& out) {
  const double reference_power = normal_force * velocity;  // Fn_bar V
  if (!(reference_power > 0.0) || !std::isfinite(e.mu_from_work) ||
      !std::isfinite(e.mu_from_dissipation) || w.size() < 3)
    return;
  const auto time = in_window(series.column("time"), w);
  const auto work = in_window(series.column("external_work"), w);
  const auto damp = in_window(series.column("damping_dissipation"), w);
  const auto cont = in_window(series.column("contact_dissipation"), w);
  std::vector<double> x(w.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = work[i] - damp[i] - cont[i];
  // Standard deviation about the least-squares line x = xm + b (t - tm).
  const double n = static_cast<double>(x.size());
  double tm = 0.0, xm = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    tm += time[i] / n;
    xm += x[i] / n;
  }
  const double slope = linear_trend(time, x).slope;
  double ss = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = x[i] - (xm + slope * (time[i] - tm));
    ss += r * r;
  }
  const double sigma = std::sqrt(ss / (n - 2.0));
  const double error = std::sqrt(2.0) * sigma / (reference_power * e.duration);
  const double difference = e.mu_from_work - e.mu_from_dissipation;
  if (!(std::abs(difference) > th.significance * error &&
        std::abs(difference) > th.relative_floor * std::abs(mu)))
    return;
  out.push_back({"energy_estimates",
                 "mu_from_work " + number(e.mu_from_work) + " and mu_from_dissipation " +
                     number(e.mu_from_dissipation) + " differ by " + number(difference) + " (± " +
                     number(error) +
                     ", the scatter of two values of the stored energy): the stored energy "
                     "changes over the window"});
}

// The energy the bulk and the contacts dissipated over the window.
double dissipated_in_window(const EnergyBudget& e) {
  return (e.bulk_power + e.contact_power) * e.duration;
}

void check_energy_drift(const Series& series, const TimeWindow& w, const EnergyBudget& e,
                        const SteadinessThresholds& th, std::vector<SteadinessWarning>& out) {
  const double dissipated = dissipated_in_window(e);
  if (!(dissipated > 0.0) || w.size() < 3) return;
  const auto time = in_window(series.column("time"), w);
  struct Energy {
    const char *column, *check, *what;
  };
  for (const Energy& energy : {Energy{"kinetic_energy", "kinetic_drift", "kinetic"},
                               Energy{"elastic_energy", "elastic_drift", "elastic"}}) {
    const auto& [column, check, what] = energy;
    const Trend trend = linear_trend(time, in_window(series.column(column), w));
    const double share = std::abs(trend.change) / dissipated;
    if (!(std::abs(trend.change) > th.significance * trend.change_error &&
          share > th.relative_floor))
      continue;
    out.push_back({check, std::string("the ") + what + " energy drifts by " + number(trend.change) +
                              " (± " + number(trend.change_error) + ") over the window, " +
                              percent(share) +
                              " of the energy dissipated in it: not a steady state"});
  }
}

void check_energy_residual(const EnergyBudget& e, const SteadinessThresholds& th,
                           std::vector<SteadinessWarning>& out) {
  const double dissipated = dissipated_in_window(e);
  if (!(dissipated > 0.0)) return;
  const double share = std::abs(e.residual_drift) / dissipated;
  if (!(share > th.ledger_residual)) return;
  out.push_back({"energy_residual",
                 "the energy ledger's residual changes by " + number(e.residual_drift) +
                     " over the window, " + percent(share) +
                     " of the energy dissipated in it (more than " + percent(th.ledger_residual) +
                     "): the time integration did not keep the energy, and the dissipation "
                     "shares are off by as much (a step beyond the stable one? see run.log)"});
}

void check_mu_trend(const Series& series, const TimeWindow& w, std::span<const DrivenBody> bodies,
                    double mu, const SteadinessThresholds& th,
                    std::vector<SteadinessWarning>& out) {
  if (bodies.empty() || !std::isfinite(mu) || w.size() < 3) return;
  // mu(t) of the bodies' forces averaged row by row, as compute_friction's "mean".
  std::vector<double> normal(w.size(), 0.0), tangential(w.size(), 0.0), ratio(w.size());
  for (const DrivenBody& body : bodies) {
    const BodyForces f = body_forces(series, body);
    for (std::size_t i = 0; i < w.size(); ++i) {
      normal[i] += f.normal[w.first + i];
      tangential[i] += f.tangential[w.first + i];
    }
  }
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!(normal[i] > 0.0)) return;  // mu(t) undefined: compute_friction said so already
    ratio[i] = tangential[i] / normal[i];
  }
  const Trend trend = linear_trend(in_window(series.column("time"), w), ratio);
  if (!(std::abs(trend.change) > th.significance * trend.change_error &&
        std::abs(trend.change) > th.relative_floor * std::abs(mu)))
    return;
  out.push_back({"mu_trend", "mu(t) has a trend: it changes by " + number(trend.change) + " (± " +
                                 number(trend.change_error) + ") over the window, " +
                                 percent(std::abs(trend.change / mu)) + " of mu " + number(mu)});
}

}  // namespace

std::vector<SteadinessWarning> check_steadiness(const Series& series, const TimeWindow& window,
                                                std::span<const DrivenBody> bodies,
                                                const FrictionResult& friction,
                                                const std::optional<EnergyBudget>& energy,
                                                double velocity,
                                                const SteadinessThresholds& thresholds) {
  std::vector<SteadinessWarning> out;
  const double mu = friction.mean.mu;
  check_stresses(friction, thresholds, out);
  if (energy) {
    if (std::isfinite(mu))
      check_energy_estimates(series, window, mu, *energy, friction.mean.normal_force, velocity,
                             thresholds, out);
    check_energy_drift(series, window, *energy, thresholds, out);
  }
  check_mu_trend(series, window, bodies, mu, thresholds, out);
  if (energy) check_energy_residual(*energy, thresholds, out);
  return out;
}

}  // namespace sg
