// The cohesive law (contact_law.h; papers 001 §2.2 / 003 §2.1): a bond that holds the
// surfaces in compression and in tension up to the adhesion sigma_c, with the tangential
// threshold tau_c + mu_c max(p_n, 0); broken, it re-forms where the surfaces touch again.
#include <algorithm>

#include "contact/contact_law_parts.h"

namespace sg::contact_law_parts {

ContactTraction evaluate_cohesive(const ContactLawParams& params, double normal_gap,
                                  double slip_increment, ContactHistory& history) {
  const double k_n = params.normal_stiffness;
  const double k_t = params.tangential_stiffness;
  const double trial = trial_slip(history, slip_increment);
  if (!history.active) {
    if (normal_gap > 0.0) return open_contact(0.0, history);  // never touched / broken
    history.active = true;  // touching: the bond (re-)forms with g_t = 0
  }
  const double normal = -k_n * normal_gap;  // p_n = -k_n g_n, tension allowed
  if (normal < -params.adhesion) {
    // Tension beyond sigma_c: the bond breaks (paper 001 §2.2, docs/method.md §Contact).
    const double released =
        0.5 * k_n * history.normal_gap * normal_gap + 0.5 * k_t * history.stored_slip * trial;
    ContactTraction out = open_contact(released, history);
    out.bond_broken = true;
    return out;
  }
  ContactTraction out;
  out.normal = normal;
  // Threshold tau_c + mu_c max(p_n, 0) (docs/method.md §Contact; paper 003 §2.1: separate
  // sigma and tau).
  const double threshold = params.shear_strength + params.friction * std::max(normal, 0.0);
  apply_tangential_threshold(k_t, threshold, trial, history, out);
  return out;
}

}  // namespace sg::contact_law_parts
