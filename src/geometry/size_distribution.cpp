#include "geometry/size_distribution.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace sg {

int uniform_index(RandomEngine& engine, int n) {
  SG_ASSERT(n >= 1, "uniform_index needs n >= 1, got " << n);
  const int k = static_cast<int>(uniform01(engine) * n);
  return std::min(k, n - 1);
}

void verify_size_range(const SizeRangeDef& range, const char* what) {
  SG_VERIFY(range.min > 0.0 && range.max >= range.min && std::isfinite(range.max),
            what << ": size range must satisfy 0 < min <= max, got [" << range.min << ", "
                 << range.max << "]");
}

// Inverse CDFs of the three laws, u uniform in [0, 1).
double sample_size(const SizeRangeDef& range, RandomEngine& engine) {
  const double u = uniform01(engine);
  const double a = range.min, b = range.max;
  if (a == b) return a;
  switch (range.law) {
    case SizeLaw::uniform:
      return a + u * (b - a);
    case SizeLaw::uniform_area:
      // F(d) = (1/a - 1/d) / (1/a - 1/b)  =>  1/d = 1/a - u (1/a - 1/b).
      return 1.0 / (1.0 / a - u * (1.0 / a - 1.0 / b));
    case SizeLaw::log_uniform:
      // F(d) = ln(d/a) / ln(b/a).
      return a * std::pow(b / a, u);
  }
  return a;
}

std::vector<double> sample_sizes(const SizeRangeDef& range, int count, std::uint64_t seed) {
  verify_size_range(range, "size distribution");
  SG_VERIFY(count >= 0, "size distribution: count must be >= 0, got " << count);
  RandomEngine engine(seed);
  std::vector<double> out(static_cast<std::size_t>(count));
  for (double& d : out)
    d = sample_size(range, engine);
  return out;
}

double size_cdf(const SizeRangeDef& range, double d) {
  const double a = range.min, b = range.max;
  if (d < a) return 0.0;
  if (d >= b) return 1.0;
  switch (range.law) {
    case SizeLaw::uniform:
      return (d - a) / (b - a);
    case SizeLaw::uniform_area:
      return (1.0 / a - 1.0 / d) / (1.0 / a - 1.0 / b);
    case SizeLaw::log_uniform:
      return std::log(d / a) / std::log(b / a);
  }
  return 0.0;
}

// Raw moment E[d^k] of each law, k = 1 or 2, from the densities listed in the header.
static double raw_moment(const SizeRangeDef& range, int k) {
  const double a = range.min, b = range.max;
  if (a == b) return std::pow(a, k);
  switch (range.law) {
    case SizeLaw::uniform:  // (b^{k+1} - a^{k+1}) / ((k+1)(b - a))
      return (std::pow(b, k + 1) - std::pow(a, k + 1)) / ((k + 1) * (b - a));
    case SizeLaw::uniform_area: {  // p(d) = c / d^2, c = 1 / (1/a - 1/b)
      const double c = 1.0 / (1.0 / a - 1.0 / b);
      return k == 1 ? c * std::log(b / a) : c * (b - a);
    }
    case SizeLaw::log_uniform:  // p(d) = 1 / (d ln(b/a))
      return (std::pow(b, k) - std::pow(a, k)) / (k * std::log(b / a));
  }
  return 0.0;
}

double size_mean(const SizeRangeDef& range) {
  return raw_moment(range, 1);
}

double size_variance(const SizeRangeDef& range) {
  const double m = raw_moment(range, 1);
  return std::max(0.0, raw_moment(range, 2) - m * m);
}

double ks_statistic(std::vector<double> x, const SizeRangeDef& range) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  // The supremum is reached at a sample point, on one side of the jump of F_n there:
  // F_n jumps from i/n to (i+1)/n at x_(i).
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = size_cdf(range, x[i]);
    // A monodisperse law is a step at min, where F jumps 0 -> 1 together with F_n: the
    // left limits agree as well.
    const double f_left = range.min == range.max && x[i] == range.min ? 0.0 : f;
    d = std::max({d, (static_cast<double>(i) + 1.0) / n - f, f_left - static_cast<double>(i) / n});
  }
  return d;
}

double ks_critical_value_5pct(std::size_t n) {
  return n == 0 ? 0.0 : 1.36 / std::sqrt(static_cast<double>(n));
}

}  // namespace sg
