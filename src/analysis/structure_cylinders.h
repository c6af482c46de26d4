#pragma once
// The space-time picture of the agglomerates (paper 002 §2.2, Figs 8C, 9, 10, 14): the
// filtered coherence |C| > threshold stacked over time, and each detected structure drawn as
// a cylinder standing in the (x, y, t) volume:
//   axis at the structure's centre (x: circular mean over the period, so that a structure
//   crossing the seam sits at the seam, not in the middle of the cell; y: mean), over its
//   cells in every frame where it appears;
//   height = lifetime (frames x frame period), from half a period before its first frame;
//   diameter = D = 2 sqrt(A_bar / pi), the mean-area diameter (agglomerates.h);
//   colour = omega~ (eq. 7), or its sign of rotation.
#include <string>
#include <vector>

#include "analysis/agglomerates.h"

namespace sg {

struct StructureCylinder {
  int label = 0;
  int sign = 0;  // +1 counter-clockwise, -1 clockwise
  double x_center = 0.0, y_center = 0.0;
  double t_bottom = 0.0, height = 0.0;  // time of the base, lifetime
  double diameter = 0.0;
  double omega_tilde = 0.0;  // NaN if unknown
};

// `first_time`: the time of frame 0.
std::vector<StructureCylinder> structure_cylinders(const AgglomerateResult& result,
                                                   double first_time);

// The cells of the stacked picture, one row per marked grid cell of every frame:
// frame,time,x,y,sign,label (written atomically). `first_time`: the time of frame 0.
void write_space_time_csv(const std::string& path, const AgglomerateResult& result,
                          double first_time);

// One row per cylinder: label,sign,x_center,y_center,t_bottom,height,diameter,omega_tilde.
void write_cylinders_csv(const std::string& path, const std::vector<StructureCylinder>& cylinders);

}  // namespace sg
