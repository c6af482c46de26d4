// The force kernel compiled for AVX2 (this file is compiled with -mavx2, without FMA: see
// force_kernel.h). Its inline namespace keeps every function it defines apart from the
// default build's; tests/model/check_isa_object.sh checks that the object file defines no
// other inline code (which the linker could otherwise pick for the whole program and run on
// a processor without AVX2).
#define SG_SIMD_ISA isa_avx2
#include "model/force_kernel_impl.h"

// The rest of the program is built for baseline x86-64, where Eigen aligns to 16 bytes. Built
// with AVX, Eigen would align Matrix2d to 32 and lay out every struct holding one differently
// from the units that call this one (an ABI mismatch that UBSan reports as a misaligned
// reference). CMake caps the alignment for this file (src/model/CMakeLists.txt).
static_assert(EIGEN_MAX_ALIGN_BYTES == 16 && alignof(Eigen::Matrix2d) == 16,
              "the AVX2 kernel must share Eigen's alignment with the baseline build");

namespace sg {

// Called only where the processor has AVX2 (avx2_force_kernel, force_kernel_default.cpp).
const ForceKernel& avx2_force_kernel_unchecked() {
  static const ForceKernel kernel = force_kernel_impl::kernel();
  return kernel;
}

}  // namespace sg
