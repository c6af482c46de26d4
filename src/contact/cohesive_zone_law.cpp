// The linear-softening cohesive zone (contact_law.h), the reference code's CZMlinear.
//
//   traction                  envelope: k_n g up to (g_e, P_lim), then linear down to
//     P_lim |    /\                     (g_lim, P_res); D = (g_max - g_e) / (g_lim - g_e)
//           |   /  \                    from the largest equivalent opening g_max reached
//           |  /  . \                   (unloading and reloading follow the secant of
//     P_res |  / .    \___              slope ((1 - D) P_lim + D P_res) / g_max)
//           | /.          |
//           +--------------+--> g
//              g_e  g_max  g_lim
//
// The energy dissipated up to g_max is the area between the envelope and the secant; a
// complete opening dissipates the whole area under the envelope (the residual traction lets
// go at g_lim, where the failed zone's cohesive law cannot hold it), G_c =
// 1/2 P_lim g_e + 1/2 (P_lim + P_res)(g_lim - g_e).
#include <algorithm>
#include <cmath>

#include "contact/contact_law_parts.h"

namespace sg::contact_law_parts {

namespace {

// The failed zone: the cohesive law with k_n both ways and strengths P_res, r_m P_res.
ContactLawParams failed_zone_law(const ContactLawParams& params) {
  ContactLawParams r;
  r.kind = ContactLawKind::cohesive;
  r.normal_stiffness = params.normal_stiffness;
  r.tangential_stiffness = params.normal_stiffness;
  r.adhesion = params.residual_traction;
  r.shear_strength = params.mixed_mode_ratio * params.residual_traction;
  return r;
}

}  // namespace

ContactTraction evaluate_cohesive_zone(const ContactLawParams& params, const ContactKinematics& kin,
                                       ContactHistory& history) {
  const double gap = kin.normal_gap;
  if (kin.first_evaluation && gap < params.bond_gap) {
    history = ContactHistory{};
    history.active = true;
    history.intact = true;
    history.normal_gap = gap;
  }
  if (!history.intact)
    return evaluate_residual(failed_zone_law(params), gap, kin.slip_increment, history);

  const double k = params.normal_stiffness;
  const double elastic_limit = params.peak_traction / k;  // g_e
  const double softening_length = params.critical_opening - elastic_limit;
  const double slip = history.stored_slip + kin.slip_increment;  // total: no slip in the zone
  double damage = history.damage;
  double max_opening = (1.0 - damage) * elastic_limit + damage * params.critical_opening;
  const double opening = std::max(gap, std::abs(slip) / params.mixed_mode_ratio);
  if (opening > max_opening) {
    max_opening = opening;
    damage = (max_opening - elastic_limit) / softening_length;
  }
  if (damage >= 1.0) {
    // Failed: the residual traction cannot hold beyond g_lim; the failed zone's law starts
    // unbonded and re-forms where the surfaces touch again.
    history.intact = false;
    history.active = false;
    history.stored_slip = 0.0;
    history.damage = 0.0;
    ContactTraction out =
        evaluate_residual(failed_zone_law(params), gap, kin.slip_increment, history);
    out.bond_broken = true;
    return out;
  }
  const double secant =
      ((1.0 - damage) * params.peak_traction + damage * params.residual_traction) / max_opening;
  const double k_normal = gap < 0.0 ? k : secant;
  history.stored_slip = slip;
  history.damage = damage;
  history.energy = 0.5 * k_normal * gap * gap + 0.5 * secant * slip * slip;
  ContactTraction out;
  out.normal = -k_normal * gap;
  out.tangential = -secant * slip;
  return out;
}

}  // namespace sg::contact_law_parts
