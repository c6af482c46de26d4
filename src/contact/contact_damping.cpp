// Contact damping (contact_law.h): viscous normal and tangential tractions of a damping
// ratio, composed with any law; the reference code's DampedMohrCoulomb made general.
#include <cmath>

#include "contact/contact_law_parts.h"

namespace sg::contact_law_parts {

void add_viscous_tractions(const ContactLawParams& params, const ContactKinematics& kin,
                           const ContactHistory& before, ContactHistory& history,
                           ContactTraction& out) {
  // The rates need the previous gap (an active contact's history) and a step; the
  // coefficients a mass and a length.
  double viscous_normal = 0.0, viscous_tangential = 0.0;
  if (before.active && history.active && kin.interval > 0.0 && kin.effective_mass > 0.0 &&
      kin.initial_length > 0.0) {
    // c = 2 zeta sqrt(m_eff k / L0) per unit length: critical damping of a mass m_eff on a
    // spring k L0, divided by L0.
    const double mass_per_length = kin.effective_mass / kin.initial_length;
    const double normal_rate = (kin.normal_gap - before.normal_gap) / kin.interval;
    viscous_normal = -2.0 * params.damping_ratio *
                     std::sqrt(mass_per_length * params.normal_stiffness) * normal_rate;
    if (!out.slipping)
      viscous_tangential = -2.0 * params.damping_ratio *
                           std::sqrt(mass_per_length * params.tangential_stiffness) *
                           (kin.slip_increment / kin.interval);
  }
  // Trapezoidal work of the viscous tractions over the increment (contact_law.h).
  if (before.active)
    out.dissipated +=
        -0.5 * (before.viscous_normal + viscous_normal) * (kin.normal_gap - before.normal_gap) -
        0.5 * (before.viscous_tangential + viscous_tangential) * kin.slip_increment;
  out.normal += viscous_normal;
  out.tangential += viscous_tangential;
  history.viscous_normal = viscous_normal;
  history.viscous_tangential = viscous_tangential;
}

}  // namespace sg::contact_law_parts
