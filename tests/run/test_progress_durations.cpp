// The run's progress line: durations (ETA, run time) in readable units, and the ETA of a run
// whose step collapsed (huge or infinite) named rather than converted.
#include <gtest/gtest.h>

#include <limits>

#include "run/progress_output.h"

namespace sg {
namespace {

TEST(FormatDuration, ReadsInTheLargestUnitThatFits) {
  EXPECT_EQ(format_duration(12.0), "12s");
  EXPECT_EQ(format_duration(3 * 60 + 4.5), "3m4s");
  EXPECT_EQ(format_duration(2 * 3600 + 5 * 60 + 59), "2h5m");
  // The README's 19 days of an explicit paper-scale run at alpha = 0.3.
  EXPECT_EQ(format_duration(19 * 86400.0 + 2 * 3600 + 30), "19d2h");
}

TEST(FormatDuration, NamesDurationsItCannotConvert) {
  EXPECT_EQ(format_duration(std::numeric_limits<double>::infinity()), "unknown");
  EXPECT_EQ(format_duration(std::numeric_limits<double>::quiet_NaN()), "unknown");
  EXPECT_EQ(format_duration(-1.0), "unknown");
  // Beyond any int: the conversion the ETA used to make here was undefined behaviour.
  EXPECT_EQ(format_duration(1e300), "over 10000 days");
  EXPECT_EQ(format_duration(9999.0 * 86400.0), "9999d0h");
}

}  // namespace
}  // namespace sg
