#include "contact/contact_law.h"

#include <algorithm>
#include <cmath>

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
  }
  return "unknown";
}

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
  if (params.kind != ContactLawKind::cohesive) {
    SG_VERIFY(params.adhesion == 0.0 && params.shear_strength == 0.0,
              context << " (" << kind << "): adhesion " << params.adhesion << " / shear strength "
                      << params.shear_strength << " given; use a cohesive law for them");
  }
}

ContactLawParams per_pass_params(const ContactLawParams& params) {
  // docs/method.md §Contact, Two-pass scheme: each pass carries half of each strength, so that
  // a contact of length l resists sigma_c l in total.
  ContactLawParams half = params;
  half.adhesion = 0.5 * params.adhesion;
  half.shear_strength = 0.5 * params.shear_strength;
  return half;
}

namespace {

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

ContactTraction open_contact(double released_energy, ContactHistory& history) {
  history.stored_slip = 0.0;
  history.active = false;
  ContactTraction out;
  out.dissipated = released_energy;
  return out;
}

}  // namespace

namespace {

ContactTraction evaluate_law_of_kind(const ContactLawParams& params, double normal_gap,
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
  }
  return ContactTraction{};
}

}  // namespace

ContactTraction evaluate_contact_law(const ContactLawParams& params, double normal_gap,
                                     double slip_increment, ContactHistory& history) {
  // history.normal_gap is still the previous gap while the law runs (energy released).
  const ContactTraction out = evaluate_law_of_kind(params, normal_gap, slip_increment, history);
  history.normal_gap = normal_gap;
  return out;
}

double stored_energy(const ContactLawParams& params, double normal_gap,
                     const ContactHistory& history) {
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
  }
  return 0.0;
}

}  // namespace sg
