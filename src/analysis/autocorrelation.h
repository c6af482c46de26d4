#pragma once
// Statistics of a correlated time series sampled at a constant interval (a series.csv
// column over the window): how many samples are effectively independent, hence the error of
// its mean and of a fitted trend.
//
// Integrated autocorrelation time (Sokal 1997, "Monte Carlo methods in statistical
// mechanics: foundations and new algorithms", in Functional Integration, Plenum, §3, eqs.
// 3.17-3.20):   tau_int = 1/2 + sum_{k=1}^{M} rho(k),   rho(k) the normalized autocovariance
// at lag k, summed over the automatic window M: the smallest M with M >= c tau_int(M), c = 5
// (the sum over all lags is pure noise beyond the decay). The variance of the mean of n
// samples is then 2 tau_int var / n: n / (2 tau_int) samples are effectively independent
// (white noise: tau_int = 1/2, the usual var / n).
#include <span>

namespace sg {

struct Autocorrelation {
  double tau_int = 0.5;    // integrated autocorrelation time, in samples (>= 1/2 is not forced)
  bool converged = false;  // the window M met M >= 5 tau_int before half the series
};

// Of `x` (at least 2 samples); a constant series gives tau_int = 1/2.
Autocorrelation integrated_autocorrelation(std::span<const double> x);

// Mean of `x` with its standard error sqrt(2 tau_int / n) s (s the sample standard deviation).
struct MeanWithError {
  double mean = 0.0;
  double std = 0.0;    // sample standard deviation
  double error = 0.0;  // standard error of the mean, from tau_int
  double tau_int = 0.5;
};
MeanWithError mean_with_error(std::span<const double> x);

// Least-squares line x = a + b t over the samples, with the standard error of the slope
// inflated by sqrt(2 tau_int) of the residuals (the effective sample size n / (2 tau_int)):
// `change` = b (t_last - t_first), the trend's change over the span, and its error.
struct Trend {
  double slope = 0.0, slope_error = 0.0;
  double change = 0.0, change_error = 0.0;
};
// Needs at least 3 samples and two distinct times.
Trend linear_trend(std::span<const double> t, std::span<const double> x);

}  // namespace sg
