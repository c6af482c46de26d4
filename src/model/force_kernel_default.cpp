// The force kernel compiled with the build's flags (baseline x86-64 by default), the run-time
// choice among the kernels, and their scratch (force_kernel.h).
#include <array>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "model/force_kernel_impl.h"

namespace sg {

#if defined(SOFTGRAIN_AVX2_KERNEL)
const ForceKernel& avx2_force_kernel_unchecked();  // force_kernel_avx2.cpp
#endif

const ForceKernel* avx2_force_kernel() {
#if defined(SOFTGRAIN_AVX2_KERNEL)
  // Checked here, in code compiled for baseline x86-64: the AVX2 unit's own code may not run
  // on a processor without AVX2.
  if (__builtin_cpu_supports("avx2")) return &avx2_force_kernel_unchecked();
#endif
  return nullptr;
}

const ForceKernel& default_force_kernel() {
  static const ForceKernel kernel = force_kernel_impl::kernel();
  return kernel;
}

std::vector<const ForceKernel*> available_force_kernels() {
  std::vector<const ForceKernel*> kernels{&default_force_kernel()};
  if (const ForceKernel* avx2 = avx2_force_kernel()) kernels.push_back(avx2);
  return kernels;
}

const ForceKernel& force_kernel_named(const char* name) {
  if (name == nullptr || std::string(name).empty()) {
    const ForceKernel* avx2 = avx2_force_kernel();
    return avx2 ? *avx2 : default_force_kernel();
  }
  const std::string asked(name);
  if (asked == "default") return default_force_kernel();
  if (asked == "avx2") {
    const ForceKernel* avx2 = avx2_force_kernel();
    SG_VERIFY(avx2 != nullptr, "environment variable SOFTGRAIN_SIMD: 'avx2' asked, but "
                                   << "this build or this processor has no AVX2 kernel "
                                   << "(expected 'default')");
    return *avx2;
  }
  SG_THROW("environment variable SOFTGRAIN_SIMD: unknown kernel '"
           << asked << "' (expected 'default' or 'avx2')");
}

const ForceKernel& force_kernel() {
  static const ForceKernel& kernel = force_kernel_named(std::getenv("SOFTGRAIN_SIMD"));
  return kernel;
}

double* force_kernel_scratch(std::size_t doubles, int slot) {
  // std::vector's memory is 16-byte aligned; 8 spare doubles leave room to align on 64.
  thread_local std::array<std::vector<double>, 4> buffers;
  std::vector<double>& b = buffers[static_cast<std::size_t>(slot)];
  if (b.size() < doubles + 8) b.resize(doubles + 8);
  void* p = b.data();
  std::size_t space = b.size() * sizeof(double);
  return static_cast<double*>(std::align(64, doubles * sizeof(double), p, space));
}

}  // namespace sg
