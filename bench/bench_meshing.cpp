// Meshing cost of a packing's grains: 2000 discs of radius 0.45-0.55 at node spacing 0.08
// (~40 contour nodes, ~160 field nodes each), with and without Lloyd smoothing. CGAL's own
// Lloyd smoother took ~13 s for this case on the 2-core development machine; one call of
// mesh_domain per grain, one
// thread (the scenario builders mesh grains one after the other).
//
//   build/bench/bench_softgrain --benchmark_filter=MeshDiscs
#include <benchmark/benchmark.h>

#include <vector>

#include "geometry/shapes.h"
#include "meshfree/domain_mesh.h"

namespace sg {
namespace {

void MeshDiscs(benchmark::State& state) {
  const int discs = 2000;
  const double h = 0.08;
  std::vector<Polygon> contours;
  for (int i = 0; i < discs; ++i)  // radii spread evenly over [0.45, 0.55): varied meshes
    contours.push_back(make_disc(Vec2(0, 0), 0.45 + 0.1 * (i % 100) / 100.0, h));
  DomainMeshParams params;
  params.spacing = h;
  params.smoothing_iterations = static_cast<int>(state.range(0));
  std::size_t nodes = 0;
  for (auto _ : state) {
    nodes = 0;
    for (const Polygon& c : contours)
      nodes += mesh_domain(c, params, "disc").nodes.size();
    benchmark::DoNotOptimize(nodes);
  }
  state.counters["nodes_per_disc"] = static_cast<double>(nodes) / discs;
  state.counters["discs_per_s"] =
      benchmark::Counter(static_cast<double>(discs), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(MeshDiscs)->Arg(0)->Arg(10)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace sg
