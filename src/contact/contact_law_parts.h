#pragma once
// The pieces the contact laws are composed of (contact_law.h), shared by their files; not
// part of the contact stage's interface.
#include "contact/contact_law.h"

namespace sg::contact_law_parts {

// Elastic stick / plastic slip of the tangential spring under `threshold` (return mapping,
// contact_law.h): writes p_t, the slip flag, the friction dissipation and the stored slip.
void apply_tangential_threshold(double tangential_stiffness, double threshold, double trial_slip,
                                ContactHistory& history, ContactTraction& out);

// A contact that lets go (surfaces separate, a bond breaks): no traction, the tangential
// spring unloaded and the contact inactive; `released_energy` is booked as dissipated.
ContactTraction open_contact(double released_energy, ContactHistory& history);

// The tangential slip a law tries this increment: g_t + ds, or 0 for a contact that was not
// active at its start (it starts the increment tangentially unloaded).
double trial_slip(const ContactHistory& history, double slip_increment);

// The basic laws (contact_law.h), one file each, with their own dissipation; they leave
// history.normal_gap to the caller.
ContactTraction evaluate_frictionless(const ContactLawParams& params, double normal_gap,
                                      ContactHistory& history);
ContactTraction evaluate_coulomb(const ContactLawParams& params, double normal_gap,
                                 double slip_increment, ContactHistory& history);
ContactTraction evaluate_cohesive(const ContactLawParams& params, double normal_gap,
                                  double slip_increment, ContactHistory& history);

// The laws whose dissipation is the work of their tractions less the change of the energy
// they store (contact_law.h, "Dissipation of the damage laws"): they set the tractions, the
// history and history.energy, not out.dissipated.
ContactTraction evaluate_two_slope(const ContactLawParams& params, const ContactKinematics& kin,
                                   ContactHistory& history);
ContactTraction evaluate_bonded(const ContactLawParams& params, const ContactKinematics& kin,
                                ContactHistory& history);
ContactTraction evaluate_cohesive_zone(const ContactLawParams& params, const ContactKinematics& kin,
                                       ContactHistory& history);

// A law's residual state after its bond failed: the cohesive law with `residual` coefficients
// (k_n, k_t, mu_c, sigma_c, tau_c), run on `history` (active: the residual bond holds).
// Sets history.energy to what the residual springs hold.
ContactTraction evaluate_residual(const ContactLawParams& residual, double normal_gap,
                                  double slip_increment, ContactHistory& history);

// Adds the viscous tractions of the damping ratio (contact_law.h, "Contact damping") to
// `out`, and their dissipation over the increment; `before` is the history at entry.
void add_viscous_tractions(const ContactLawParams& params, const ContactKinematics& kin,
                           const ContactHistory& before, ContactHistory& history,
                           ContactTraction& out);

}  // namespace sg::contact_law_parts
