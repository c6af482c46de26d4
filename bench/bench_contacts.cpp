// Contact stage (ContactSystem::add_contact_forces: contour positions, broad phase when due,
// narrow phase, Coulomb law with history, force scatter) on dense packings of rigid discs:
// ~100, 1,000 and 10,000 grains of radius 0.5 with 31 contour points each (spacing 0.1, the
// papers' boundary node spacing), on a hexagonal lattice 1% closer than touching, periodic in x,
// so that every grain has up to 6 active contacts. 1 and 2 threads. Reports time per call and
// per contour ("boundary") node.
//
//   ContactForces         the Verlet candidate list stays valid (grains do not move): the
//                         cost of a typical step;
//   ContactForcesRebuild  all grains are shifted by 0.6 skin, back and forth, before each call,
//                         so the broad phase is rebuilt every time: the cost of a rebuild step.
//
// candidate_pairs (broad-phase pairs) and active_contacts are reported too: per boundary node
// they are ~6% higher on 10,000 grains than on 100 (fewer grains on the free top and bottom
// rows), so the work per node is, too.
//
// Scaling (bench/results/debian12-2core/contacts.csv): the instructions per candidate pair
// are the same for the three sizes (valgrind --tool=callgrind, ContactForces: 576, 570, 568);
// what grows the time per node is memory. The stage's arrays (~0.4 kB per boundary node: 1.2,
// 12 and 120 MB) fit in L2 (2 MB) for 100 grains only; per node and step ~11 cache lines
// (0.7 kB) then come from L3 for 1,000 grains and from DRAM for 10,000.
//
//   build/bench/bench_softgrain --benchmark_filter=ContactForces --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_system.h"
#include "geometry/shapes.h"
#include "model/model.h"

namespace sg {
namespace {

struct Packing {
  Model model;
  MaterialPairTable laws{{"grain"}};
};

// columns x rows rigid discs on a hexagonal lattice of pitch 0.99 (overlap 0.01 = 0.2 of the
// contour spacing), periodic in x over columns * pitch.
Packing hexagonal_packing(int columns, int rows) {
  Packing p;
  MaterialDef m;
  m.name = "grain";
  m.young = 10.0;
  m.density = 1.0;
  const MaterialId id = p.model.add_material(m);
  const double radius = 0.5, pitch = 0.99, spacing = 0.1;
  p.model.periodic_x = true;
  p.model.x_min = 0.0;
  p.model.x_max = columns * pitch;
  const Polygon disc = make_disc(Vec2(0, 0), radius, spacing);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const Vec2 center((i + 0.5 * (j % 2) + 0.25) * pitch, j * pitch * std::sqrt(3.0) / 2.0);
      Polygon contour = disc;
      for (Vec2& x : contour)
        x += center;
      p.model.add_rigid_body("g" + std::to_string(j * columns + i), contour, id);
    }
  ContactLawParams law;
  law.kind = ContactLawKind::coulomb;
  law.normal_stiffness = 1e3;
  law.tangential_stiffness = 1e3;
  law.friction = 0.3;
  p.laws.set(0, 0, law);
  return p;
}

ContactSettings settings() {
  ContactSettings s;
  s.cutoff = 0.05;  // half the contour spacing
  s.skin = 0.05;
  return s;
}

void zero_rigid_forces(Model& model) {
  std::fill(model.rigid.fx.begin(), model.rigid.fx.end(), 0.0);
  std::fill(model.rigid.fy.begin(), model.rigid.fy.end(), 0.0);
  std::fill(model.rigid.torque.begin(), model.rigid.torque.end(), 0.0);
}

void report(benchmark::State& state, const Model& model, const ContactSystem& system, int threads,
            int contacts) {
  const auto nodes = static_cast<double>(model.contour_point_count());
  state.counters["candidate_pairs"] = static_cast<double>(system.broad_phase().candidates().size());
  state.counters["grains"] = static_cast<double>(model.bodies.size());
  state.counters["boundary_nodes"] = nodes;
  state.counters["active_contacts"] = contacts;
  state.counters["threads"] = threads;
  // Seconds per boundary node and call (printed with an SI prefix, e.g. 45n = 45 ns).
  state.counters["s_per_node"] =
      benchmark::Counter(nodes * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Two untimed calls: the first builds the broad phase and first touches (allocates) the
// stage's arrays, the second the history buffer it swaps with; a one-off cost of about two
// steps. Timed, it added ~30 ns per boundary node to the 10,000-grain figure, where a run
// has only 11 to 14 iterations, and ~4 at 100 grains (~2000 iterations): a spurious growth
// with size.
void warm_up(ContactSystem& contacts, Model& model) {
  for (int call = 0; call < 2; ++call) {
    zero_rigid_forces(model);
    contacts.add_contact_forces(model);
  }
}

int side_columns(int grains) {
  return static_cast<int>(std::lround(std::sqrt(static_cast<double>(grains))));
}

void ContactForces(benchmark::State& state) {
  const int grains = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const int columns = side_columns(grains);
  Packing p = hexagonal_packing(columns, grains / columns);
  ContactSystem contacts(p.model, p.laws, settings());
  warm_up(contacts, p.model);
  int active = 0;
  for (auto _ : state) {
    zero_rigid_forces(p.model);
    active = contacts.add_contact_forces(p.model).active_contacts;
    benchmark::ClobberMemory();
  }
  report(state, p.model, contacts, threads, active);
}

void ContactForcesRebuild(benchmark::State& state) {
  const int grains = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const int columns = side_columns(grains);
  Packing p = hexagonal_packing(columns, grains / columns);
  ContactSystem contacts(p.model, p.laws, settings());
  warm_up(contacts, p.model);
  // Every other disc moves by more than the skin, the others stay: relative motion, which the
  // broad phase rebuilds for (a common translation of all the discs would not make it rebuild).
  const double shift = 1.2 * settings().skin;
  const int builds_before = contacts.broad_phase().build_count();
  int active = 0;
  double sign = 1.0;
  for (auto _ : state) {
    for (std::size_t r = 0; r < p.model.rigid.y.size(); r += 2)
      p.model.rigid.y[r] += sign * shift;
    sign = -sign;
    zero_rigid_forces(p.model);
    active = contacts.add_contact_forces(p.model).active_contacts;
    benchmark::ClobberMemory();
  }
  if (contacts.broad_phase().build_count() - builds_before != static_cast<int>(state.iterations()))
    state.SkipWithError("the broad phase was not rebuilt at every call");
  report(state, p.model, contacts, threads, active);
}

BENCHMARK(ContactForces)
    ->ArgsProduct({{100, 1000, 10000}, {1, 2}})
    ->ArgNames({"grains", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

BENCHMARK(ContactForcesRebuild)
    ->ArgsProduct({{100, 1000, 10000}, {1, 2}})
    ->ArgNames({"grains", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace
}  // namespace sg
