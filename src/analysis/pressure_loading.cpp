#include "analysis/pressure_loading.h"

#include <cmath>
#include <sstream>

namespace sg {

double coordinate_normal_stress(double imposed_pressure, double mean_normal_stress) {
  return imposed_pressure > 0.0 ? imposed_pressure : mean_normal_stress;
}

std::optional<SteadinessWarning> check_imposed_pressure(const FrictionResult& friction,
                                                        double imposed_pressure, double tolerance) {
  if (!(imposed_pressure > 0.0)) return std::nullopt;
  for (const FrictionStats& body : friction.bodies) {
    if (body.body != kLoadedFirstBody || !std::isfinite(body.normal_stress)) continue;
    const double mismatch = body.normal_stress / imposed_pressure - 1.0;
    if (std::abs(mismatch) <= tolerance) return std::nullopt;
    std::ostringstream m;
    m << "the loaded first body '" << kLoadedFirstBody << "' carries a mean normal stress of "
      << body.normal_stress << " over the window against the imposed pressure " << imposed_pressure
      << " (" << (mismatch > 0 ? "+" : "") << 100.0 * mismatch << "%; more than "
      << 100.0 * tolerance
      << "%): the servo has not loaded the layer yet (a smaller [shear_cell] servo_damping, "
         "a lighter top or a longer run)";
    return SteadinessWarning{"pressure_not_reached", m.str()};
  }
  return std::nullopt;
}

}  // namespace sg
