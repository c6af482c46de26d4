#pragma once
// Velocity profiles across the gap and the solid fraction of the layer (paper 001
// §3.2 velocity profiles; paper 002 §3.3 solid fraction S_F).
//
// Profiles: grains of every snapshot of the window are binned by the y of their centre of
// mass into n equal bins over [y_min, y_max]; per bin, mean and sample std of vx and vy
// over all (grain, snapshot) samples that fall in it. Unweighted: one grain, one sample,
// as in the papers' plots of grain velocities. Grains outside [y_min, y_max] (e.g. stuck
// in a roughness valley) are counted apart, not silently folded into an edge bin.
//
// Solid fraction: S_F = sum of grain areas / (L (y_max - y_min)), the area of matter over
// the area of the layer between the first bodies (paper 002 §3.3). Which y_min, y_max
// (mean lines of the rough surfaces, say) is the caller's choice and must be reported.
#include <span>
#include <string>
#include <vector>

#include "analysis/grain_snapshot.h"

namespace sg {

struct ProfileBin {
  double y_center = 0.0;
  std::size_t count = 0;               // samples in the bin
  double vx_mean = 0.0, vx_std = 0.0;  // NaN if count == 0; std 0 if count == 1
  double vy_mean = 0.0, vy_std = 0.0;
};

struct VelocityProfile {
  double y_min = 0.0, y_max = 0.0;
  std::vector<ProfileBin> bins;
  std::size_t outside = 0;  // samples with y outside [y_min, y_max]
};

VelocityProfile compute_velocity_profile(std::span<const GrainSnapshot> snapshots, double y_min,
                                         double y_max, int bin_count);

// CSV: y_center,count,vx_mean,vx_std,vy_mean,vy_std (written atomically).
void write_velocity_profile_csv(const std::string& path, const VelocityProfile& profile);

double solid_fraction(const GrainSnapshot& snapshot, double length, double y_min, double y_max);

// Mean of solid_fraction over the snapshots.
double mean_solid_fraction(std::span<const GrainSnapshot> snapshots, double length, double y_min,
                           double y_max);

}  // namespace sg
