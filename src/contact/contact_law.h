#pragma once
// Contact laws: parameters, per-contact history and a pure evaluation (docs/architecture.md
// §Conventions 5: `(kinematics, params, history) -> {traction, new history}`, composed from a
// normal sub-model and a tangential sub-model, the law owning its history).
//
// Sign conventions (docs/method.md §Contact; the cohesive law of papers 001 §2.2 / 003 §2.1)
// ----------------------------------------------------------------------------------------
// One contact = one slave node against the contour of a master body (node_segment.h).
//
//                       slave node x
//                        o   ^ n  (unit outward normal of the master contour)
//              g_n > 0   :   |
//   ---------------------+---+-------------->  t = perp(n)  (tangent, direction of travel
//   master contour      p = projection            along the master contour; its material is
//   ///////////////// master material ////        on the left of t, i.e. opposite to n)
//
//   g_n = (x - p) . n   normal gap, positive = open, negative = penetration   [length]
//   ds                  slip increment of the node relative to the master along t [length]
//   g_t                 stored elastic tangential slip (history), g_t <- g_t + ds
//   p_n = -k_n g_n      normal traction on the node along n: positive = compression  [F/L]
//   p_t = -k_t g_t      tangential traction on the node along t (opposes the slip)     [F/L]
//
// Tractions are per unit contact length. The force on the slave node is
//     f_node = l_node (p_n n + p_t t),
// l_node its tributary length (node_segment.h), and the opposite force goes to the master
// segment's end points with weights (1 - s, s) at the projection parameter s.
// k_n, k_t are penalty stiffnesses per unit contact length: pressure per unit gap, [F/L^2].
//
// Laws (ContactLawKind):
//   frictionless  p_n = k_n max(-g_n, 0), p_t = 0. Nothing dissipated, ever.
//   coulomb       no tension: open (p = 0) when g_n >= 0; closed: tangential threshold
//                 mu_c p_n (elastic stick up to it, slip at it).
//   cohesive      a bond holds the surfaces: p_n = -k_n g_n in compression and in tension,
//                 so the contact stays active for small positive gaps (up to sigma_c / k_n);
//                 if p_n < -sigma_c the bond breaks (p_n = p_t = 0, g_t reset); otherwise
//                 the tangential threshold is tau_c + mu_c max(p_n, 0) (docs/method.md
//                 §Contact, Laws: Coulomb friction added to the shear strength; mu_c = 0
//                 gives the papers' pure cohesive law).
//   two_slope     coulomb with a normal stiffness k_n while the gap closes (or holds) and
//                 r k_n while it opens (unloading_ratio r in (0, 1]): a linear spring that
//                 returns the fraction r of the energy it stored, restitution e = sqrt(r)
//                 (the reference code MELODY 2D's TwoSlopesMohrCoulomb).
//   bonded        an interface that starts intact where the surfaces are within bond_gap at
//                 the first evaluation: p_n = -k_n g_n in compression, -k_b g_n in tension,
//                 p_t = -k_t g_t (elastic, no slip); it fails for good when p_n < -T_b
//                 (bond_tensile_strength) or |p_t| > c_b + mu_b max(p_n, 0) (bond shear
//                 strength and friction), then behaves as the cohesive law with the residual
//                 coefficients (friction, adhesion, shear_strength): frictional-cohesive, a
//                 residual bond re-forming on touch (MELODY 2D's BondedMohrCoulomb).
//   cohesive_zone a linear-softening cohesive zone, intact where the surfaces are within
//                 bond_gap at the first evaluation. With g_e = P_lim / k_n the elastic limit,
//                 the traction envelope rises as k_n g up to the peak traction P_lim at g_e,
//                 then falls linearly to the residual traction P_res at the critical opening
//                 g_lim; damage D = (g_max - g_e) / (g_lim - g_e) from the largest equivalent
//                 opening reached, g_max = max over the history of max(g_n, |g_t| / r_m)
//                 (mixed_mode_ratio r_m: the shear envelope is the normal one scaled by r_m in
//                 slip and in traction). Below g_max the contact unloads along the secant
//                 k_s = ((1 - D) P_lim + D P_res) / g_max, in tension and in shear (g_t is the
//                 total tangential displacement, no slip); compression is k_n g_n. At D = 1 the
//                 zone has failed: the cohesive law with k_n, sigma_c = P_res,
//                 tau_c = r_m P_res takes over (MELODY 2D's CZMlinear). The energy dissipated
//                 per unit length by a complete opening is the area under the envelope,
//                 G_c = 1/2 P_lim g_e + 1/2 (P_lim + P_res)(g_lim - g_e) (1/2 P_lim g_lim for
//                 P_res = 0), whatever the path of unloading and reloading before it.
// Thresholds are inclusive: exactly p_n == -sigma_c holds, exactly |p_t| == threshold sticks.
//
// Contact damping (any law, damping_ratio zeta >= 0, the reference code's DampedMohrCoulomb
// made general): viscous tractions added to the law's while its springs are loaded,
//   p_n += -c_n v_n,  c_n = 2 zeta sqrt(m_eff k_n / L0)   (while active at both ends of the
//                                                         increment),
//   p_t += -c_t v_t,  c_t = 2 zeta sqrt(m_eff k_t / L0)   (while the contact also sticks: a
//                                                         sliding one stays at its threshold),
// with v_n = (g_n - g_n,prev) / dt, v_t = ds / dt the rates over the increment, m_eff =
// m_s m_m / (m_s + m_m) from the masses of the two bodies (deformable ones included, unlike
// the reference code, where they have no mass; a rigid body moved at imposed velocity counts
// as infinitely heavy) and L0 the slave point's initial tributary length. A body of mass m_eff
// on one contact point of length L0 is then an oscillator of stiffness k_n L0 and damping
// ratio zeta: restitution e = exp(-zeta pi / sqrt(1 - zeta^2)) (the viscous traction may pull
// at the end of an impact, as in the linear spring-dashpot model, so that this holds). The
// viscous tractions do not enter the friction threshold. Their dissipation is the trapezoidal
// work -1/2 (p_v,prev + p_v) (g_n - g_n,prev) - 1/2 (p_t,v,prev + p_t,v) ds (see below).
//
// Dissipation of the damage laws (two_slope, bonded, cohesive_zone): the trapezoidal work of
// the law's tractions over the increment less the change of the energy E the law stores,
//   dissipated = -1/2 (p_n,prev + p_n) (g_n - g_n,prev) - 1/2 (p_t,prev + p_t) ds
//                - (E - E_prev),
// which is what the explicit scheme takes out of the bodies (see evaluate_contact_law): the
// ledger stays closed through a bond failure, a branch switch or a softening step. (The
// first increment of a contact that was not active has no previous state and books none, as
// for the basic laws.)
//
// Length: the force on a node is traction x length, the current tributary length l_node
// (length = "current", the reference code's "Evolutive") or the initial one L0
// ("initial", its "Fixed").
//
// Tangential return mapping (shared by coulomb and cohesive), threshold T:
//   g_trial = g_t + ds;  if k_t |g_trial| <= T: stick, g_t = g_trial;
//   else slip: p_t = -sign(g_trial) T, g_t = -p_t / k_t, plastic slip = |g_trial| - T / k_t,
//   dissipated = T * plastic slip (exact for a constant threshold; first order in the change
//   of T over the increment when p_n varies).
//
// Opening and bond breaking release the elastic energy the contact holds in the current
// configuration, which is counted as dissipated:
//   broken bond:      1/2 k_n g_n^2 + 1/2 k_t g_trial^2
//   coulomb opening:  1/2 k_t g_trial^2   (the normal spring holds nothing at g_n >= 0)
// so that, over any path, work done on the contact = change of stored energy + dissipated
// (stored_energy() below gives the stored part).
//
// Re-forming (a decision, documented here): a broken cohesive bond re-forms when the
// surfaces touch again, g_n <= 0, with g_t = 0. A contact that was not active at the start
// of an increment (new, open or broken) starts it tangentially unloaded: the slip increment
// of the step in which it closes is not stored. New histories start inactive, so a bond only
// forms where surfaces have touched at least once.
//
// Two-pass scheme: each physical contact is evaluated twice (nodes of A on segments of B
// and nodes of B on segments of A), so each pass carries half of each strength
// (per_pass_params): a flat contact of length l then resists sigma_c l in opening and
// tau_c l in sliding in total. Stiffnesses and mu_c are not halved: the effective normal
// stiffness of a two-sided flat contact is 2 k_n per unit length (what the stable time step
// must account for), and the friction threshold scales with each pass's own p_n. The new
// laws' strengths are halved likewise (T_b, c_b, P_lim, P_res): a cohesive zone's elastic limit
// per pass is P_lim / (2 k_n) and its fracture energy per pass G_c / 2; openings (bond_gap,
// critical_opening) are not halved.
#include <string_view>
#include <type_traits>
#include <vector>

namespace sg {

enum class ContactLawKind { frictionless, coulomb, cohesive, two_slope, bonded, cohesive_zone };

// The length a contact's tractions are multiplied by (header comment).
enum class ContactLength { current, initial };

// The name used in scenario files and messages ("frictionless", "coulomb", "cohesive",
// "two_slope", "bonded", "cohesive_zone").
const char* contact_law_kind_name(ContactLawKind kind);
inline const char* to_string(ContactLawKind kind) {
  return contact_law_kind_name(kind);
}
// Every law, for readers that parse a name by to_string (scenario/toml_reader.h, named_value).
inline constexpr ContactLawKind kContactLawKinds[] = {
    ContactLawKind::frictionless, ContactLawKind::coulomb, ContactLawKind::cohesive,
    ContactLawKind::two_slope,    ContactLawKind::bonded,  ContactLawKind::cohesive_zone};

// "current" or "initial", as scenario files name them.
const char* to_string(ContactLength length);
inline constexpr ContactLength kContactLengths[] = {ContactLength::current, ContactLength::initial};

// Law coefficients (immutable, from the scenario). Strengths are for the whole physical
// contact; see per_pass_params for the two-pass scheme.
struct ContactLawParams {
  ContactLawKind kind = ContactLawKind::frictionless;
  double normal_stiffness = 0.0;      // k_n   [force / length^2]
  double tangential_stiffness = 0.0;  // k_t   [force / length^2] (coulomb, cohesive)
  double friction = 0.0;              // mu_c  [-]                (coulomb, cohesive)
  double adhesion = 0.0;              // sigma_c [force / length] (cohesive)
  double shear_strength = 0.0;        // tau_c   [force / length] (cohesive)
  // (bonded: friction, adhesion and shear_strength are the residual law's mu_f, T_f, c_f.)
  double damping_ratio = 0.0;  // zeta [-] (any law)
  ContactLength length = ContactLength::current;
  double unloading_ratio = 1.0;        // r, unloading / loading stiffness (two_slope)
  double bond_normal_stiffness = 0.0;  // k_b [force / length^2], in tension (bonded)
  double bond_tensile_strength = 0.0;  // T_b [force / length] (bonded)
  double bond_shear_strength = 0.0;    // c_b [force / length] (bonded)
  double bond_friction = 0.0;          // mu_b [-] (bonded)
  double bond_gap = 0.0;               // [length] bonds form below it at start (bonded, zone)
  double peak_traction = 0.0;          // P_lim [force / length] (cohesive_zone)
  double critical_opening = 0.0;       // g_lim [length] (cohesive_zone)
  double residual_traction = 0.0;      // P_res [force / length] (cohesive_zone)
  double mixed_mode_ratio = 1.0;       // r_m [-] (cohesive_zone)
};

// The largest opening at which a law can still carry load or form a bond: what the contact
// cutoff must cover (sigma_c / (2 k_n) for cohesive, T_b / (2 k_b) for bonded, g_lim for
// cohesive_zone, and bond_gap).
double tensile_reach(const ContactLawParams& params);

// Every coefficient of a law as numbers (kind first), for fingerprints of the run settings.
std::vector<double> contact_law_coefficients(const ContactLawParams& params);

// Throws sg::Error naming `context` (e.g. "contact law for materials 'soft' and 'wall'")
// if a coefficient is not finite, a stiffness the law uses is not > 0, mu_c or a strength is
// negative, a ratio is out of its range (damping_ratio in [0, 1), unloading_ratio in (0, 1],
// mixed_mode_ratio > 0), a cohesive zone softens before its elastic limit (g_lim <=
// P_lim / (2 k_n)) or has P_res > P_lim, or a coefficient is given that the kind does not
// use (adhesion on a coulomb law, friction on a frictionless one): a sign that the scenario
// means another kind.
void validate(const ContactLawParams& params, std::string_view context);

// The coefficients one pass of the two-pass node-to-segment scheme uses: adhesion and
// shear strength halved, stiffnesses and friction unchanged (see the header comment).
ContactLawParams per_pass_params(const ContactLawParams& params);

// Per-contact memory, owned by the law (72 bytes, trivially copyable: checkpointed field by
// field). Key it by (slave node, master body), not by segment: the closest segment changes as
// the node slides along the master contour, the contact does not.
struct ContactHistory {
  double stored_slip = 0.0;  // g_t, the elastic tangential slip [length] (cohesive_zone: total)
  double normal_gap = 0.0;   // g_n at the previous evaluation (energy released, rates)
  // The previous evaluation's law tractions and stored energy per unit length (dissipation of
  // the damage laws), and viscous tractions (contact damping).
  double normal_traction = 0.0, tangential_traction = 0.0, energy = 0.0;
  double viscous_normal = 0.0, viscous_tangential = 0.0;
  double damage = 0.0;     // cohesive_zone: D in [0, 1) while intact
  bool active = false;     // cohesive: the bond holds; coulomb/frictionless: surfaces touch
  bool intact = false;     // bonded, cohesive_zone: the initial bond holds (else: residual)
  bool unloading = false;  // two_slope: on the unloading branch
};
static_assert(std::is_trivially_copyable_v<ContactHistory>);
static_assert(sizeof(ContactHistory) == 72);

// What a law needs to know about one contact at one evaluation besides its history.
struct ContactKinematics {
  double normal_gap = 0.0;        // g_n now [length]
  double slip_increment = 0.0;    // ds since the previous evaluation [length]
  double interval = 0.0;          // time since the previous evaluation (0: no damping)
  double effective_mass = 0.0;    // m_eff of the two bodies (0: no damping)
  double initial_length = 0.0;    // L0, initial tributary length of the slave point
  bool first_evaluation = false;  // the run's first: bonded / cohesive_zone bonds form here
};

struct ContactTraction {
  double normal = 0.0;       // p_n [force / length], positive = compression
  double tangential = 0.0;   // p_t [force / length], along the master tangent t
  double dissipated = 0.0;   // energy dissipated during this increment [energy / length]
  bool slipping = false;     // the tangential threshold was reached in this increment
  bool bond_broken = false;  // a cohesive bond broke in this increment (an event to count)
};

// The law at the end of an increment: `normal_gap` g_n in the current configuration,
// `slip_increment` ds since the previous evaluation; updates `history`. Pure, no
// allocation: called once per contact and step.
//
// Energy released when a spring lets go (a bond breaks, surfaces separate with a loaded
// tangential spring): the time-centred energy 1/2 k g_prev g_trial of the spring between the
// previous evaluation (where it still carried -k g_prev) and the trial state of this one,
// not 1/2 k g_trial^2. The explicit scheme does the trapezoidal work
// -1/2 (f_prev + f_now) (g_trial - g_prev) over the increment (the same pairing that makes
// the kinetic energy 1/2 v_n-1/2 . v_n+1/2 close the balance, see stepper.h); with
// f_now = 0 after the release, 1/2 k g_prev g_trial is exactly the energy the discrete
// system gives up, and it tends to the continuous 1/2 k g_c^2 as the step goes to zero.
// With 1/2 k g_trial^2 instead, a bond loaded at v dt >> g_c per step (the papers' cohesion
// with a stiff penalty) left 9% of the external work unaccounted in the shear cell.
ContactTraction evaluate_contact_law(const ContactLawParams& params, const ContactKinematics& kin,
                                     ContactHistory& history);
// The same with only a gap and a slip increment (no damping, no bond formation).
ContactTraction evaluate_contact_law(const ContactLawParams& params, double normal_gap,
                                     double slip_increment, ContactHistory& history);

// Elastic energy per unit length the contact holds after an evaluation at `normal_gap`
// (1/2 k_n g_n^2 while the normal spring is loaded, + 1/2 k_t g_t^2; the damage laws: the
// energy of their current springs, history.energy): the contact part of the energy budget.
double stored_energy(const ContactLawParams& params, double normal_gap,
                     const ContactHistory& history);

}  // namespace sg
