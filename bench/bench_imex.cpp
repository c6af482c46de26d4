// The IMEX integrator against the explicit one on the papers' viscosities
// (solver/implicit_viscosity.h): a 60-grain cohesive shear cell (L = 20, E = 10, nu = 0.495,
// node spacing 0.12, as the papers' grains but fewer; bench/scenes/imex-cell.toml), compacted for 3
// time units once (IMEX, alpha = 0.02), then for each alpha in {0.02, 0.1, 0.3, 0.5}, damping model
// and integrator (the objective model's imex with its split solve, split: 1, the default, and
// its exact one, 0): whole adaptive steps of shearing from that state. Reports the step, the wall
// seconds per simulated time unit (time per step / dt: the step is constant over the timed steps),
// the conjugate-gradient iterations per step (objective model), and the share of the wall time
// spent in the velocity phase (the implicit solves).
//
//   build/bench/bench_softgrain --benchmark_filter=ImexShearCell --benchmark_min_time=1
//       --benchmark_out=bench/results/<machine>/imex.csv --benchmark_out_format=csv
#include <benchmark/benchmark.h>
#include <omp.h>
#include <Eigen/Dense>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include "../tests/scenes/shear_cell_scenario.h"
#include "scenario/scenario.h"
#include "solver/envelope_cholesky_factor.h"
#include "solver/implicit_viscosity.h"
#include "solver/state_snapshot.h"
#include "solver/step_controller.h"
#include "solver/stepper.h"

namespace sg {
namespace {

constexpr DampingModel kModels[] = {DampingModel::objective, DampingModel::corotational,
                                    DampingModel::reference_stiffness};

// `objective_split`: the objective model's split solve (the default) or the exact one.
ScenarioDef imex_cell(double alpha, DampingModel model, bool imex, bool objective_split = true) {
  scenes::CohesiveShearCell c;
  c.name = "imex_bench";
  c.grains = 60;
  c.length = 20.0;
  c.node_spacing = 0.12;
  c.poisson = 0.495;
  c.damping = alpha;
  c.duration = 10.0;
  // examples/shear-cell-small.toml's layer (bench/scenes/imex-cell.toml): with the default gap
  // (90% of the packed height) and roughness the grains of this packing touch nothing before
  // t = 11, and the timed steps measured free flight.
  c.gap = 3.2;
  c.roughness_rms = 0.3;
  c.seed = 1;
  c.compaction_time = 3.0;
  c.extra_time = imex ? "integrator = \"imex\"\n" : "integrator = \"explicit\"\n";
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "softgrain_bench_imex_cell.toml";
  std::ofstream(file) << scenes::shear_cell_scenario(c);
  ScenarioDef s = load_scenario(file);
  std::filesystem::remove(file);
  for (MaterialDef& m : s.materials)
    if (m.name == "soft") m.damping_model = model;
  s.imex_objective_split = objective_split;
  return s;
}

// The compacted state (the exact objective solve, as before the split one), computed once.
const StateSnapshot& compacted_state() {
  static const StateSnapshot state = [] {
    const ScenarioDef s = imex_cell(0.02, DampingModel::objective, true, false);
    Model model = build_model(s);
    ContactSystem contacts(model, contact_law_table(s), contact_settings(s));
    Stepper solver(model, &contacts, resolve_integrator(s, model, 0.0).params);
    StepController controller(solver, &contacts, StepControlParams{});
    while (solver.state().time < 3.0)
      controller.advance();
    StateSnapshot snapshot;
    capture_state(solver, &contacts, snapshot);
    return snapshot;
  }();
  return state;
}

void ImexShearCell(benchmark::State& state) {
  const double alpha = static_cast<double>(state.range(0)) / 1000.0;
  const DampingModel damping_model = kModels[state.range(1)];
  const bool imex = state.range(2) != 0;
  omp_set_num_threads(static_cast<int>(state.range(3)));
  const bool split = state.range(4) != 0;
  const StateSnapshot& start = compacted_state();
  const ScenarioDef s = imex_cell(alpha, damping_model, imex, split);
  Model model = build_model(s);
  ContactSystem contacts(model, contact_law_table(s), contact_settings(s));
  Stepper solver(model, &contacts, resolve_integrator(s, model, 0.0).params);
  restore_state(start, solver, &contacts);
  StepControlParams params;
  params.reestimate_interval = 0;
  StepController controller(solver, &contacts, params);
  controller.advance();  // first factorizations and contact detection outside the timing
  const StepProfile before = solver.profile();
  const ViscousSolveStatistics solves_before = solver.viscous_statistics();
  const auto wall_start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    controller.advance();
    benchmark::ClobberMemory();
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const double steps = static_cast<double>(state.iterations());
  const double dt = controller.next_step();
  const ViscousSolveStatistics solves = solver.viscous_statistics();
  state.counters["dt"] = dt;
  state.counters["nodes"] = static_cast<double>(model.node_count());
  state.counters["s_per_time_unit"] = wall / steps / dt;
  state.counters["cg_per_step"] =
      static_cast<double>(solves.iterations - solves_before.iterations) / steps;
  state.counters["factorizations"] =
      static_cast<double>(solves.factorizations - solves_before.factorizations);
  state.counters["velocity_share"] =
      (solver.profile()[StepPhase::velocities] - before[StepPhase::velocities]) / wall;
  const bool exact = imex && !split && damping_model == DampingModel::objective;
  state.SetLabel(std::string(to_string(damping_model)) + (imex ? " imex" : " explicit") +
                 (exact ? " exact" : ""));
}

// The last argument: the objective model's split solve (1, the default) or the exact one (0).
BENCHMARK(ImexShearCell)
    ->ArgsProduct({{20, 100, 300, 500}, {0, 1, 2}, {0, 1}, {1, 2}, {1}})
    ->ArgsProduct({{20, 100, 300, 500}, {0}, {1}, {1, 2}, {0}})
    ->ArgNames({"alpha_milli", "model", "imex", "threads", "split"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The velocity solve's factor on the 60 grains of the cell: the grains' A0 = M + h/2 alpha K0
// (alpha = 0.02, h = 3.2e-3), each factored (factorize: 1) or solved for one right-hand side
// (0), grain after grain as the velocity phase does, so that the factors come from memory and
// not from the cache. Factors (kind): 0 sparse SimplicialLDLT (AMD ordering; a grain's factor
// fills 59% of the lower triangle), 1 dense LDLT (Eigen::LDLT, pivoted), 2 dense LLT
// (Eigen::LLT: blocked factorization, no pivoting; A0 is symmetric positive definite).
// Reports microseconds per grain.
//   build/bench/bench_softgrain --benchmark_filter=ViscousFactor
void ViscousFactor(benchmark::State& state) {
  const auto kind = state.range(0);
  const bool factorize = state.range(1) != 0;
  const ScenarioDef s = imex_cell(0.02, DampingModel::reference_stiffness, true);
  const Model model = build_model(s);
  std::vector<Eigen::SparseMatrix<double>> systems;
  for (BodyId b = 0; b < static_cast<BodyId>(model.bodies.size()); ++b) {
    if (!has_implicit_viscosity(model, b)) continue;
    Eigen::SparseMatrix<double> a = (0.5 * 3.2e-3) * assemble_damping_stiffness(model, b);
    const Body& body = model.body(b);
    for (int i = 0; i < body.node_count(); ++i)
      for (int c = 0; c < 2; ++c)
        a.coeffRef(2 * i + c, 2 * i + c) +=
            model.nodes.mass[static_cast<std::size_t>(body.node_begin + i)];
    systems.push_back(a);
  }
  std::vector<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> sparse(systems.size());
  std::vector<Eigen::LDLT<Eigen::MatrixXd>> ldlt(systems.size());
  std::vector<Eigen::LLT<Eigen::MatrixXd>> llt(systems.size());
  std::vector<Eigen::MatrixXd> matrices(systems.size());
  std::vector<Eigen::VectorXd> rhs(systems.size()), x(systems.size());
  for (std::size_t k = 0; k < systems.size(); ++k) {
    sparse[k].compute(systems[k]);
    matrices[k] = Eigen::MatrixXd(systems[k]);
    ldlt[k].compute(matrices[k]);
    llt[k].compute(matrices[k]);
    rhs[k] = Eigen::VectorXd::Ones(systems[k].rows());
  }
  const auto wall_start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    for (std::size_t k = 0; k < systems.size(); ++k) {
      if (kind == 0) {
        if (factorize)
          sparse[k].factorize(systems[k]);
        else
          x[k] = sparse[k].solve(rhs[k]);
      } else if (kind == 1) {
        if (factorize)
          ldlt[k].compute(matrices[k]);
        else
          x[k] = ldlt[k].solve(rhs[k]);
      } else {
        if (factorize)
          llt[k].compute(matrices[k]);
        else
          x[k] = llt[k].solve(rhs[k]);
      }
    }
    benchmark::ClobberMemory();
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  state.counters["us_per_grain"] =
      1e6 * wall / static_cast<double>(state.iterations()) / static_cast<double>(systems.size());
  const char* names[] = {"sparse LDLT", "dense LDLT", "dense LLT"};
  state.SetLabel(std::string(names[kind]) + (factorize ? " factorize" : " solve"));
}

BENCHMARK(ViscousFactor)
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->ArgNames({"kind", "factorize"})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

// The single-precision factor's solve (solver/envelope_cholesky_factor.h): the grains' A0 of
// the cell (as ViscousFactor), factored in double precision, kept in single precision either
// as a full n x n matrix (storage 0, Eigen's triangular solves of its lower triangle), in 8 x 8
// tiles over the whole lower triangle (1: the envelope without an ordering) or over the envelope
// in the reverse Cuthill-McKee ordering (2, what the solver keeps), solved grain after grain for
// one right-hand side. `copies` copies of the 60 factors: 1 (60 grains, 2.6 MB of lower
// triangles: they stay in cache) or 7 (420 grains, 18 MB, about the 400-grain cell's: they come
// from the L3 cache or memory at each pass). Reports microseconds per grain and the factors'
// bytes per grain.
//   build/bench/bench_softgrain --benchmark_filter=SinglePrecisionCholeskySolve
void SinglePrecisionCholeskySolve(benchmark::State& state) {
  const auto storage = static_cast<int>(state.range(0));
  const auto copies = static_cast<int>(state.range(1));
  const ScenarioDef s = imex_cell(0.02, DampingModel::reference_stiffness, true);
  const Model model = build_model(s);
  std::vector<Eigen::MatrixXf> full;
  std::vector<EnvelopeCholeskyFactor> factors;
  double bytes = 0.0;
  for (int copy = 0; copy < copies; ++copy)
    for (BodyId b = 0; b < static_cast<BodyId>(model.bodies.size()); ++b) {
      if (!has_implicit_viscosity(model, b)) continue;
      const Eigen::SparseMatrix<double> k0 = assemble_damping_stiffness(model, b);
      Eigen::MatrixXd a = (0.5 * 3.2e-3) * Eigen::MatrixXd(k0);
      const Body& body = model.body(b);
      for (int i = 0; i < 2 * body.node_count(); ++i)
        a(i, i) += model.nodes.mass[static_cast<std::size_t>(body.node_begin + i / 2)];
      if (storage == 0) {
        Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> cholesky(a);
        full.push_back(a.cast<float>());
        bytes += static_cast<double>(a.size()) * sizeof(float);
        continue;
      }
      EnvelopeCholeskyFactor& factor = factors.emplace_back();
      if (storage == 2) factor.order(k0);
      if (!factor.factor(a)) state.SkipWithError("a factorization failed");
      bytes += static_cast<double>(factor.bytes());
    }
  const std::size_t grains = storage == 0 ? full.size() : factors.size();
  std::vector<Eigen::VectorXf> x(grains);
  const auto wall_start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    for (std::size_t k = 0; k < grains; ++k) {
      if (storage != 0) {
        x[k].setOnes(factors[k].size());
        factors[k].solve_in_place(x[k]);
      } else {
        x[k].setOnes(full[k].rows());
        full[k].triangularView<Eigen::Lower>().solveInPlace(x[k]);
        full[k].triangularView<Eigen::Lower>().adjoint().solveInPlace(x[k]);
      }
    }
    benchmark::ClobberMemory();
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  state.counters["us_per_grain"] =
      1e6 * wall / static_cast<double>(state.iterations()) / static_cast<double>(grains);
  state.counters["kB_per_grain"] = 1e-3 * bytes / static_cast<double>(grains);
  const char* names[] = {"full matrix", "lower triangle in tiles",
                         "envelope in tiles, RCM ordering"};
  state.SetLabel(std::string(names[storage]) + ", " + std::to_string(grains) + " grains");
}

BENCHMARK(SinglePrecisionCholeskySolve)
    ->ArgsProduct({{0, 1, 2}, {1, 7}})
    ->ArgNames({"storage", "copies"})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
}  // namespace sg
