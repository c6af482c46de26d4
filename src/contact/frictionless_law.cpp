// The frictionless law (contact_law.h): a normal penalty spring in compression only,
// p_n = k_n max(-g_n, 0), p_t = 0. Nothing is dissipated, ever.
#include "contact/contact_law_parts.h"

namespace sg::contact_law_parts {

ContactTraction evaluate_frictionless(const ContactLawParams& params, double normal_gap,
                                      ContactHistory& history) {
  history.stored_slip = 0.0;
  history.active = normal_gap < 0.0;
  ContactTraction out;
  if (history.active) out.normal = -params.normal_stiffness * normal_gap;
  return out;
}

}  // namespace sg::contact_law_parts
