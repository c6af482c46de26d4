#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "core/rounding.h"

namespace sg {
namespace {

// Same bits as std::round: the contact phase's nearest periodic images must not change.
void expect_same_bits_as_std_round(double x) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(round_half_away(x)),
            std::bit_cast<std::uint64_t>(std::round(x)))
      << "x = " << x;
}

TEST(Rounding, RoundHalfAwayIsStdRoundBitForBit) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> edges = {0.0,
                                     -0.0,
                                     0.3,
                                     -0.3,
                                     0.5,
                                     -0.5,
                                     std::nextafter(0.5, 0.0),
                                     std::nextafter(-0.5, 0.0),
                                     1.5,
                                     -1.5,
                                     2.5,
                                     -2.5,
                                     std::nextafter(2.5, 3.0),
                                     4503599627370495.5,
                                     -4503599627370495.5,
                                     4503599627370496.0,
                                     9007199254740993.0,
                                     1e300,
                                     -1e300,
                                     std::numeric_limits<double>::denorm_min(),
                                     -std::numeric_limits<double>::denorm_min(),
                                     inf,
                                     -inf};
  for (const double x : edges)
    expect_same_bits_as_std_round(x);
  // Quotients like the contact phase's (offsets over a period), over many magnitudes.
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 100000; ++i)
    expect_same_bits_as_std_round(unit(random) * std::pow(10.0, i % 12 - 4));
  EXPECT_TRUE(std::isnan(round_half_away(std::numeric_limits<double>::quiet_NaN())));
}

}  // namespace
}  // namespace sg
