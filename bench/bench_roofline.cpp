// The force kernel against the machine's ceilings (a roofline): streamed bandwidth (STREAM
// triad), indexed loads (gather) and their latency (pointer chase) at working sets from L1 to
// memory, the arithmetic peak of the build's SIMD width, and add_internal_forces alone on the
// disc sets of bench_internal_forces.cpp with its bytes and flops per Gauss point and the
// fractions of the ceilings it attains.
//
//   build/bench/bench_softgrain --benchmark_filter='Triad|Gather|Chase|PeakFlops|Kernel'
//
// Kernel counts (per step, from the model's blocks: padded entries P, real entries R, Gauss
// points G, nodes N; damped neo-Hookean body, objective damping, viscous part kept apart):
//   bytes  = 20 P (int32 node, two double gradients) + 16 per lane (weight, length, index)
//            + 80 N (u, v read; f read and written; f_v written): what must stream in;
//   flops  = 16 per padded entry (F and F_dot sums) + 12 per padded entry (the terms w P grad N
//            of the total and the viscous stress) + 4 per real entry (the scatter's subtractions)
//            + 110 per Gauss point (the laws: 39 neo-Hookean with its log counted as one,
//            54 viscous, 17 for F, det F, weights and energies);
//   loads  = 4 node loads per padded entry (gathers) + 4 per real entry (scatter): indexed
//            8-byte loads, compared with the gather ceiling at an L1-sized array.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>

#include "../tests/scenes/reference_kernel.h"
#include "disc_set.h"
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

struct KernelCounts {
  double bytes = 0, flops = 0, loads = 0, gauss_points = 0, padded_entries = 0, real_entries = 0;
};

KernelCounts kernel_counts(const Model& model) {
  KernelCounts c;
  const GaussBlocks& blocks = model.gauss_blocks;
  for (std::size_t b = 0; b < blocks.blocks(); ++b) {
    c.padded_entries +=
        static_cast<double>(blocks.row_offset[b + 1] - blocks.row_offset[b]) * GaussBlocks::width;
    for (int l = 0; l < GaussBlocks::width; ++l) {
      const std::size_t lane = b * GaussBlocks::width + static_cast<std::size_t>(l);
      c.real_entries += blocks.length[lane];
      c.gauss_points += blocks.gauss[lane] >= 0 ? 1 : 0;
    }
  }
  const double lanes = static_cast<double>(blocks.blocks()) * GaussBlocks::width;
  c.bytes = 20 * c.padded_entries + 16 * lanes + 80 * static_cast<double>(model.node_count());
  c.flops = 28 * c.padded_entries + 4 * c.real_entries + 110 * c.gauss_points;
  c.loads = 4 * c.padded_entries + 4 * c.real_entries;
  return c;
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
  const double peak = bench::peak_flops_per_second(kCeilingSeconds);
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
  state.counters["padding"] = c.padded_entries / c.real_entries - 1.0;
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
  state.counters["simd_width"] = kSimdWidth;
}
BENCHMARK(Kernel)
    ->ArgsProduct({{100, 1000}, {1, 2}})
    ->ArgNames({"discs", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

// The scalar kernel the blocked one replaced (tests/scenes/reference_kernel.h), driven as
// add_internal_forces drives it: the baseline of the kernel's speed-up.
void KernelScalarReference(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(1)));
  Model model = bench::disc_set(static_cast<int>(state.range(0)));
  NodeState& n = model.nodes;
  const int bodies = static_cast<int>(model.bodies.size());
  for (auto _ : state) {
#pragma omp parallel for schedule(dynamic, 8)
    for (int b = 0; b < bodies; ++b) {
      const auto o = static_cast<std::size_t>(model.bodies[static_cast<std::size_t>(b)].node_begin);
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
