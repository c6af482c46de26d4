// The force kernel against the machine's ceilings (a roofline): streamed bandwidth (STREAM
// triad), indexed loads (gather) and their latency (pointer chase) at working sets from L1 to
// memory, the arithmetic peak of the build's SIMD width, and add_internal_forces alone on the
// disc sets of bench_internal_forces.cpp with its bytes and flops per Gauss point and the
// fractions of the ceilings it attains.
//
//   build/bench/bench_softgrain --benchmark_filter='Triad|Gather|Chase|PeakFlops|Kernel'
//
// Kernel counts (per step, from the model's rows: entries R, Gauss points G, nodes N; damped
// neo-Hookean body, objective damping, viscous part kept apart; the kernel of
// model/force_kernel.h, which reads the rows without padding):
//   bytes  = 20 R (int32 node, two double gradients) + 12 G (weight, row offset)
//            + 80 N (u, v read; f read and written; f_v written): what must stream in;
//   flops  = 16 per entry (F and F_dot sums) + 12 per entry (the terms w P grad N of the total
//            and the viscous stress) + 4 per entry (the subtractions from the forces)
//            + 110 per Gauss point (the laws: 39 neo-Hookean with its log counted as one,
//            54 viscous, 17 for F, det F, weights and energies);
//   loads  = 4 node values per entry read (u, v) + 4 read and written (f, f_v): indexed 8-byte
//            values (the kernel moves each node's four as one vector), compared with the gather
//            ceiling at an L1-sized array.
// The flop ceiling is that of the kernel version in use: AVX2 (4 doubles) where the processor
// has it, else the build's width.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <string>

#include "../tests/scenes/reference_kernel.h"
#include "disc_set.h"
#include "material/simd.h"
#include "model/force_kernel.h"
#include "model/internal_forces.h"
#include "roofline.h"

namespace sg {
namespace {

constexpr double kCeilingSeconds = 0.3;

void Triad(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  for (auto _ : state)
    state.counters["bytes_per_s"] = bench::triad_bytes_per_second(n, kCeilingSeconds);
  state.counters["working_set_bytes"] = 24.0 * static_cast<double>(n);
}
BENCHMARK(Triad)->RangeMultiplier(8)->Range(1 << 10, 1 << 23)->Iterations(3);

void Gather(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  for (auto _ : state)
    state.counters["loads_per_s"] = bench::gather_loads_per_second(n, kCeilingSeconds);
  state.counters["working_set_bytes"] = 8.0 * static_cast<double>(n);
}
BENCHMARK(Gather)->RangeMultiplier(8)->Range(1 << 10, 1 << 25)->Iterations(3);

void Chase(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  for (auto _ : state)
    state.counters["ns_per_load"] = 1e9 * bench::chase_seconds_per_load(n, kCeilingSeconds);
  state.counters["working_set_bytes"] = 8.0 * static_cast<double>(n);
}
BENCHMARK(Chase)->RangeMultiplier(8)->Range(1 << 10, 1 << 25)->Iterations(3);

void PeakFlops(benchmark::State& state) {
  for (auto _ : state)
    state.counters["flops_per_s"] = bench::peak_flops_per_second(kCeilingSeconds);
  state.counters["simd_width"] = kSimdWidth;
}
BENCHMARK(PeakFlops)->Iterations(3);

void PeakFlopsAvx2(benchmark::State& state) {
  if (avx2_force_kernel() == nullptr) {
    state.SkipWithError("this build or this processor has no AVX2 kernel");
    return;
  }
  for (auto _ : state)
    state.counters["flops_per_s"] = bench::peak_avx2_flops_per_second(kCeilingSeconds);
  state.counters["simd_width"] = 4;
}
BENCHMARK(PeakFlopsAvx2)->Iterations(3);

struct KernelCounts {
  double bytes = 0, flops = 0, loads = 0, gauss_points = 0, entries = 0;
};

KernelCounts kernel_counts(const Model& model) {
  KernelCounts c;
  c.entries = static_cast<double>(model.gauss_rows.entries());
  c.gauss_points = static_cast<double>(model.gauss_rows.points());
  c.bytes = 20 * c.entries + 12 * c.gauss_points + 80 * static_cast<double>(model.node_count());
  c.flops = 32 * c.entries + 110 * c.gauss_points;
  c.loads = 8 * c.entries;
  return c;
}

// The flop ceiling of the kernel version in use, and its SIMD width.
double kernel_peak_flops(double seconds) {
  return std::string(force_kernel().isa) == "avx2" ? bench::peak_avx2_flops_per_second(seconds)
                                                   : bench::peak_flops_per_second(seconds);
}
int kernel_simd_width() {
  return std::string(force_kernel().isa) == "avx2" ? 4 : kSimdWidth;
}

void Kernel(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  Model model = bench::disc_set(static_cast<int>(state.range(0)));
  const KernelCounts c = kernel_counts(model);
  // Ceilings on one core, at the kernel's streamed working set (triad), an L1-sized array
  // (gather: a body's node arrays are a few kB), and the build's SIMD width (flops).
  const auto stream_doubles = static_cast<std::size_t>(c.bytes / 24.0);
  const double bandwidth = bench::triad_bytes_per_second(stream_doubles, kCeilingSeconds);
  const double gathers = bench::gather_loads_per_second(1024, kCeilingSeconds);
  const double peak = kernel_peak_flops(kCeilingSeconds);
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    add_internal_forces(model);
    benchmark::ClobberMemory();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
      static_cast<double>(state.iterations());
  const double bytes_per_s = c.bytes / seconds, flops_per_s = c.flops / seconds;
  const double loads_per_s = c.loads / seconds;
  state.counters["gauss_points"] = c.gauss_points;
  state.counters["entries_per_gp"] = c.entries / c.gauss_points;
  state.counters["bytes_per_gp"] = c.bytes / c.gauss_points;
  state.counters["flops_per_gp"] = c.flops / c.gauss_points;
  state.counters["ns_per_gp"] = 1e9 * seconds / c.gauss_points;
  state.counters["GB_per_s"] = 1e-9 * bytes_per_s;
  state.counters["GFlop_per_s"] = 1e-9 * flops_per_s;
  // Fractions of the ceilings of `threads` cores (each ceiling measured on one).
  state.counters["of_triad"] = bytes_per_s / (threads * bandwidth);
  state.counters["of_peak_flops"] = flops_per_s / (threads * peak);
  state.counters["of_gather"] = loads_per_s / (threads * gathers);
  state.counters["threads"] = threads;
  state.counters["simd_width"] = kernel_simd_width();
}
BENCHMARK(Kernel)
    ->ArgsProduct({{100, 1000}, {1, 2}})
    ->ArgNames({"discs", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

// The scalar kernel the SIMD kernels replaced (tests/scenes/reference_kernel.h), driven as
// add_internal_forces drives it: the baseline of the kernel's speed-up.
void KernelScalarReference(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(1)));
  Model model = bench::disc_set(static_cast<int>(state.range(0)));
  NodeState& n = model.nodes;
  const int bodies = static_cast<int>(model.bodies.size());
  for (auto _ : state) {
#pragma omp parallel for schedule(dynamic, 8)
    for (int b = 0; b < bodies; ++b) {
      const auto o = static_cast<std::size_t>(model.body(b).node_begin);
      scenes::reference_body_internal_forces(
          model, b, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o, n.vy.data() + o,
          n.fx.data() + o, n.fy.data() + o, true, n.viscous_fx.data() + o, n.viscous_fy.data() + o);
    }
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_gp"] = benchmark::Counter(
      static_cast<double>(model.gauss_point_count()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(KernelScalarReference)
    ->ArgsProduct({{100, 1000}, {1, 2}})
    ->ArgNames({"discs", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace
}  // namespace sg
