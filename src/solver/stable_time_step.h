#pragma once
// Stable step of the explicit scheme (docs/method.md §Stable step).
//
// Symplectic Euler on a mode of frequency omega with stiffness-proportional damping
// (xi = alpha omega / 2) is stable iff omega dt <= 2 (sqrt(1 + xi^2) - xi): write the update
// of (x, dt v) as a 2x2 matrix; its characteristic polynomial l^2 - (2 - a - c) l + (1 - c)
// with a = (omega dt)^2, c = 2 xi omega dt is Schur stable iff a + 2c < 4 (Jury test).
// For the papers' parameters the damping, not the wave speed, sets the limit.
//
// omega_max is measured per body by power iteration on M^-1 K (K the tangent stiffness at
// the current state, applied by differencing the force kernel): sharper than the bound
// 2 c_p / h_min, which ignores how far MLS supports reach.
#include <string>
#include <vector>

#include "model/model.h"
#include "solver/integrator_params.h"

namespace sg {

// Largest stable dt for a mode of angular frequency `omega` with damping coefficient alpha.
double critical_time_step(double omega, double alpha);

// omega_max of one deformable body at its current state (power iteration, deterministic
// start vector). Relative accuracy ~1e-3 after the default iterations.
double estimate_max_frequency(const Model& model, BodyId body, int iterations = 60);

// sqrt(lambda_max(M^-1/2 C M^-1/2) / alpha) of one damped deformable body at its current state
// (C the viscous operator, model/internal_forces.h apply_viscous_operator): the frequency of
// the stiffness C / alpha, which is the body's own K (and this its estimate_max_frequency) at
// small strain except for an F-bar material, whose viscous stress keeps the standard
// volumetric stiffness.
double estimate_viscous_frequency(const Model& model, BodyId body, int iterations = 60);

// The 2 c_p / h_min bound of a body (h_min: smallest distance between two of its nodes).
double wave_speed_frequency_bound(const Model& model, BodyId body);

// omega_max of every body (`omega`), as estimate_stable_time_step combines them, and the share
// of omega^2 its contact terms carry (`contact_share`, 0 to 1): a deformable body's
// power-iteration frequency with its contour's contact frequency and its partner's (see
// below), a rigid body's contact frequencies alone (0 without contacts). Deterministic,
// parallel over bodies. An F-bar body (material.h VolumetricFormulation::fbar) whose
// viscosity `integrator` treats explicitly takes the larger of its elastic and viscous
// frequencies (estimate_viscous_frequency): its damping C = alpha K_v is not proportional to
// its elastic K, and with omega = max of the two the mode condition a + 2c < 4 (above) holds
// for both a <= (omega dt)^2 and c <= alpha omega^2 dt.
struct BodyFrequencies {
  std::vector<double> omega;          // per body, 0 for a body with no frequency
  std::vector<double> contact_share;  // per body: (omega_contact^2 + omega_partner^2) / omega^2
};
BodyFrequencies estimate_body_frequencies(const Model& model, double contact_stiffness,
                                          const IntegratorParams& integrator = {});

// The stiffness-proportional damping coefficient alpha that limits a body's explicit step: 0
// for undamped bodies (Model::is_damped) and for bodies whose viscosity `integrator` treats
// implicitly (IMEX).
double body_damping(const Model& model, BodyId body, const IntegratorParams& integrator);

struct StableStep {
  double dt = 0.0;               // safety * min over bodies of the critical step
  BodyId limiting_body = -1;     // the body that sets it
  double omega_max = 0.0;        // its highest frequency
  bool damping_limited = false;  // xi > 1 for that body: the damping sets the limit
  double contact_share = 0.0;    // the share of its omega_max^2 its contacts carry (0 to 1)
};
// "contact penalties carry N% of its omega^2": how much of the step the contact
// penalty sets, for run.log and `softgrain info` (docs/verification.md "The contact penalty").
std::string contact_share_note(const StableStep& stable);

// `contact_stiffness`: the largest contact penalty k (force / length^2), 0 without contacts.
// Contact part of a deformable body's frequency: its whole contour bonded (both passes,
// springs 2 k l_I on each node's MLS row) against an immovable partner, by power iteration on
// the boundary rows (no floor at the per-node value sqrt(2 k l_I / m_I): see contact_frequency
// in the .cpp); a rigid body's from its whole contour. A contact also moves the partner: the
// two sides add in omega^2 (see estimate_body_frequencies), so each body adds the largest
// contact frequency of any other body that is not fully velocity-driven. All terms combine in
// omega^2 (springs in parallel): omega^2 = omega_body^2 + omega_contact^2 + omega_partner^2.
// `integrator`: the step's (an implicit viscosity does not limit the step).
StableStep estimate_stable_time_step(const Model& model, double safety,
                                     double contact_stiffness = 0.0,
                                     const IntegratorParams& integrator = {});

// The same from body frequencies already estimated (estimate_body_frequencies), so that two
// integrators' steps can be compared at the cost of one estimate (solver/default_integrator.h).
StableStep stable_time_step(const Model& model, const BodyFrequencies& body_frequencies,
                            double safety, const IntegratorParams& integrator);

}  // namespace sg
