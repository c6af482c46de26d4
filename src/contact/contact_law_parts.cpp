// The sub-models several contact laws share (contact_law_parts.h).
#include <cmath>

#include "contact/contact_law_parts.h"

namespace sg::contact_law_parts {

void apply_tangential_threshold(double tangential_stiffness, double threshold, double trial_slip,
                                ContactHistory& history, ContactTraction& out) {
  const double trial_traction = -tangential_stiffness * trial_slip;  // p_t = -k_t g_t
  if (std::abs(trial_traction) <= threshold) {
    history.stored_slip = trial_slip;
    out.tangential = trial_traction;
    return;
  }
  const double direction = trial_slip > 0.0 ? 1.0 : -1.0;
  const double elastic_slip = threshold / tangential_stiffness;        // |g_t| at the threshold
  out.tangential = -direction * threshold;                             // p_t = -/+ T
  history.stored_slip = direction * elastic_slip;                      // g_t = -p_t / k_t
  out.dissipated = threshold * (std::abs(trial_slip) - elastic_slip);  // T x plastic slip
  out.slipping = true;
}

ContactTraction open_contact(double released_energy, ContactHistory& history) {
  history.stored_slip = 0.0;
  history.active = false;
  ContactTraction out;
  out.dissipated = released_energy;
  return out;
}

double trial_slip(const ContactHistory& history, double slip_increment) {
  // A contact not active at the start of the increment starts it unloaded tangentially.
  return history.active ? history.stored_slip + slip_increment : 0.0;
}

}  // namespace sg::contact_law_parts
