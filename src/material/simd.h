#pragma once
// The SIMD batch the force kernel computes with: xsimd (Debian libxsimd-dev), its widest
// instruction set enabled at compile time. The default build targets baseline x86-64 (SSE2:
// 2 doubles per batch); SOFTGRAIN_NATIVE (-march=native) gives 4 (AVX2) or 8 (AVX-512).
// The Gauss-point blocks of the model (model/gauss_blocks.h) have this width.
#include <cstddef>
#include <vector>

#include <xsimd/xsimd.hpp>

namespace sg {

using DoubleBatch = xsimd::batch<double>;
using DoubleBatchBool = xsimd::batch_bool<double>;
inline constexpr int kSimdWidth = static_cast<int>(DoubleBatch::size);
// Block arrays start on a cache line, so that a row of a block never straddles two.
inline constexpr std::size_t kSimdAlignment = 64;

template <class T>
using AlignedVector = std::vector<T, xsimd::aligned_allocator<T, kSimdAlignment>>;

}  // namespace sg
