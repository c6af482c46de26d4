#pragma once
// Rounding to whole numbers, exactly as the standard library does, inline: in the baseline
// x86-64 build (SSE2, no rounding instruction) std::round and std::floor are calls into libm,
// and the contact phase calls them for every candidate pair (the nearest periodic image) and
// the broad phase's grid for every node and segment end.
#include <cmath>

namespace sg {

// std::round(x), bit for bit (halves away from zero, the sign of zero kept), for any x.
inline double round_half_away(double x) {
  constexpr double kWhole = 4503599627370496.0;  // 2^52: from here on every double is whole
  if (!(std::abs(x) < kWhole)) return x;         // (and NaN)
  const double t = static_cast<double>(static_cast<long long>(x));  // toward zero
  const double fraction = x - t;                                    // exact
  if (fraction >= 0.5) return t + 1.0;
  if (fraction <= -0.5) return t - 1.0;
  return std::copysign(t, x);  // std::round(-0.3) is -0.0
}

// floor(x) as an integer, exactly, for finite x within the range of long long (the binning of
// the 400-grain cell of bench/scenes/imex-cell-400.toml took 0.8 ms per rebuild with
// std::floor: four per segment and two per node).
inline long long floor_index(double x) {
  const auto truncated = static_cast<long long>(x);
  return truncated - (static_cast<double>(truncated) > x ? 1 : 0);
}

}  // namespace sg
