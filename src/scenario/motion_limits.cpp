#include "scenario/motion_limits.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sg {

TravelLimit::TravelLimit(const ScenarioDef& s)
    : duration_(s.duration), node_spacing_(s.discretization.mesh.spacing) {}

void TravelLimit::check_speed(const TomlReader& t, const std::string& key, double speed,
                              const std::string& body) const {
  const double travel = std::abs(speed) * duration_;
  const double limit = kMaxTravelInNodeSpacings * node_spacing_;
  if (travel <= limit) return;
  std::ostringstream m;
  m << body << ": a speed of " << std::abs(speed) << " carries it " << travel
    << " over the duration " << duration_ << "; expected at most " << kMaxTravelInNodeSpacings
    << " node spacings (" << limit << "), |velocity| x duration <= " << limit
    << " (the contact grid spans the bodies' reach)";
  t.fail(key, m.str());
}

void TravelLimit::check_drive(const TomlReader& t, const DriveDef& drive,
                              const std::string& body) const {
  const char* axes[2] = {"x", "y"};
  for (int k = 0; k < 2; ++k) {
    const auto& a = drive.axis[static_cast<std::size_t>(k)];
    if (!a || a->kind != AxisDriveKind::velocity || a->history.values.empty()) continue;
    const auto fastest =
        std::max_element(a->history.values.begin(), a->history.values.end(),
                         [](double u, double v) { return std::abs(u) < std::abs(v); });
    check_speed(*t.table(axes[k]), "velocity", *fastest, body);
  }
}

void check_material_frequency(const TomlReader& t, const MaterialDef& m, double node_spacing) {
  // Plane strain P-wave modulus: the stiffest wave of an isotropic solid.
  const double nu = m.poisson;
  const double p_modulus = m.young * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double frequency = std::sqrt(p_modulus / m.density) / node_spacing;
  if (frequency <= kMaxWaveFrequency) return;
  std::ostringstream s;
  s << "material '" << m.name << "': young " << m.young << " over density " << m.density
    << " (poisson " << nu << ") with node_spacing " << node_spacing
    << " vibrate at a frequency of about " << frequency << " (P-wave speed / node spacing), "
    << "beyond what the stable-step estimate can hold: expected at most " << kMaxWaveFrequency
    << " (check the units of young and density)";
  t.fail("young", s.str());
}

}  // namespace sg
