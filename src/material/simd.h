#pragma once
// The SIMD batch the force kernel computes with: xsimd (Debian libxsimd-dev), its widest
// instruction set enabled at compile time. The default build targets baseline x86-64 (SSE2:
// 2 doubles per batch); SOFTGRAIN_NATIVE (-march=native) gives 4 (AVX2) or 8 (AVX-512).
//
// The force kernel is also compiled a second time for AVX2 and chosen at run time
// (model/force_kernel.h). What these headers define therefore lives in an inline namespace
// named after the instruction set of the translation unit (SG_SIMD_ISA, set by the file that
// compiles the kernel for AVX2 before it includes anything): the two compilations define
// distinct functions, and the linker cannot mix them up.
#include <cstddef>
#include <vector>

#include <xsimd/xsimd.hpp>

#ifndef SG_SIMD_ISA
#define SG_SIMD_ISA isa_default
#endif

namespace sg {
inline namespace SG_SIMD_ISA {

using DoubleBatch = xsimd::batch<double>;
using DoubleBatchBool = xsimd::batch_bool<double>;
inline constexpr int kSimdWidth = static_cast<int>(DoubleBatch::size);
// Block arrays start on a cache line, so that a row of a block never straddles two.
inline constexpr std::size_t kSimdAlignment = 64;

template <class T>
using AlignedVector = std::vector<T, xsimd::aligned_allocator<T, kSimdAlignment>>;

}  // namespace SG_SIMD_ISA
}  // namespace sg
