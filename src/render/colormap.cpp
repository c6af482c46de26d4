#include "render/colormap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sg {

Rgb viridis(double t) {
  // matplotlib's viridis at t = 0, 0.1, ..., 1, linearly interpolated (close to the full
  // 256-entry table; the map's lightness is nearly linear in t).
  static constexpr std::array<std::array<double, 3>, 11> kTable = {{
      {0.267004, 0.004874, 0.329415},
      {0.282623, 0.140926, 0.457517},
      {0.253935, 0.265254, 0.529983},
      {0.206756, 0.371758, 0.553117},
      {0.163625, 0.471133, 0.558148},
      {0.127568, 0.566949, 0.550556},
      {0.134692, 0.658636, 0.517649},
      {0.266941, 0.748751, 0.440573},
      {0.477504, 0.821444, 0.318195},
      {0.741388, 0.873449, 0.149561},
      {0.993248, 0.906157, 0.143936},
  }};
  if (std::isnan(t)) return {0.6, 0.6, 0.6};
  t = std::fmin(1.0, std::fmax(0.0, t));
  const double x = t * 10.0;
  const int i = std::min(9, static_cast<int>(x));
  const double f = x - i;
  const auto& a = kTable[static_cast<std::size_t>(i)];
  const auto& b = kTable[static_cast<std::size_t>(i + 1)];
  return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

// Moreland's cool-warm diverging map (K. Moreland, "Diverging Color Maps for Scientific
// Visualization", ISVC 2009), his table sampled every 1/8: blue -> light grey -> red, equal
// lightness on both sides, so C = -0.9 and C = +0.9 look equally strong.
Rgb cool_warm(double t) {
  static constexpr std::array<std::array<double, 3>, 9> kTable = {{
      {59, 76, 192},
      {98, 130, 234},
      {141, 176, 254},
      {184, 208, 249},
      {221, 221, 221},
      {245, 196, 173},
      {244, 154, 123},
      {222, 96, 77},
      {180, 4, 38},
  }};
  if (std::isnan(t)) return {0.45, 0.45, 0.45};  // undefined: darker than the midpoint
  t = std::fmin(1.0, std::fmax(0.0, t));
  const double x = t * 8.0;
  const int i = std::min(7, static_cast<int>(x));
  const double f = x - i;
  const auto& a = kTable[static_cast<std::size_t>(i)];
  const auto& b = kTable[static_cast<std::size_t>(i + 1)];
  return {((1 - f) * a[0] + f * b[0]) / 255.0, ((1 - f) * a[1] + f * b[1]) / 255.0,
          ((1 - f) * a[2] + f * b[2]) / 255.0};
}

Rgb category_colour(int k) {
  static constexpr std::array<std::array<int, 3>, 10> kTableau = {{
      {78, 121, 167},
      {242, 142, 43},
      {225, 87, 89},
      {118, 183, 178},
      {89, 161, 79},
      {237, 201, 72},
      {176, 122, 161},
      {255, 157, 167},
      {156, 117, 95},
      {186, 176, 172},
  }};
  const auto& c = kTableau[static_cast<std::size_t>(((k % 10) + 10) % 10)];
  return {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
}

Rgb agglomerate_colour(double grain_class) {
  if (std::isnan(grain_class)) return cool_warm(std::nan(""));
  if (grain_class > 0.5) return cool_warm(1.0);
  if (grain_class < -0.5) return cool_warm(0.0);
  return {0.86, 0.86, 0.86};  // lighter than the map's midpoint: clearly "not in a structure"
}

double ColourScale::fraction(double v) const {
  if (std::isnan(v)) return v;
  if (!log) return hi > lo ? (v - lo) / (hi - lo) : 0.5;
  if (v <= 0.0) return -std::numeric_limits<double>::infinity();
  return std::log(v / lo) / std::log(hi / lo);
}

double ColourScale::value_at(double f) const {
  return log ? lo * std::pow(hi / lo, f) : lo + f * (hi - lo);
}

std::vector<double> decades_within(double lo, double hi) {
  std::vector<double> out;
  if (!(lo > 0.0 && hi > lo)) return out;
  // A relative slack so that a bound that is a power of ten up to round-off counts as one.
  const double slack = 1e-9;
  for (int k = static_cast<int>(std::ceil(std::log10(lo) - slack));
       k <= static_cast<int>(std::floor(std::log10(hi) + slack)); ++k)
    out.push_back(std::pow(10.0, k));
  return out;
}

}  // namespace sg
