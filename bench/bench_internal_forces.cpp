// Internal forces + time update on sets of ~100-node soft discs (the papers' grains):
// ~10,000 and ~100,000 field nodes, 1 and 2 threads, standard and F-bar elasticity (fbar:1,
// `volumetric = "fbar"`). Reports node-steps per second.
//
//   build/bench/bench_softgrain --benchmark_filter=InternalForces --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include "disc_set.h"
#include "solver/stable_time_step.h"
#include "solver/step_profile.h"
#include "solver/stepper.h"

namespace sg {
namespace {

void InternalForces(benchmark::State& state) {
  const int discs = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const bool fbar = state.range(2) != 0;
  omp_set_num_threads(threads);
  Model model =
      bench::disc_set(discs, fbar ? VolumetricFormulation::fbar : VolumetricFormulation::standard);
  Stepper solver(model);
  const double dt = estimate_stable_time_step(model, 0.9).dt;
  solver.profile() = StepProfile{};
  for (auto _ : state) {
    solver.step(dt);
    benchmark::ClobberMemory();
  }
  // Where the step goes: microseconds per step of each phase that takes time here (no contact
  // between the discs), the rest of the step apart.
  const StepProfile& profile = solver.profile();
  const double per_step = 1e6 / static_cast<double>(profile.steps);
  const double internal = profile[StepPhase::internal_forces] * per_step;
  const double velocities = profile[StepPhase::velocities] * per_step;
  state.counters["us_internal_forces"] = internal;
  state.counters["us_velocities"] = velocities;
  state.counters["us_other"] = profile.total() * per_step - internal - velocities;
  const double node_steps =
      static_cast<double>(model.node_count()) * static_cast<double>(state.iterations());
  state.counters["nodes"] = static_cast<double>(model.node_count());
  state.counters["gauss_points"] = static_cast<double>(model.gauss_point_count());
  state.counters["node_steps_per_s"] = benchmark::Counter(node_steps, benchmark::Counter::kIsRate);
  state.counters["threads"] = threads;
}

BENCHMARK(InternalForces)
    ->ArgsProduct({{100, 1000}, {1, 2}, {0, 1}})
    ->ArgNames({"discs", "threads", "fbar"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace
}  // namespace sg

BENCHMARK_MAIN();
