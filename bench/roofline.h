#pragma once
// The machine's ceilings for the force kernel's roofline (bench_roofline.cpp): streamed
// bandwidth (a STREAM triad), indexed loads (a gather), load latency (a pointer chase) and
// the arithmetic peak of the build's SIMD batches without fused multiply-add (the project
// compiles with -ffp-contract=off, so the kernel cannot use FMA either). Single thread.
#include <cstddef>

namespace sg::bench {

// a = b + s c over arrays of n doubles, repeated for about `seconds`: bytes moved per second,
// counted as STREAM counts them (24 bytes per element: two reads, one write).
double triad_bytes_per_second(std::size_t n, double seconds);
// s += x[index[k]] over random indices into x of n doubles (four independent sums): loads per
// second, each an 8-byte load at a 4-byte index.
double gather_loads_per_second(std::size_t n, double seconds);
// p = next[p] around a random cycle of n 8-byte entries: seconds per load (latency).
double chase_seconds_per_load(std::size_t n, double seconds);
// Independent chains of x = x * a + b on DoubleBatch (a multiply and an add, not fused):
// floating-point operations per second.
double peak_flops_per_second(double seconds);
// The same with 4 doubles per operation on AVX2 (the force kernel's AVX2 version,
// model/force_kernel.h); call it only where the processor has AVX2.
double peak_avx2_flops_per_second(double seconds);

}  // namespace sg::bench
