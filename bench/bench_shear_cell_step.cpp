// Whole steps of a compacted third-body shear cell, as `softgrain run` takes them (step
// controller, contacts, internal forces, update): the number behind "the papers' run in
// under a day". Cohesive soft grains (nu = 0.45, alpha = 0.01) of diameter 0.85-1.15 at node
// spacing 0.1 (about 80 nodes per grain); the cell is compacted for one time unit before
// the timing, so the grains are in contact. Reports node-steps per second, the step, and the
// share of the wall time of each phase of the step profile (solver/step_profile.h) with
// profile_over_wall, the sum of the phases over the measured wall time (the steps' own
// phases only: the controller's held-state copies are the rest).
//
//   build/bench/bench_softgrain --benchmark_filter=ShearCellStep --benchmark_repetitions=3
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "../tests/scenes/shear_cell_scenario.h"
#include "scenario/scenario.h"
#include "solver/step_controller.h"
#include "solver/stepper.h"

namespace sg {
namespace {

ScenarioDef bench_cell(int grains) {
  scenes::CohesiveShearCell c;
  c.name = "bench";
  c.grains = grains;
  c.length = std::max(10.0, grains / 20.0);  // 2000 grains: L = 100, as in papers 001/002
  c.node_spacing = 0.1;
  c.duration = 2.0;
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("softgrain_bench_cell_" + std::to_string(grains) + ".toml");
  std::ofstream(file) << scenes::shear_cell_scenario(c);
  ScenarioDef s = load_scenario(file);
  std::filesystem::remove(file);
  return s;
}

void ShearCellStep(benchmark::State& state) {
  const int grains = static_cast<int>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const ScenarioDef scenario = bench_cell(grains);
  Model model = build_model(scenario);
  ContactSystem contacts(model, contact_law_table(scenario), contact_settings(scenario));
  Stepper solver(model, &contacts);
  StepController controller(solver, &contacts, StepControlParams{});
  while (solver.state().time < 1.0)  // the compaction stage: grains in contact
    controller.advance();
  // The profile's phases against the wall time of the timed steps (issue: they must add up).
  const StepProfile before = solver.profile();
  const auto wall_start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    controller.advance();
    benchmark::ClobberMemory();
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const StepProfile& after = solver.profile();
  for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
    const double share = (after.seconds[p] - before.seconds[p]) / wall;
    if (after.seconds[p] > before.seconds[p]) {
      std::string name(phase_name(static_cast<StepPhase>(p)));
      std::replace(name.begin(), name.end(), ' ', '_');
      state.counters["share_" + name] = share;
    }
  }
  state.counters["profile_over_wall"] = (after.total() - before.total()) / wall;
  const double node_steps =
      static_cast<double>(model.node_count()) * static_cast<double>(state.iterations());
  state.counters["nodes"] = static_cast<double>(model.node_count());
  state.counters["contacts"] = static_cast<double>(contacts.records().size());
  state.counters["dt"] = controller.next_step();
  state.counters["node_steps_per_s"] = benchmark::Counter(node_steps, benchmark::Counter::kIsRate);
}

BENCHMARK(ShearCellStep)
    ->ArgsProduct({{100, 500, 2000}, {1, 2}})
    ->ArgNames({"grains", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace sg
