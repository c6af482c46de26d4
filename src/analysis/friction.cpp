#include "analysis/friction.h"

#include <cmath>
#include <vector>

#include "analysis/autocorrelation.h"
#include "core/error.h"

namespace sg {
namespace {

FrictionStats window_stats(const std::string& name, const std::vector<double>& normal,
                           const std::vector<double>& tangential, const TimeWindow& window,
                           double length, const Series& series) {
  const auto time = series.column("time");
  FrictionStats s;
  s.body = name;
  const double n = static_cast<double>(window.size());
  double fn = 0.0, ft = 0.0;
  for (std::size_t i = window.first; i <= window.last; ++i) {
    fn += normal[i];
    ft += tangential[i];
  }
  s.normal_force = fn / n;
  s.tangential_force = ft / n;
  SG_VERIFY(s.normal_force > 0.0, series.path << ": body '" << name << "': mean normal force "
                                              << s.normal_force
                                              << " over the window is not positive");
  s.mu = s.tangential_force / s.normal_force;  // paper 002 eq. 4
  double mean_ratio = 0.0;
  for (std::size_t i = window.first; i <= window.last; ++i) {
    SG_VERIFY(normal[i] > 0.0, series.path << ": body '" << name << "': normal force " << normal[i]
                                           << " <= 0 at time " << time[i]
                                           << " inside the window; start the window later");
    mean_ratio += tangential[i] / normal[i];
  }
  mean_ratio /= n;
  double var = 0.0;
  std::vector<double> ratio;
  for (std::size_t i = window.first; i <= window.last; ++i) {
    const double d = tangential[i] / normal[i] - mean_ratio;
    var += d * d;
    ratio.push_back(tangential[i] / normal[i]);
  }
  s.mu_std = std::sqrt(var / (n - 1.0));  // sample std (n >= 2 by TimeWindow)
  const MeanWithError e = mean_with_error(ratio);
  s.mu_error = e.error;
  s.mu_decorrelation_time = 2.0 * e.tau_int * (time[window.last] - time[window.first]) / (n - 1.0);
  if (length > 0.0) {
    s.normal_stress = s.normal_force / length;
    s.shear_stress = s.tangential_force / length;
  }
  return s;
}

double log10_or_nan(double x) {
  return x > 0.0 ? std::log10(x) : RunParameters::kUnknown;
}

}  // namespace

BodyForces body_forces(const Series& series, const DrivenBody& body) {
  const auto fx = series.column(body.name + "_fx");
  const auto fy = series.column(body.name + "_fy");
  BodyForces f;
  f.normal.resize(fx.size());
  f.tangential.resize(fx.size());
  for (std::size_t i = 0; i < fx.size(); ++i) {
    f.normal[i] = body.normal_sign * fy[i];
    f.tangential[i] = -body.slide_sign * fx[i];
  }
  return f;
}

FrictionResult compute_friction(const Series& series, std::span<const DrivenBody> bodies,
                                const TimeWindow& window, double length) {
  SG_VERIFY(!bodies.empty(), series.path << ": no driven body to compute friction on");
  SG_VERIFY(window.last < series.size() && window.first < window.last,
            series.path << ": window rows [" << window.first << ", " << window.last
                        << "] outside the series of " << series.size() << " rows");
  FrictionResult r;
  std::vector<double> mean_n(series.size(), 0.0), mean_t(series.size(), 0.0);
  const double inv = 1.0 / static_cast<double>(bodies.size());
  for (const auto& body : bodies) {
    const BodyForces f = body_forces(series, body);
    r.bodies.push_back(window_stats(body.name, f.normal, f.tangential, window, length, series));
    for (std::size_t i = 0; i < series.size(); ++i) {
      mean_n[i] += inv * f.normal[i];
      mean_t[i] += inv * f.tangential[i];
    }
  }
  r.mean = window_stats("mean", mean_n, mean_t, window, length, series);
  return r;
}

DimensionlessParameters compute_dimensionless(const RunParameters& run, double normal_stress) {
  DimensionlessParameters p;
  if (normal_stress > 0.0) {
    p.stiffness = log10_or_nan(run.young_modulus / normal_stress);  // paper 001 eq. 2
    p.cohesion = log10_or_nan(run.cohesion / normal_stress);        // paper 001 eq. 3
  }
  if (run.gap > 0.0)
    p.viscosity = log10_or_nan(run.damping_alpha * run.velocity / run.gap);  // eq. 4
  return p;
}

}  // namespace sg
