#pragma once
// The steady-state window of a run: the rows of series.csv over which time averages
// are taken (paper 001 §2.3: "time averages on the whole duration of the steady-state
// sliding"; paper 002 §2.1.1 discards a fixed transient).
//
// Criterion when not given: MSER-m, the Marginal Standard Error Rule on batch means
// (White 1997, Simulation 69(6):323-334; White, Cobb & Spratt 2000, MSER-5). For a
// candidate truncation d (in batches), MSER(d) = sum_{j>=d} (z_j - zbar_d)^2 / (k-d)^2
// over the k batch means z_j: the squared standard error of the mean of what is kept.
// Cutting more of a biased transient lowers it; cutting stationary data raises it (fewer
// samples), so the minimum marks the end of the transient. It has no tuning band, it is
// the standard rule in simulation output analysis, and it is a change-point detector on
// the running mean. As is standard, d is searched in the first half of the series only;
// a minimum at that limit means the transient was not over (flagged, not hidden).
// Applied to the normal and the tangential force of every driven body; the window starts
// at the latest of these truncation points, so that every averaged signal is stationary.
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "analysis/driven_body.h"
#include "analysis/series.h"

namespace sg {

struct TimeWindow {
  std::size_t first = 0;  // first row in the window
  std::size_t last = 0;   // last row in the window (inclusive)
  double t_begin = 0.0;   // time of row `first`
  double t_end = 0.0;     // time of row `last`
  bool detected = false;  // true: found by MSER; false: given by the user
  // MSER's minimum sat at the search limit (half the series): the run is probably too
  // short for its transient, and the averages are suspect.
  bool truncation_at_limit = false;

  std::size_t size() const { return last - first + 1; }
};

struct MserResult {
  std::size_t truncation = 0;  // number of leading samples to discard
  bool at_limit = false;
};

// MSER-m on one signal (batch size m >= 1; m = 5 is the usual MSER-5). Needs at least
// 2 full batches.
MserResult mser_truncation(std::span<const double> signal, std::size_t batch = 5);

// Steady-state window by MSER-m on Fn(t) and Ft(t) of each body; ends at the last row.
// `not_before`: the end of what the scenario drives on purpose before the steady state (the
// shear cell's compaction or load ramp, a drive's last breakpoint): when MSER over the whole
// series starts before it (a ramp whose bias is below the noise; issue #29: a window started at
// t = 1.2 inside the load ramp), MSER runs again on the rows from that time on, so the window
// never starts inside it; a window MSER puts after it is unchanged.
TimeWindow detect_steady_window(const Series& series, std::span<const DrivenBody> bodies,
                                std::size_t batch = 5,
                                double not_before = -std::numeric_limits<double>::infinity());

// The window of rows with t_begin <= time <= t_end (t_end = +inf for "to the end").
// Throws sg::Error if it holds fewer than 2 rows.
TimeWindow window_from_times(const Series& series, double t_begin, double t_end);

}  // namespace sg
