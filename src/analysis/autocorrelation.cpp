#include "analysis/autocorrelation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"

namespace sg {

Autocorrelation integrated_autocorrelation(std::span<const double> x) {
  const std::size_t n = x.size();
  SG_VERIFY(n >= 2, "autocorrelation needs at least 2 samples, got " << n);
  double mean = 0.0;
  for (double v : x)
    mean += v;
  mean /= static_cast<double>(n);
  const auto autocovariance = [&](std::size_t k) {  // the biased estimator (Sokal eq. 3.15)
    double c = 0.0;
    for (std::size_t i = 0; i + k < n; ++i)
      c += (x[i] - mean) * (x[i + k] - mean);
    return c / static_cast<double>(n);
  };
  Autocorrelation a;
  const double c0 = autocovariance(0);
  if (!(c0 > 0.0)) {
    a.converged = true;  // constant: every sample independent of the (absent) noise
    return a;
  }
  constexpr double kWindowFactor = 5.0;  // c of Sokal's automatic window
  for (std::size_t m = 1; m < n / 2; ++m) {
    a.tau_int += autocovariance(m) / c0;
    if (static_cast<double>(m) >= kWindowFactor * a.tau_int) {
      a.converged = true;
      break;
    }
  }
  return a;
}

MeanWithError mean_with_error(std::span<const double> x) {
  const std::size_t n = x.size();
  SG_VERIFY(n >= 2, "mean with error needs at least 2 samples, got " << n);
  MeanWithError m;
  for (double v : x)
    m.mean += v;
  m.mean /= static_cast<double>(n);
  double var = 0.0;
  for (double v : x)
    var += (v - m.mean) * (v - m.mean);
  m.std = std::sqrt(var / static_cast<double>(n - 1));
  // tau_int below 1/2 (anticorrelated noise) would claim more independent samples than there
  // are: not credited.
  m.tau_int = std::max(0.5, integrated_autocorrelation(x).tau_int);
  m.error = m.std * std::sqrt(2.0 * m.tau_int / static_cast<double>(n));
  return m;
}

Trend linear_trend(std::span<const double> t, std::span<const double> x) {
  const std::size_t n = t.size();
  SG_VERIFY(n >= 3 && x.size() == n, "trend needs at least 3 samples of (t, x), got " << n);
  double tm = 0.0, xm = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    tm += t[i];
    xm += x[i];
  }
  tm /= static_cast<double>(n);
  xm /= static_cast<double>(n);
  double stt = 0.0, stx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    stt += (t[i] - tm) * (t[i] - tm);
    stx += (t[i] - tm) * (x[i] - xm);
  }
  SG_VERIFY(stt > 0.0, "trend needs two distinct times");
  Trend r;
  r.slope = stx / stt;
  std::vector<double> residual(n);
  double ss = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    residual[i] = x[i] - (xm + r.slope * (t[i] - tm));
    ss += residual[i] * residual[i];
  }
  const double tau = std::max(0.5, integrated_autocorrelation(residual).tau_int);
  // OLS: var(b) = s^2 / S_tt with s^2 = SS / (n - 2); correlated residuals: times 2 tau_int.
  r.slope_error = std::sqrt(ss / static_cast<double>(n - 2) / stt * 2.0 * tau);
  const double span = t[n - 1] - t[0];
  r.change = r.slope * span;
  r.change_error = r.slope_error * std::abs(span);
  return r;
}

}  // namespace sg
