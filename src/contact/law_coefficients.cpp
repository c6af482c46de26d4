#include "contact/law_coefficients.h"

namespace sg {

namespace {

using K = ContactLawKind;
using Bound = LawCoefficient::Bound;
using P = ContactLawParams;

// Units and meanings: ContactLawParams (contact_law.h).
const LawCoefficient kCoefficients[] = {
    {"unloading_ratio", &P::unloading_ratio, {K::two_slope}, 1.0, Bound::positive, false, 1.0},
    {"bond_normal_stiffness",
     &P::bond_normal_stiffness,
     {K::bonded},
     0.0,
     Bound::positive,
     false,
     0.0,
     &P::normal_stiffness},
    {"bond_tensile_strength", &P::bond_tensile_strength, {K::bonded}, 0.0, Bound::non_negative},
    {"bond_shear_strength", &P::bond_shear_strength, {K::bonded}, 0.0, Bound::non_negative},
    {"bond_friction", &P::bond_friction, {K::bonded}, 0.0, Bound::non_negative},
    {"bond_gap", &P::bond_gap, {K::bonded, K::cohesive_zone}, 0.0, Bound::non_negative},
    {"peak_traction", &P::peak_traction, {K::cohesive_zone}, 0.0, Bound::positive, true},
    {"critical_opening", &P::critical_opening, {K::cohesive_zone}, 0.0, Bound::positive, true},
    {"residual_traction", &P::residual_traction, {K::cohesive_zone}, 0.0, Bound::non_negative},
    {"mixed_mode_ratio",
     &P::mixed_mode_ratio,
     {K::cohesive_zone},
     1.0,
     Bound::positive,
     false,
     1.0},
};

}  // namespace

std::span<const LawCoefficient> law_coefficients() {
  return kCoefficients;
}

bool is_used_by(const LawCoefficient& c, ContactLawKind kind) {
  for (const ContactLawKind k : c.kinds)
    if (k == kind) return true;
  return false;
}

std::string names_of_laws_using(const LawCoefficient& c) {
  std::string names;
  std::size_t i = 0;
  for (const ContactLawKind k : c.kinds) {
    if (i > 0) names += i + 1 == c.kinds.size() ? " or " : ", ";
    names += std::string("\"") + contact_law_kind_name(k) + "\"";
    ++i;
  }
  return names;
}

}  // namespace sg
