#pragma once
// Tiny real runs for the render and analyze tests, each simulated once per test process
// (defined in test_tiny_run.cpp, which alone includes the scenario layer):
//  - tiny_run_dir(): a soft grain pressed on a floor next to a rigid grain (not periodic,
//    not a shear cell);
//  - tiny_shear_run_dir(): a periodic shear cell of 20 soft cohesive grains (L = 8, D = 2.6,
//    V = 1), 4 time units, grain snapshots every 0.1: the shear-cell contract of analyze
//    (top/bottom columns, window, agglomerates) in about a second. Loose: the top body
//    loses contact now and then, so friction may be null (tests must not rely on it).
#include <filesystem>

namespace sg::test {

// The run folder (created on first call under the temp directory).
const std::filesystem::path& tiny_run_dir();
const std::filesystem::path& tiny_shear_run_dir();

}  // namespace sg::test
