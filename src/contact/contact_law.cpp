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

namespace {

// The coefficients only some kinds use (law_coefficients.h): one given to another kind is
// refused (a sign that the scenario means another kind).
void validate_kind_coefficients(const ContactLawParams& p, std::string_view context) {
  using K = ContactLawKind;
  const char* kind = contact_law_kind_name(p.kind);
  const bool bonded = p.kind == K::bonded, zone = p.kind == K::cohesive_zone;
  const auto check_coefficient = [&](const char* name, double value, double unused_value,
                                     bool used) {
    SG_VERIFY(std::isfinite(value), context << " (" << kind << "): " << name
                                            << " must be a finite number, got " << value);
    SG_VERIFY(used || value == unused_value, context << " (" << kind << "): " << name << " "
                                                     << value << " given, which a " << kind
                                                     << " law does not use");
    SG_VERIFY(value >= 0.0,
              context << " (" << kind << "): " << name << " must be >= 0, got " << value);
  };
  check_coefficient("damping_ratio", p.damping_ratio, 0.0, true);
  for (const LawCoefficient& c : law_coefficients())
    check_coefficient(c.key, p.*c.member, c.unused_value, is_used_by(c, p.kind));
  const auto require = [&](bool ok, const char* name, double value, const char* expected) {
    SG_VERIFY(ok, context << " (" << kind << "): " << name << " " << expected << ", got " << value);
  };
  require(p.damping_ratio < 1.0, "damping_ratio", p.damping_ratio, "must be < 1 (underdamped)");
  require(p.unloading_ratio > 0.0 && p.unloading_ratio <= 1.0, "unloading_ratio", p.unloading_ratio,
          "must be in (0, 1]");
  if (bonded)
    require(p.bond_normal_stiffness > 0.0, "bond_normal_stiffness (k_b, force/length^2)",
            p.bond_normal_stiffness, "must be > 0");
  if (!zone) return;
  require(p.friction == 0.0, "friction", p.friction, "is not used by a cohesive_zone law (0)");
  require(p.peak_traction > 0.0, "peak_traction (P_lim, force/length)", p.peak_traction,
          "must be > 0");
  require(p.residual_traction <= p.peak_traction, "residual_traction (P_res, force/length)",
          p.residual_traction, "must be <= peak_traction");
  require(p.mixed_mode_ratio > 0.0, "mixed_mode_ratio", p.mixed_mode_ratio, "must be > 0");
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

namespace contact_law_parts {

// Sub-model: elastic stick / plastic slip of the tangential spring under `threshold`
// (return mapping, see the header). Writes p_t, the slip flag and the dissipation.
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

namespace {

ContactTraction open_contact(double released_energy, ContactHistory& history) {
  history.stored_slip = 0.0;
  history.active = false;
  ContactTraction out;
  out.dissipated = released_energy;
  return out;
}

}  // namespace

ContactTraction evaluate_basic_law(const ContactLawParams& params, double normal_gap,
                                   double slip_increment, ContactHistory& history) {
  const double k_n = params.normal_stiffness;
  const double k_t = params.tangential_stiffness;
  // A contact not active at the start of the increment starts it unloaded tangentially.
  const double trial_slip = history.active ? history.stored_slip + slip_increment : 0.0;

  switch (params.kind) {
    case ContactLawKind::frictionless: {
      history.stored_slip = 0.0;
      history.active = normal_gap < 0.0;
      ContactTraction out;
      if (history.active) out.normal = -k_n * normal_gap;
      return out;
    }

    case ContactLawKind::coulomb: {
      if (normal_gap >= 0.0) {
        // No tension: the surfaces separate and the tangential spring releases its energy.
        const double released = history.active ? 0.5 * k_t * history.stored_slip * trial_slip : 0.0;
        return open_contact(released, history);
      }
      history.active = true;
      ContactTraction out;
      out.normal = -k_n * normal_gap;  // > 0
      // Coulomb threshold mu_c p_n (docs/method.md §Contact, Laws).
      apply_tangential_threshold(k_t, params.friction * out.normal, trial_slip, history, out);
      return out;
    }

    case ContactLawKind::cohesive: {
      if (!history.active) {
        if (normal_gap > 0.0) return open_contact(0.0, history);  // never touched / broken
        history.active = true;  // touching: the bond (re-)forms with g_t = 0
      }
      const double normal = -k_n * normal_gap;  // p_n = -k_n g_n, tension allowed
      if (normal < -params.adhesion) {
        // Tension beyond sigma_c: the bond breaks (paper 001 §2.2, docs/method.md §Contact).
        const double released = 0.5 * k_n * history.normal_gap * normal_gap +
                                0.5 * k_t * history.stored_slip * trial_slip;
        ContactTraction out = open_contact(released, history);
        out.bond_broken = true;
        return out;
      }
      ContactTraction out;
      out.normal = normal;
      // Threshold tau_c + mu_c max(p_n, 0) (docs/method.md §Contact; paper 003 §2.1: separate
      // sigma and tau).
      const double threshold = params.shear_strength + params.friction * std::max(normal, 0.0);
      apply_tangential_threshold(k_t, threshold, trial_slip, history, out);
      return out;
    }
    case ContactLawKind::two_slope:
    case ContactLawKind::bonded:
    case ContactLawKind::cohesive_zone:
      break;  // not basic laws (evaluate_contact_law dispatches them)
  }
  return ContactTraction{};
}

}  // namespace contact_law_parts

namespace {

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

}  // namespace

ContactTraction evaluate_contact_law(const ContactLawParams& params, const ContactKinematics& kin,
                                     ContactHistory& history) {
  using namespace contact_law_parts;
  const ContactHistory before = history;
  ContactTraction out;
  // history.normal_gap is still the previous gap while the law runs (energy released).
  switch (params.kind) {
    case ContactLawKind::frictionless:
    case ContactLawKind::coulomb:
    case ContactLawKind::cohesive:
      out = evaluate_basic_law(params, kin.normal_gap, kin.slip_increment, history);
      break;
    case ContactLawKind::two_slope:
    case ContactLawKind::bonded:
    case ContactLawKind::cohesive_zone:
      out = params.kind == ContactLawKind::two_slope ? evaluate_two_slope(params, kin, history)
            : params.kind == ContactLawKind::bonded  ? evaluate_bonded(params, kin, history)
                                                     : evaluate_cohesive_zone(params, kin, history);
      out.dissipated = work_less_stored_change(before, history, kin, out);
      history.normal_traction = out.normal;
      history.tangential_traction = out.tangential;
      break;
  }
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
  if (params.kind == ContactLawKind::two_slope || params.kind == ContactLawKind::bonded ||
      params.kind == ContactLawKind::cohesive_zone)
    return history.energy;
  if (!history.active) return 0.0;
  const double normal_part = 0.5 * params.normal_stiffness * normal_gap * normal_gap;
  const double tangential_part =
      0.5 * params.tangential_stiffness * history.stored_slip * history.stored_slip;
  switch (params.kind) {
    case ContactLawKind::frictionless:
      return normal_part;
    case ContactLawKind::coulomb:
    case ContactLawKind::cohesive:
      return normal_part + tangential_part;
    case ContactLawKind::two_slope:
    case ContactLawKind::bonded:
    case ContactLawKind::cohesive_zone:
      return history.energy;
  }
  return 0.0;
}

double tensile_reach(const ContactLawParams& params) {
  switch (params.kind) {
    case ContactLawKind::frictionless:
    case ContactLawKind::coulomb:
    case ContactLawKind::two_slope:
      return 0.0;
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
