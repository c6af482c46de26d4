#pragma once
// Mass scaling (issue #4 "optional mass scaling, reported"; docs/method.md §Mass scaling).
//
// The explicit step is bounded by the highest frequency of the stiffest, lightest body. In a
// slow (quasi-static) shear or compaction the inertia of those bodies hardly matters, so their
// mass can be raised until their critical step reaches a target: scaling a body's masses by
// s divides each of its frequencies by sqrt(s). For a mode of frequency omega with
// stiffness-proportional damping alpha the critical step is
//   dt_c = (2 / omega) (sqrt(1 + xi^2) - xi),   xi = alpha omega / 2
// (stable_time_step.h); solving dt_c = T for omega gives the largest frequency a body may keep,
//   omega_T^2 = 1 / (T (T / 4 + alpha / 2)),
// so a body of frequency omega > omega_T is scaled by s = (omega / omega_T)^2. Bodies are
// scaled uniformly (every node of a deformable body, or a rigid body's mass and moment of
// inertia), so centres of mass and momentum balances are untouched; gravity keeps acting on
// the physical mass (Body::mass_scale). The energy ledger uses the scaled masses: the run's
// energy balance stays exact, but the kinetic energy is that of the scaled system.
//
// Mass scaling changes the dynamics: it is only sound when the added inertia forces stay
// small against the contact and elastic forces (check the kinetic energy against the elastic
// energy, or compare with a shorter unscaled run). The run log reports what was added.
#include <string>

#include "model/model.h"
#include "solver/integrator_params.h"

namespace sg {

struct MassScalingReport {
  double target_step = 0.0;     // T (time)
  int scaled_bodies = 0;        // bodies whose masses were raised
  double max_factor = 1.0;      // largest s
  BodyId max_factor_body = -1;  // the body that got it
  double physical_mass = 0.0;   // total mass before scaling
  double added_mass = 0.0;      // total mass added (mass units)
  double added_fraction() const { return physical_mass > 0.0 ? added_mass / physical_mass : 0.0; }
};

// The scale factor s >= 1 that brings a mode of frequency `omega` (rad/time) with damping
// `alpha` to a critical step of at least `target_step` (1 when it is there already).
double mass_scale_for_step(double omega, double alpha, double target_step);

// Scales the bodies of `model` whose critical step (safety x critical step, as the step
// controller computes it with `contact_stiffness`) is below `target_step`, once, on the
// current (normally the initial) state; repeated (at most 4 passes) while a body's estimate,
// which includes its contact partners' terms, is still below the target. Deterministic: the same
// model gives the same factors whatever the thread count, so a resumed run rebuilds the same
// masses. Throws sg::Error when target_step is not positive or a body was scaled already.
// `integrator`: the run's (a body whose viscosity it treats implicitly is limited by its wave
// speed only).
MassScalingReport apply_mass_scaling(Model& model, double target_step, double safety,
                                     double contact_stiffness,
                                     const IntegratorParams& integrator = {});

// One line for the run log and the terminal: target, bodies scaled, largest factor and where,
// added mass in percent of the total.
std::string describe(const MassScalingReport& report, const Model& model);

}  // namespace sg
