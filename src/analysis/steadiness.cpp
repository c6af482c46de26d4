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

// mu_from_work - mu_from_dissipation per block of the window: the scatter of the difference.
void check_energy_estimates(const Series& series, const TimeWindow& w, double mu,
                            const EnergyBudget& e, double normal_force, double velocity,
                            const SteadinessThresholds& th, std::vector<SteadinessWarning>& out) {
  const double reference_power = normal_force * velocity;  // Fn_bar V
  const auto k = static_cast<std::size_t>(th.blocks);
  if (!(reference_power > 0.0) || !std::isfinite(e.mu_from_work) ||
      !std::isfinite(e.mu_from_dissipation) || k < 2 || w.size() < 2 * k + 1)
    return;
  const auto time = series.column("time"), work = series.column("external_work");
  const auto damp = series.column("damping_dissipation");
  const auto cont = series.column("contact_dissipation");
  std::vector<double> d(k);
  for (std::size_t b = 0; b < k; ++b) {
    const std::size_t i0 = w.first + b * (w.size() - 1) / k;
    const std::size_t i1 = w.first + (b + 1) * (w.size() - 1) / k;
    const double dt = time[i1] - time[i0];
    const double dissipated = (damp[i1] - damp[i0]) + (cont[i1] - cont[i0]);
    d[b] = (work[i1] - work[i0] - dissipated) / dt / reference_power;
  }
  double mean = 0.0, var = 0.0;
  for (double v : d)
    mean += v / static_cast<double>(k);
  for (double v : d)
    var += (v - mean) * (v - mean) / static_cast<double>(k - 1);
  const double error = std::sqrt(var / static_cast<double>(k));
  const double difference = e.mu_from_work - e.mu_from_dissipation;
  if (!(std::abs(difference) > th.significance * error &&
        std::abs(difference) > th.relative_floor * std::abs(mu)))
    return;
  out.push_back({"energy_estimates",
                 "mu_from_work " + number(e.mu_from_work) + " and mu_from_dissipation " +
                     number(e.mu_from_dissipation) + " differ by " + number(difference) + " (± " +
                     number(error) + " from " + std::to_string(k) +
                     " blocks of the window): the stored energy changes over the window"});
}

void check_energy_drift(const Series& series, const TimeWindow& w, const EnergyBudget& e,
                        const SteadinessThresholds& th, std::vector<SteadinessWarning>& out) {
  const double dissipated = (e.bulk_power + e.contact_power) * e.duration;
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
  return out;
}

}  // namespace sg
