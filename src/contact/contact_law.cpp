#include "contact/contact_law.h"

#include <algorithm>
#include <cmath>

#include "contact/contact_law_parts.h"
#include "contact/law_coefficients.h"
#include "core/error.h"

namespace sg {

const char* contact_law_kind_name(ContactLawKind kind) {
  switch (kind) {
    case ContactLawKind::frictionless:
      return "frictionless";
    case ContactLawKind::coulomb:
      return "coulomb";
    case ContactLawKind::cohesive:
      return "cohesive";
    case ContactLawKind::two_slope:
      return "two_slope";
    case ContactLawKind::bonded:
      return "bonded";
    case ContactLawKind::cohesive_zone:
      return "cohesive_zone";
  }
  return "unknown";
}

const char* to_string(ContactLength length) {
  switch (length) {
    case ContactLength::current:
      return "current";
    case ContactLength::initial:
      return "initial";
  }
  return "unknown";
}

namespace {

// The coefficients only some kinds use (law_coefficients.h): one given to another kind is
// refused (a sign that the scenario means another kind), one a kind uses must be within its
// row's bound; then the ranges that involve more than one coefficient or bound.
void validate_kind_coefficients(const ContactLawParams& p, std::string_view context) {
  const char* kind = contact_law_kind_name(p.kind);
  const auto check_coefficient = [&](const char* name, double value, double unused_value, bool used,
                                     bool positive) {
    SG_VERIFY(std::isfinite(value), context << " (" << kind << "): " << name
                                            << " must be a finite number, got " << value);
    SG_VERIFY(used || value == unused_value, context << " (" << kind << "): " << name << " "
                                                     << value << " given, which a " << kind
                                                     << " law does not use");
    SG_VERIFY(value >= 0.0,
              context << " (" << kind << "): " << name << " must be >= 0, got " << value);
    SG_VERIFY(!used || !positive || value > 0.0,
              context << " (" << kind << "): " << name << " must be > 0, got " << value);
  };
  check_coefficient("damping_ratio", p.damping_ratio, 0.0, true, false);
  for (const LawCoefficient& c : law_coefficients())
    check_coefficient(c.key, p.*c.member, c.unused_value, is_used_by(c, p.kind),
                      c.bound == LawCoefficient::Bound::positive);
  const auto require = [&](bool ok, const char* name, double value, const char* expected) {
    SG_VERIFY(ok, context << " (" << kind << "): " << name << " " << expected << ", got " << value);
  };
  require(p.damping_ratio < 1.0, "damping_ratio", p.damping_ratio, "must be < 1 (underdamped)");
  require(p.unloading_ratio <= 1.0, "unloading_ratio", p.unloading_ratio, "must be in (0, 1]");
  if (p.kind != ContactLawKind::cohesive_zone) return;
  require(p.friction == 0.0, "friction", p.friction, "is not used by a cohesive_zone law (0)");
  require(p.residual_traction <= p.peak_traction, "residual_traction (P_res, force/length)",
          p.residual_traction, "must be <= peak_traction");
  const double elastic_limit = 0.5 * p.peak_traction / p.normal_stiffness;
  SG_VERIFY(p.critical_opening > elastic_limit,
            context << " (cohesive_zone): critical_opening " << p.critical_opening
                    << " must exceed the elastic limit of a pass, peak_traction / (2"
                       " normal_stiffness) = "
                    << elastic_limit);
}

}  // namespace

void validate(const ContactLawParams& params, std::string_view context) {
  const char* kind = contact_law_kind_name(params.kind);
  const auto check_finite = [&](double value, const char* name) {
    SG_VERIFY(std::isfinite(value), context << " (" << kind << "): " << name
                                            << " must be a finite number, got " << value);
  };
  check_finite(params.normal_stiffness, "normal_stiffness");
  check_finite(params.tangential_stiffness, "tangential_stiffness");
  check_finite(params.friction, "friction");
  check_finite(params.adhesion, "adhesion");
  check_finite(params.shear_strength, "shear_strength");

  SG_VERIFY(params.normal_stiffness > 0.0,
            context << " (" << kind << "): normal_stiffness (penalty k_n, force/length^2) must be"
                    << " > 0, got " << params.normal_stiffness);
  SG_VERIFY(params.friction >= 0.0, context << " (" << kind << "): friction coefficient must be"
                                            << " >= 0, got " << params.friction);
  SG_VERIFY(params.adhesion >= 0.0,
            context << " (" << kind << "): adhesion strength (sigma_c, force/length) must be >= 0,"
                    << " got " << params.adhesion);
  SG_VERIFY(params.shear_strength >= 0.0,
            context << " (" << kind << "): shear strength (tau_c, force/length) must be >= 0, got "
                    << params.shear_strength);

  if (params.kind == ContactLawKind::frictionless) {
    SG_VERIFY(params.friction == 0.0, context << " (frictionless): friction " << params.friction
                                              << " given; use a coulomb law for friction");
  } else {
    SG_VERIFY(params.tangential_stiffness > 0.0,
              context << " (" << kind << "): tangential_stiffness (penalty k_t, force/length^2)"
                      << " must be > 0, got " << params.tangential_stiffness);
  }
  if (params.kind != ContactLawKind::cohesive && params.kind != ContactLawKind::bonded) {
    SG_VERIFY(params.adhesion == 0.0 && params.shear_strength == 0.0,
              context << " (" << kind << "): adhesion " << params.adhesion << " / shear strength "
                      << params.shear_strength << " given; use a cohesive law for them");
  }
  validate_kind_coefficients(params, context);
}

ContactLawParams per_pass_params(const ContactLawParams& params) {
  // docs/method.md §Contact, Two-pass scheme: each pass carries half of each strength, so that
  // a contact of length l resists sigma_c l in total.
  ContactLawParams half = params;
  half.adhesion = 0.5 * params.adhesion;
  half.shear_strength = 0.5 * params.shear_strength;
  half.bond_tensile_strength = 0.5 * params.bond_tensile_strength;
  half.bond_shear_strength = 0.5 * params.bond_shear_strength;
  half.peak_traction = 0.5 * params.peak_traction;
  half.residual_traction = 0.5 * params.residual_traction;
  return half;
}

namespace {

using namespace contact_law_parts;

// Work of the law's tractions over the increment less the change of its stored energy (the
// header's "Dissipation of the damage laws").
double work_less_stored_change(const ContactHistory& before, const ContactHistory& after,
                               const ContactKinematics& kin, const ContactTraction& out) {
  if (!before.active) return 0.0;  // no previous state: the onset books nothing
  const double normal_work =
      -0.5 * (before.normal_traction + out.normal) * (kin.normal_gap - before.normal_gap);
  const double tangential_work =
      -0.5 * (before.tangential_traction + out.tangential) * kin.slip_increment;
  return normal_work + tangential_work - (after.energy - before.energy);
}

// A damage law's increment `out` booked: its dissipation from the work and the stored energy,
// its tractions kept for the next increment's work.
ContactTraction book_damage_law(const ContactHistory& before, const ContactKinematics& kin,
                                ContactHistory& history, ContactTraction out) {
  out.dissipated = work_less_stored_change(before, history, kin, out);
  history.normal_traction = out.normal;
  history.tangential_traction = out.tangential;
  return out;
}

// The law of `params.kind` over the increment, without damping. history.normal_gap is still
// the previous gap while the law runs (energy released).
ContactTraction evaluate_law(const ContactLawParams& params, const ContactKinematics& kin,
                             const ContactHistory& before, ContactHistory& history) {
  switch (params.kind) {
    case ContactLawKind::frictionless:
      return evaluate_frictionless(params, kin.normal_gap, history);
    case ContactLawKind::coulomb:
      return evaluate_coulomb(params, kin.normal_gap, kin.slip_increment, history);
    case ContactLawKind::cohesive:
      return evaluate_cohesive(params, kin.normal_gap, kin.slip_increment, history);
    case ContactLawKind::two_slope:
      return book_damage_law(before, kin, history, evaluate_two_slope(params, kin, history));
    case ContactLawKind::bonded:
      return book_damage_law(before, kin, history, evaluate_bonded(params, kin, history));
    case ContactLawKind::cohesive_zone:
      return book_damage_law(before, kin, history, evaluate_cohesive_zone(params, kin, history));
  }
  return ContactTraction{};
}

// 1/2 k g^2, the energy of a linear spring of stiffness k stretched by g.
double spring_energy(double stiffness, double stretch) {
  return 0.5 * stiffness * stretch * stretch;
}

}  // namespace

ContactTraction evaluate_contact_law(const ContactLawParams& params, const ContactKinematics& kin,
                                     ContactHistory& history) {
  const ContactHistory before = history;
  ContactTraction out = evaluate_law(params, kin, before, history);
  if (params.damping_ratio > 0.0) add_viscous_tractions(params, kin, before, history, out);
  history.normal_gap = kin.normal_gap;
  return out;
}

ContactTraction evaluate_contact_law(const ContactLawParams& params, double normal_gap,
                                     double slip_increment, ContactHistory& history) {
  ContactKinematics kin;
  kin.normal_gap = normal_gap;
  kin.slip_increment = slip_increment;
  return evaluate_contact_law(params, kin, history);
}

double stored_energy(const ContactLawParams& params, double normal_gap,
                     const ContactHistory& history) {
  const double k_n = params.normal_stiffness, k_t = params.tangential_stiffness;
  switch (params.kind) {
    case ContactLawKind::frictionless:
      return history.active ? spring_energy(k_n, normal_gap) : 0.0;
    case ContactLawKind::coulomb:
      return history.active
                 ? spring_energy(k_n, normal_gap) + spring_energy(k_t, history.stored_slip)
                 : 0.0;
    case ContactLawKind::cohesive:
      return history.active
                 ? spring_energy(k_n, normal_gap) + spring_energy(k_t, history.stored_slip)
                 : 0.0;
    case ContactLawKind::two_slope:
      return history.energy;
    case ContactLawKind::bonded:
      return history.energy;
    case ContactLawKind::cohesive_zone:
      return history.energy;
  }
  return 0.0;
}

double tensile_reach(const ContactLawParams& params) {
  switch (params.kind) {
    case ContactLawKind::frictionless:
      return 0.0;
    case ContactLawKind::coulomb:
      return 0.0;  // no tension
    case ContactLawKind::two_slope:
      return 0.0;  // no tension
    case ContactLawKind::cohesive:
      return 0.5 * params.adhesion / params.normal_stiffness;
    case ContactLawKind::bonded:
      return std::max({0.5 * params.bond_tensile_strength / params.bond_normal_stiffness,
                       0.5 * params.adhesion / params.normal_stiffness, params.bond_gap});
    case ContactLawKind::cohesive_zone:
      return std::max(params.critical_opening, params.bond_gap);
  }
  return 0.0;
}

std::vector<double> contact_law_coefficients(const ContactLawParams& p) {
  return {static_cast<double>(p.kind),
          p.normal_stiffness,
          p.tangential_stiffness,
          p.friction,
          p.adhesion,
          p.shear_strength,
          p.damping_ratio,
          static_cast<double>(p.length),
          p.unloading_ratio,
          p.bond_normal_stiffness,
          p.bond_tensile_strength,
          p.bond_shear_strength,
          p.bond_friction,
          p.bond_gap,
          p.peak_traction,
          p.critical_opening,
          p.residual_traction,
          p.mixed_mode_ratio};
}

}  // namespace sg
