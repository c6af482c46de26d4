#include "analysis/agglomerate_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sg {

AgglomerateStatistics compute_agglomerate_statistics(const AgglomerateResult& result,
                                                     double mean_diameter) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  AgglomerateStatistics s;
  s.grain_share = result.grain_share;
  std::vector<double> omega, diameter, weight;
  double max_diameter = 0.0;
  double w_omega = 0.0, sum_omega = 0.0, w_all = 0.0, sum_d = 0.0, sum_life = 0.0;
  for (const auto& st : result.structures) {
    s.structure_count += 1.0;
    (st.sign > 0 ? s.positive_count : s.negative_count) += 1.0;
    const auto w = static_cast<double>(st.grain_samples);
    omega.push_back(st.omega_normalized);
    diameter.push_back(st.diameter);
    weight.push_back(w);
    max_diameter = std::max(max_diameter, st.diameter);
    if (w > 0.0 && std::isfinite(st.omega_normalized)) {
      w_omega += w;
      sum_omega += w * st.omega_normalized;
    }
    w_all += w;
    sum_d += w * st.diameter;
    sum_life += w * st.lifetime;
  }
  s.omega_mean = w_omega > 0.0 ? sum_omega / w_omega : nan;
  s.diameter_mean = w_all > 0.0 ? sum_d / w_all : nan;
  s.lifetime_mean = w_all > 0.0 ? sum_life / w_all : nan;
  s.omega_pdf = weighted_pdf(omega, weight, 100, -5.0, 5.0);
  const double width = mean_diameter > 0.0 ? 0.5 * mean_diameter : 0.5;
  const int bins = std::max(1, static_cast<int>(std::ceil(max_diameter / width)));
  s.diameter_pdf = weighted_pdf(diameter, weight, bins, 0.0, bins * width);
  s.omega_mode = s.omega_pdf.mode();
  s.diameter_mode = s.diameter_pdf.mode();
  return s;
}

}  // namespace sg
