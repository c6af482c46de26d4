// The bonded law (contact_law.h): an intact elastic bond with tensile and shear strengths,
// then the cohesive law with residual coefficients; the reference code's BondedMohrCoulomb
// (its residual is stateless Mohr-Coulomb; ours is the cohesive law, whose residual bond
// re-forms only where the surfaces touch).
#include <algorithm>
#include <cmath>

#include "contact/contact_law_parts.h"

namespace sg::contact_law_parts {

namespace {

ContactLawParams residual_law(const ContactLawParams& params) {
  ContactLawParams r;
  r.kind = ContactLawKind::cohesive;
  r.normal_stiffness = params.normal_stiffness;
  r.tangential_stiffness = params.tangential_stiffness;
  r.friction = params.friction;
  r.adhesion = params.adhesion;
  r.shear_strength = params.shear_strength;
  return r;
}

// A bond where the surfaces are within bond_gap at the first evaluation.
void form_initial_bond(const ContactLawParams& params, const ContactKinematics& kin,
                       ContactHistory& history) {
  if (!kin.first_evaluation || !(kin.normal_gap < params.bond_gap)) return;
  history = ContactHistory{};
  history.active = true;
  history.intact = true;
  history.normal_gap = kin.normal_gap;
}

}  // namespace

ContactTraction evaluate_residual(const ContactLawParams& residual, double normal_gap,
                                  double slip_increment, ContactHistory& history) {
  ContactTraction out = evaluate_cohesive(residual, normal_gap, slip_increment, history);
  history.intact = false;
  history.energy = stored_energy(residual, normal_gap, history);
  return out;
}

ContactTraction evaluate_bonded(const ContactLawParams& params, const ContactKinematics& kin,
                                ContactHistory& history) {
  form_initial_bond(params, kin, history);
  const ContactLawParams residual = residual_law(params);
  if (!history.intact)
    return evaluate_residual(residual, kin.normal_gap, kin.slip_increment, history);

  const double gap = kin.normal_gap;
  const double k_normal = gap < 0.0 ? params.normal_stiffness : params.bond_normal_stiffness;
  const double normal = -k_normal * gap;
  const double slip = history.stored_slip + kin.slip_increment;  // elastic: no slip while intact
  const double tangential = -params.tangential_stiffness * slip;
  const bool tensile_failure = normal < -params.bond_tensile_strength;
  const bool shear_failure =
      std::abs(tangential) >
      params.bond_shear_strength + params.bond_friction * std::max(normal, 0.0);
  if (tensile_failure || shear_failure) {
    // The bond fails for good; the residual law takes the increment over from the bond's
    // state (its residual bond holds at first: it lets go too if the tension exceeds its own
    // adhesion, and slides at its own threshold).
    history.intact = false;
    ContactTraction out = evaluate_residual(residual, gap, kin.slip_increment, history);
    out.bond_broken = true;
    return out;
  }
  history.stored_slip = slip;
  history.energy = 0.5 * k_normal * gap * gap + 0.5 * params.tangential_stiffness * slip * slip;
  ContactTraction out;
  out.normal = normal;
  out.tangential = tangential;
  return out;
}

}  // namespace sg::contact_law_parts
