// The two-slope law (contact_law.h): coulomb with a normal stiffness that depends on the
// direction of the normal motion, the reference code's TwoSlopesMohrCoulomb.
//
// Restitution: a contact loaded along k_n to the largest penetration delta stores
// 1/2 k_n delta^2; unloaded along r k_n it gives back 1/2 r k_n delta^2, so a frictionless
// impact of a mass on it rebounds with v_out^2 / v_in^2 = r, e = sqrt(r). The drop of the
// traction from k_n delta to r k_n delta at the reversal is where the energy goes (booked by
// the work-less-stored-change rule, contact_law.h).
#include <cmath>

#include "contact/contact_law_parts.h"

namespace sg::contact_law_parts {

ContactTraction evaluate_two_slope(const ContactLawParams& params, const ContactKinematics& kin,
                                   ContactHistory& history) {
  const double gap = kin.normal_gap;
  if (gap >= 0.0) {  // no tension: the surfaces separate, the springs let go
    history.stored_slip = 0.0;
    history.active = false;
    history.unloading = false;
    history.energy = 0.0;
    return ContactTraction{};
  }
  // Unloading while the gap opens (v_n > 0); loading while it closes or holds, and on first
  // touch.
  const bool unloading = history.active && gap > history.normal_gap;
  const double trial_slip = history.active ? history.stored_slip + kin.slip_increment : 0.0;
  const double k_n =
      unloading ? params.unloading_ratio * params.normal_stiffness : params.normal_stiffness;
  ContactTraction out;
  out.normal = -k_n * gap;
  history.active = true;
  history.unloading = unloading;
  apply_tangential_threshold(params.tangential_stiffness, params.friction * out.normal, trial_slip,
                             history, out);
  history.energy = 0.5 * k_n * gap * gap +
                   0.5 * params.tangential_stiffness * history.stored_slip * history.stored_slip;
  return out;
}

}  // namespace sg::contact_law_parts
