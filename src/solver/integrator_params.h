#pragma once
// The time integrator's settings ([time] integrator, imex_tolerance, imex_refactor_threshold,
// imex_dense_factors, imex_objective):
// how the stepper treats the bulk damping, explicitly (central difference, the viscous force at
// v_n-1/2) or implicitly per damped deformable body (IMEX, solver/implicit_viscosity.h). A
// parameter of the step, not of the model: the stepper, the stable step estimate and mass
// scaling take it (an implicit viscosity does not limit the step), so that two integrators can
// be compared on one model (`softgrain info`) without changing it.
namespace sg {

struct IntegratorParams {
  bool implicit_viscosity = false;       // IMEX; false: explicit
  double imex_tolerance = 1e-5;          // relative residual of the iterative solves (scenario.md)
  double imex_refactor_threshold = 0.1;  // objective model's preconditioner (implicit_viscosity.h)
  // Dense factors for the bodies whose sparse factor would be over half dense (grains), up to
  // this many DOFs; 0: sparse factors for every body (the arithmetic of versions before them).
  int imex_dense_factor_limit = kDefaultDenseFactorLimit;
  static constexpr int kDefaultDenseFactorLimit = 1500;
  // The objective model's solve: true, "split" (its reference operator implicit, the rest
  // explicit: one stored-factor solve per step); false, "exact" (conjugate gradients to
  // imex_tolerance). solver/implicit_viscosity.h. Scenarios default to split (scenario.h); the
  // solver's own default is the exact solve its tests verify.
  bool imex_objective_split = false;

  static IntegratorParams explicit_integrator() { return {}; }
  static IntegratorParams imex(double tolerance = 1e-5, double refactor_threshold = 0.1,
                               int dense_factor_limit = kDefaultDenseFactorLimit,
                               bool objective_split = false) {
    return {true, tolerance, refactor_threshold, dense_factor_limit, objective_split};
  }
  const char* name() const { return implicit_viscosity ? "imex" : "explicit"; }
};

}  // namespace sg
