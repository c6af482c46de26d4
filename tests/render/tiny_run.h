#pragma once
// A tiny real run for the render and analyze tests, simulated once per test binary: a soft
// grain pressed on a floor next to a rigid grain. Defined in test_tiny_run.cpp, apart from
// the tests, because scenario/scenario.h (via meshfree/mls.h) and analysis/summary.h (via
// analysis/velocity_grid.h) both define sg::VelocityFitParams and cannot share a translation unit.
#include <filesystem>

namespace sg::test {

// The run folder (created on first call under the temp directory).
const std::filesystem::path& tiny_run_dir();

}  // namespace sg::test
