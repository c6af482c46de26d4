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
// Thresholds are inclusive: exactly p_n == -sigma_c holds, exactly |p_t| == threshold sticks.
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
// must account for), and the friction threshold scales with each pass's own p_n.
#include <string_view>
#include <type_traits>

namespace sg {

enum class ContactLawKind { frictionless, coulomb, cohesive };

// The name used in scenario files and messages ("frictionless", "coulomb", "cohesive").
const char* contact_law_kind_name(ContactLawKind kind);

// Law coefficients (immutable, from the scenario). Strengths are for the whole physical
// contact; see per_pass_params for the two-pass scheme.
struct ContactLawParams {
  ContactLawKind kind = ContactLawKind::frictionless;
  double normal_stiffness = 0.0;      // k_n   [force / length^2]
  double tangential_stiffness = 0.0;  // k_t   [force / length^2] (coulomb, cohesive)
  double friction = 0.0;              // mu_c  [-]                (coulomb, cohesive)
  double adhesion = 0.0;              // sigma_c [force / length] (cohesive)
  double shear_strength = 0.0;        // tau_c   [force / length] (cohesive)
};

// Throws sg::Error naming `context` (e.g. "contact law for materials 'soft' and 'wall'")
// if a coefficient is not finite, a stiffness the law uses is not > 0, mu_c or a strength is
// negative, or a coefficient is given that the kind does not use (adhesion on a coulomb law,
// friction on a frictionless one): a sign that the scenario means another kind.
void validate(const ContactLawParams& params, std::string_view context);

// The coefficients one pass of the two-pass node-to-segment scheme uses: adhesion and
// shear strength halved, stiffnesses and friction unchanged (see the header comment).
ContactLawParams per_pass_params(const ContactLawParams& params);

// Per-contact memory, owned by the law (24 bytes, trivially copyable: checkpointed as is).
// Key it by (slave node, master body), not by segment: the closest segment changes as the
// node slides along the master contour, the contact does not.
struct ContactHistory {
  double stored_slip = 0.0;  // g_t, the elastic tangential slip [length]
  bool active = false;       // cohesive: the bond holds; coulomb/frictionless: surfaces touch
  double normal_gap = 0.0;   // g_n at the previous evaluation (for the energy released)
};
static_assert(std::is_trivially_copyable_v<ContactHistory>);
static_assert(sizeof(ContactHistory) == 24);

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
// the kinetic energy 1/2 v_n-1/2 . v_n+1/2 close the balance, see explicit_solver.h); with
// f_now = 0 after the release, 1/2 k g_prev g_trial is exactly the energy the discrete
// system gives up, and it tends to the continuous 1/2 k g_c^2 as the step goes to zero.
// With 1/2 k g_trial^2 instead, a bond loaded at v dt >> g_c per step (the papers' cohesion
// with a stiff penalty) left 9% of the external work unaccounted in the shear cell.
ContactTraction evaluate_contact_law(const ContactLawParams& params, double normal_gap,
                                     double slip_increment, ContactHistory& history);

// Elastic energy per unit length the contact holds after an evaluation at `normal_gap`
// (1/2 k_n g_n^2 while the normal spring is loaded, + 1/2 k_t g_t^2): the contact part of
// the energy budget.
double stored_energy(const ContactLawParams& params, double normal_gap,
                     const ContactHistory& history);

}  // namespace sg
