#pragma once
// Activated third-body thickness, ATT (paper 003 §3.4, Fig. 13): the thickness of the layer
// that accommodates the velocity jump, "the third body layer in which particles carry
// velocities of 20-80 m/s" for a jump of 100 m/s. With u = (vx - v_bottom) / (v_top - v_bottom)
// the grain's share of the jump, and thresholds lo < hi (paper 003: 0.2 and 0.8):
//
//   from the velocity map (Fig. 13a):  ATT = H * sum_{u_i in [lo, hi]} A_i / sum_i A_i
//     the share of the layer's matter (grain areas A_i) that moves at between lo and hi of
//     the jump, times the layer thickness H: the thickness those grains fill at the layer's
//     mean solid fraction;
//   from the profile (Fig. 13b):       ATT = sum of the heights of the bins whose mean u lies
//     in [lo, hi] (the bins' resolution: one bin height).
//
// A linear (Couette) profile across H gives (hi - lo) H, 0.6 H for the default thresholds; a
// plug flow with a thin band moving at between lo and hi gives the band's thickness.
#include <span>
#include <vector>

#include "analysis/grain_snapshot.h"
#include "analysis/profiles.h"

namespace sg {

struct AttThresholds {
  double lo = 0.2, hi = 0.8;  // shares of the velocity jump (paper 003: 20% and 80%)
};

// Throws sg::Error if v_top == v_bottom, lo >= hi, H <= 0, or the snapshot has no grain.
double activated_thickness_from_grains(const GrainSnapshot& snapshot, double v_bottom, double v_top,
                                       double layer_thickness,
                                       const AttThresholds& thresholds = {});

// Bins without samples count as outside. Throws sg::Error as above.
double activated_thickness_from_profile(const VelocityProfile& profile, double v_bottom,
                                        double v_top, const AttThresholds& thresholds = {});

struct AttSample {
  double time = 0.0;
  double from_grains = 0.0, from_profile = 0.0;  // length
};

struct AttSeries {
  AttThresholds thresholds;
  double layer_thickness = 0.0;  // H used by the map measure
  int profile_bins = 0;
  std::vector<AttSample> samples;  // one per snapshot of the window
  double mean_from_grains = 0.0, mean_from_profile = 0.0;
};

// Both measures per snapshot (the profile of each snapshot alone, `bins` bins over
// [y_min, y_max]) and their means over the snapshots.
AttSeries activated_thickness_series(std::span<const GrainSnapshot> snapshots, double v_bottom,
                                     double v_top, double layer_thickness, double y_min,
                                     double y_max, int bins, const AttThresholds& thresholds);

// CSV: time,att_map,att_profile (written atomically).
void write_att_csv(const std::string& path, const AttSeries& series);

}  // namespace sg
