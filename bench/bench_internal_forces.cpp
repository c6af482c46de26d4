// Internal forces + time update on sets of ~100-node soft discs (the papers' grains):
// ~10,000 and ~100,000 field nodes, 1 and 2 threads. Reports node-steps per second.
//
//   build/bench/bench_softgrain --benchmark_filter=InternalForces --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>

#include "geometry/shapes.h"
#include "model/kinematics.h"
#include "solver/explicit_solver.h"
#include "solver/stable_time_step.h"

namespace sg {
namespace {

Model disc_set(int discs) {
  MaterialDef m;
  m.name = "soft";
  m.young = 10.0;
  m.poisson = 0.495;
  m.damping = 0.02;
  DiscretizationParams p;
  p.mesh.spacing = 0.1;  // 117 field nodes per disc of radius 0.5 (the papers: 100-150)
  const BodyDiscretization disc =
      discretize_body(make_disc(Vec2(0, 0), 0.5, p.mesh.spacing), p, "disc");
  Model model;
  const MaterialId id = model.add_material(m);
  const int side = static_cast<int>(std::ceil(std::sqrt(discs)));
  for (int k = 0; k < discs; ++k) {
    BodyDiscretization shifted = disc;
    for (Vec2& x : shifted.mesh.nodes)
      x += Vec2(1.1 * (k % side), 1.1 * (k / side));
    const BodyId b = model.add_deformable_body("d" + std::to_string(k), shifted, id);
    Mat2 f = Mat2::Identity();
    f(0, 0) = 1.0 + 0.01 * (k % 7);
    set_affine_deformation(model, b, f);
    set_rigid_velocity(model, b, Vec2(0.1, 0.0), 0.5);
  }
  return model;
}

void InternalForces(benchmark::State& state) {
  const int discs = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  Model model = disc_set(discs);
  ExplicitSolver solver(model);
  const double dt = estimate_stable_time_step(model, 0.9).dt;
  for (auto _ : state) {
    solver.step(dt);
    benchmark::ClobberMemory();
  }
  const double node_steps =
      static_cast<double>(model.node_count()) * static_cast<double>(state.iterations());
  state.counters["nodes"] = static_cast<double>(model.node_count());
  state.counters["gauss_points"] = static_cast<double>(model.gauss_point_count());
  state.counters["node_steps_per_s"] = benchmark::Counter(node_steps, benchmark::Counter::kIsRate);
  state.counters["threads"] = threads;
}

BENCHMARK(InternalForces)
    ->ArgsProduct({{100, 1000}, {1, 2}})
    ->ArgNames({"discs", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace
}  // namespace sg

BENCHMARK_MAIN();
