// The force kernel compiled for AVX2 (this file is compiled with -mavx2, without FMA: see
// force_kernel.h). Its inline namespace keeps every function it defines apart from the
// default build's; tests/model/check_isa_object.sh checks that the object file defines no
// other inline code (which the linker could otherwise pick for the whole program and run on
// a processor without AVX2).
#define SG_SIMD_ISA isa_avx2
#include "model/force_kernel_impl.h"

namespace sg {

// Called only where the processor has AVX2 (avx2_force_kernel, force_kernel_default.cpp).
const ForceKernel& avx2_force_kernel_unchecked() {
  static const ForceKernel kernel = force_kernel_impl::kernel();
  return kernel;
}

}  // namespace sg
