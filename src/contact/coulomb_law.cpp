// The Coulomb law (contact_law.h): no tension; while closed, a normal penalty spring and an
// elastic tangential spring that slips at mu_c p_n (docs/method.md §Contact, Laws).
#include "contact/contact_law_parts.h"

namespace sg::contact_law_parts {

ContactTraction evaluate_coulomb(const ContactLawParams& params, double normal_gap,
                                 double slip_increment, ContactHistory& history) {
  const double k_t = params.tangential_stiffness;
  const double trial = trial_slip(history, slip_increment);
  if (normal_gap >= 0.0) {
    // No tension: the surfaces separate and the tangential spring releases its energy.
    const double released = history.active ? 0.5 * k_t * history.stored_slip * trial : 0.0;
    return open_contact(released, history);
  }
  history.active = true;
  ContactTraction out;
  out.normal = -params.normal_stiffness * normal_gap;  // > 0
  // Coulomb threshold mu_c p_n (docs/method.md §Contact, Laws).
  apply_tangential_threshold(k_t, params.friction * out.normal, trial, history, out);
  return out;
}

}  // namespace sg::contact_law_parts
