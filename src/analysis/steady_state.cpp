#include "analysis/steady_state.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/friction.h"
#include "core/error.h"

namespace sg {

MserResult mser_truncation(std::span<const double> signal, std::size_t batch) {
  SG_VERIFY(batch >= 1, "MSER batch size must be >= 1, got " << batch);
  const std::size_t k = signal.size() / batch;  // a trailing partial batch is dropped
  SG_VERIFY(k >= 2, "MSER needs at least 2 batches of " << batch << " samples, got "
                                                        << signal.size() << " samples");
  std::vector<double> z(k);
  for (std::size_t j = 0; j < k; ++j) {
    double s = 0.0;
    for (std::size_t i = 0; i < batch; ++i)
      s += signal[j * batch + i];
    z[j] = s / static_cast<double>(batch);
  }
  // Two-pass variance per candidate would be O(k^2); suffix sums of z - z_ref keep it O(k)
  // and, being centred on a typical value, avoid cancellation for signals with a large
  // mean (forces of order 100 with fluctuations of order 1).
  const double z_ref = z[k - 1];
  std::vector<double> s1(k + 1, 0.0), s2(k + 1, 0.0);
  for (std::size_t j = k; j-- > 0;) {
    const double u = z[j] - z_ref;
    s1[j] = s1[j + 1] + u;
    s2[j] = s2[j + 1] + u * u;
  }
  const std::size_t d_max = k / 2;
  MserResult best;
  double best_value = std::numeric_limits<double>::infinity();
  for (std::size_t d = 0; d <= d_max; ++d) {
    const double n = static_cast<double>(k - d);
    const double ss = std::max(0.0, s2[d] - s1[d] * s1[d] / n);
    const double value = ss / (n * n);
    if (value < best_value) {  // strict: the earliest minimum wins ties
      best_value = value;
      best.truncation = d * batch;
    }
  }
  best.at_limit = k >= 4 && best.truncation == d_max * batch;
  return best;
}

namespace {

// The latest MSER truncation over Fn and Ft of every body, on the rows from `offset` on.
std::size_t mser_start(const Series& series, std::span<const DrivenBody> bodies, std::size_t batch,
                       std::size_t offset, bool& at_limit) {
  std::size_t start = offset;
  at_limit = false;
  for (const auto& body : bodies) {
    const BodyForces f = body_forces(series, body);
    for (const auto* signal : {&f.normal, &f.tangential}) {
      const MserResult r = mser_truncation(std::span<const double>(*signal).subspan(offset), batch);
      start = std::max(start, offset + r.truncation);
      at_limit = at_limit || r.at_limit;
    }
  }
  return start;
}

}  // namespace

TimeWindow detect_steady_window(const Series& series, std::span<const DrivenBody> bodies,
                                std::size_t batch, double not_before) {
  SG_VERIFY(!bodies.empty(), series.path << ": no driven body to detect a steady state on");
  const auto time = series.column("time");
  // The first row at or after `not_before` (up to round-off of the written times).
  std::size_t first_allowed = 0;
  while (first_allowed < time.size() &&
         time[first_allowed] < not_before - 1e-9 * std::max(1.0, std::abs(not_before)))
    ++first_allowed;
  TimeWindow w;
  w.detected = true;
  // MSER over the whole series, as without a ramp; only if it starts inside the ramp (its bias
  // below the noise), MSER again over the rows after it. A window already after the ramp is
  // the one it always was.
  std::size_t start = mser_start(series, bodies, batch, 0, w.truncation_at_limit);
  if (start < first_allowed) {
    SG_VERIFY(first_allowed + 2 * batch <= time.size(),
              series.path << ": fewer than " << 2 * batch << " rows after t = " << not_before
                          << " (the end of the compaction or load ramp): no steady state to "
                             "detect; run longer");
    start = mser_start(series, bodies, batch, first_allowed, w.truncation_at_limit);
  }
  SG_VERIFY(start + 2 <= time.size(), series.path << ": steady-state window too short");
  w.first = start;
  w.last = time.size() - 1;
  w.t_begin = time[w.first];
  w.t_end = time[w.last];
  return w;
}

TimeWindow window_from_times(const Series& series, double t_begin, double t_end) {
  const auto time = series.column("time");
  TimeWindow w;
  w.detected = false;
  std::size_t first = time.size(), last = 0, count = 0;
  for (std::size_t i = 0; i < time.size(); ++i)
    if (time[i] >= t_begin && time[i] <= t_end) {
      first = std::min(first, i);
      last = i;
      ++count;
    }
  SG_VERIFY(count >= 2, series.path << ": window [" << t_begin << ", " << t_end << "] holds "
                                    << count << " rows, need at least 2");
  w.first = first;
  w.last = last;
  w.t_begin = time[first];
  w.t_end = time[last];
  return w;
}

}  // namespace sg
