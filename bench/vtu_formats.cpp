// Size and write time of one field snapshot (fields/NNNNNN.vtu) in each encoding of
// io/vtu_document.h, on a paper-scale model (docs/scenario.md "Field files"):
//
//   bench_vtu_formats SCENARIO.toml OUTPUT_FOLDER [REPETITIONS]
//
// builds the scenario's model (examples/shear-cell-full.toml: 2,000 grains, about 317k
// nodes), gives every node a pseudo-random displacement (up to 1% of the node spacing) and
// velocity (|v_i| <= 0.5, the order of V/2), so that positions, stresses and rates hold
// full-precision doubles as in a run (the initial state is all zeros, which compresses far
// better than any real snapshot), then writes the snapshot binary and ASCII, REPETITIONS times
// each (default 1), and reads each back with softgrain's reader. Prints one CSV row per write:
//   format,nodes,cells,bytes,write_seconds,write_cpu_seconds,read_seconds
// write_cpu_seconds: the CPU time of the process (all threads) during the write, which a
// machine shared with other jobs inflates less than the wall time.
// The reader's arrays of both files are checked identical (exit status 1 if not).
#include <time.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>

#include "io/vtk_writer.h"
#include "render/vtu_reader.h"
#include "scenario/scenario.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// A deterministic state with full-precision values at every node.
void perturb(sg::Model& model, double spacing) {
  std::mt19937_64 random(1);
  auto uniform = [&](double a) {
    return a * (2.0 * static_cast<double>(random() >> 11) * 0x1.0p-53 - 1.0);
  };
  for (std::size_t j = 0; j < model.node_count(); ++j) {
    model.nodes.ux[j] += uniform(0.01 * spacing);
    model.nodes.uy[j] += uniform(0.01 * spacing);
    model.nodes.vx[j] = uniform(0.5);
    model.nodes.vy[j] = uniform(0.5);
  }
}

bool same_arrays(const sg::VtuMesh& a, const sg::VtuMesh& b) {
  if (a.points != b.points || a.connectivity != b.connectivity || a.offsets != b.offsets ||
      a.types != b.types || a.point_data.size() != b.point_data.size())
    return false;
  for (std::size_t k = 0; k < a.point_data.size(); ++k)
    if (a.point_data[k].name != b.point_data[k].name ||
        a.point_data[k].values != b.point_data[k].values)
      return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: bench_vtu_formats SCENARIO.toml OUTPUT_FOLDER [REPETITIONS]\n";
    return 2;
  }
  try {
    const sg::ScenarioDef scenario = sg::load_scenario(argv[1]);
    const std::filesystem::path out = argv[2];
    const int repetitions = argc > 3 ? std::stoi(argv[3]) : 1;
    std::filesystem::create_directories(out);
    const auto built = Clock::now();
    sg::Model model = sg::build_model(scenario);
    std::cerr << "model built in " << seconds_since(built) << " s: " << model.node_count()
              << " nodes\n";
    perturb(model, scenario.discretization.mesh.spacing);
    const double rate = sg::global_strain_rate(scenario);
    std::cout << "format,nodes,cells,bytes,write_seconds,write_cpu_seconds,read_seconds\n";
    sg::VtuMesh meshes[2];
    const char* names[2] = {"binary", "ascii"};
    for (int r = 0; r < repetitions; ++r) {
      for (int f = 0; f < 2; ++f) {
        const auto format = f == 0 ? sg::FieldFormat::binary : sg::FieldFormat::ascii;
        const std::filesystem::path file = out / (std::string(names[f]) + ".vtu");
        const auto write = Clock::now();
        const double cpu = process_cpu_seconds();
        sg::write_vtu_snapshot(model, file, rate, {}, format);
        const double write_seconds = seconds_since(write);
        const double write_cpu_seconds = process_cpu_seconds() - cpu;
        const auto read = Clock::now();
        meshes[f] = sg::read_vtu(file);
        const double read_seconds = seconds_since(read);
        std::cout << names[f] << ',' << meshes[f].points.size() << ',' << meshes[f].cell_count()
                  << ',' << std::filesystem::file_size(file) << ',' << write_seconds << ','
                  << write_cpu_seconds << ',' << read_seconds << std::endl;
      }
    }
    if (!same_arrays(meshes[0], meshes[1])) {
      std::cerr << "the binary and ASCII files read back to different arrays\n";
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_vtu_formats: " << e.what() << '\n';
    return 1;
  }
}
