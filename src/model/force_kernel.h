#pragma once
// The internal-force kernel (force_kernel_impl.h on row_kernel.h) in the versions this build
// has, and the choice among them at run time.
//
// The default build targets baseline x86-64 (SSE2), what every x86-64 processor runs. On
// x86-64 it compiles the kernel a second time for AVX2 (force_kernel_avx2.cpp) and uses that
// version where the processor has AVX2: 1.5x the step rate of the SSE2 one on the benchmark's
// discs, one thread (bench/results/*/internal_forces.csv, set D). Both versions give the same bits:
// the kernel's sums do not depend on the SIMD width (row_kernel.h), no multiply-add is fused
// (-ffp-contract=off, and AVX2 without FMA), and ln J is std::log per lane in both
// (material/material_batch.h). A SOFTGRAIN_NATIVE build (-march=native) has one version, for the
// build machine.
//
// SOFTGRAIN_SIMD=default (or =avx2) in the environment asks for one version; `softgrain info`
// prints the one in use.
#include <cstddef>
#include <vector>

#include "model/model.h"

namespace sg {

// What a body's force evaluation measured. A Gauss point with det F <= 0 or a non-finite
// value stops the evaluation of that body and is reported (the caller adds the step).
struct BodyForceResult {
  double elastic_energy = 0.0;  // integral of W over the body
  double damping_power = 0.0;   // integral of S_v : E_dot (>= 0)
  int bad_gauss_point = -1;     // global index of the first invalid Gauss point, or -1
  double bad_jacobian = 0.0;    // det F there
};

// The node arrays a body's force evaluation reads and writes, from the body's first node (the
// rows' local numbering). vx, vy are read for damped bodies only; viscous_fx, viscous_fy may be
// null (no split of the viscous part) and are otherwise added to, like fx, fy. `gradients`,
// if not null, receives F at each Gauss point (g - body.gauss_begin), the bits
// deformation_gradients() computes (standard formulation; the F-bar kernel leaves it alone).
struct BodyArrays {
  const double *ux, *uy, *vx, *vy;
  double *fx, *fy, *viscous_fx, *viscous_fy;
  Mat2* gradients = nullptr;
};

struct ForceKernel {
  const char* isa;  // xsimd's name of the instruction set: "sse2", "avx2", ...
  // f -= internal forces of `body` (elastic, plus viscous when `damped`), `rotation` the body's
  // mean rotation (corotational damping).
  BodyForceResult (*body_forces)(const Model& model, const Body& body, const BodyArrays& arrays,
                                 bool damped, const Mat2& rotation);
  // F at each Gauss point of `body` into out[g - body.gauss_begin].
  void (*deformation_gradients)(const Model& model, const Body& body, const double* ux,
                                const double* uy, Mat2* out);
  // out = C x, the viscous operator at the deformation gradients F (internal_forces.h).
  void (*viscous_operator)(const Model& model, const Body& body, const Mat2* gradients,
                           const Mat2& rotation, const double* x, const double* y, double* out_x,
                           double* out_y);
};

// The kernel compiled with the build's flags, and the AVX2 one (null if this build has none
// or the processor lacks AVX2).
const ForceKernel& default_force_kernel();
const ForceKernel* avx2_force_kernel();
// The kernels this build has and this processor runs, default first.
std::vector<const ForceKernel*> available_force_kernels();
// The kernel in use: the AVX2 one where available, unless SOFTGRAIN_SIMD names another
// ("default" or "avx2"; an unknown or unavailable name is an error).
const ForceKernel& force_kernel();
// The kernel a value of SOFTGRAIN_SIMD names (null or empty: the AVX2 one where available, else
// the default); throws sg::Error naming the variable and the values expected.
const ForceKernel& force_kernel_named(const char* name);

// Per-thread scratch of the kernels: `doubles` values aligned on 64 bytes, slot 0 to 3 (0, 1:
// node buffers; 2, 3: the F-bar kernel's per-point and per-patch values); kept
// (and grown) from call to call.
double* force_kernel_scratch(std::size_t doubles, int slot);

}  // namespace sg
