#pragma once
// Total Lagrangian internal forces of deformable bodies (docs/method.md §Finite strain):
//   F   = I + sum_J u_J (x) grad0 N_J          at each Gauss point
//   F'  =     sum_J v_J (x) grad0 N_J          (rate, for the damping)
//   P   = P_el(F) + F S_v,  S_v = alpha C0 : sym(F^T F')
//   f_J -= w_gp P grad0 N_J
// The kernel streams through the precomputed rows; no allocation, no branches on strings.
#include <vector>

#include "model/force_kernel.h"
#include "model/model.h"

namespace sg {

// Adds the internal forces of `body` into fx, fy. Arrays point at the body's first node
// (local numbering of the rows). With `with_damping` false the viscous stress is skipped.
// When `viscous_fx`/`viscous_fy` are given, they receive (are set to) the viscous part alone.
// `kernel`: the version of the force kernel to run (force_kernel.h; null: force_kernel()).
BodyForceResult add_body_internal_forces(const Model& model, BodyId body, const double* ux,
                                         const double* uy, const double* vx, const double* vy,
                                         double* fx, double* fy, bool with_damping = true,
                                         double* viscous_fx = nullptr, double* viscous_fy = nullptr,
                                         const ForceKernel* kernel = nullptr,
                                         Mat2* gradients = nullptr);

// The viscous operator of a deformable body at a fixed deformation: out = C x, where the
// viscous force of the body under the velocity parameters x is f_v = -C x (C symmetric
// positive semi-definite, linear in x at fixed F). `gradients` are the body's deformation
// gradients at its Gauss points (body_deformation_gradients), `rotation` its mean rotation
// (corotational damping model). Arrays in the body's local numbering; out is overwritten.
// This is the viscous part of add_body_internal_forces applied to an arbitrary vector: the
// IMEX integrator's matrix-free operator (solver/implicit_viscosity.h).
void body_deformation_gradients(const Model& model, BodyId body, const double* ux, const double* uy,
                                std::vector<Mat2>& gradients);
void apply_viscous_operator(const Model& model, BodyId body, const std::vector<Mat2>& gradients,
                            const Mat2& rotation, const double* x, const double* y, double* out_x,
                            double* out_y);

struct InternalForceResult {
  double elastic_energy = 0.0;
  double damping_power = 0.0;
};

// The internal forces of one body of the model at its nodes' state (model.nodes: u, v in, f
// and the viscous part added to; see above), with its deformation gradients written to
// `gradients` if not null; nothing for a rigid body.
BodyForceResult add_body_internal_forces(Model& model, BodyId body, Mat2* gradients = nullptr);

// The bodies' results of add_body_internal_forces summed in body order; throws sg::Error
// naming the body and the Gauss point of the first invalid deformation.
InternalForceResult sum_internal_forces(const Model& model,
                                        const std::vector<BodyForceResult>& per_body);

// All deformable bodies, in parallel over bodies (each writes only its own node range,
// and the energies are reduced in body order: results do not depend on the thread count).
// Throws sg::Error naming the body and the Gauss point if a deformation is invalid.
// `gradients`, if given, holds per body null or where its F go (BodyArrays::gradients): the
// IMEX solve of the objective damping model reuses them (solver/implicit_viscosity.h).
InternalForceResult add_internal_forces(Model& model,
                                        const std::vector<Mat2*>* gradients = nullptr);

}  // namespace sg
