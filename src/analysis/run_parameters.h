#pragma once
// The few scenario values the analysis needs and series.csv does not hold. The CLI will
// fill them from the scenario; NaN means "unknown", and every quantity that needs an
// unknown value is then reported as absent (null in summary.json), never guessed.
#include <limits>

namespace sg {

struct RunParameters {
  static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
  double length = kUnknown;    // L, period of the cell along x (length)
  double gap = kUnknown;       // D, distance between the first bodies (length)
  double velocity = kUnknown;  // V, relative sliding velocity of the first bodies (length/time)
  double young_modulus = kUnknown;  // E of the grains (stress)
  double cohesion =
      kUnknown;  // c, contact strength per unit length (stress x length / length = stress in 2D)
  double damping_alpha = kUnknown;  // alpha, stiffness-proportional Rayleigh coefficient (time)
  double mean_diameter = kUnknown;  // mean grain diameter (length); grid spacing default
  // p, the normal stress imposed on the loaded first body under pressure loading (stress:
  // force per unit length in 2D); NaN under gap loading, where sigma_n is an output.
  double pressure = kUnknown;
};

}  // namespace sg
