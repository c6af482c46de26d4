#pragma once
// A tiny real compaction-box run for the analyze tests, simulated once per test process
// (defined in test_tiny_compaction_run.cpp, which alone includes the scenario layer: see
// render/run_folder.h): 8 grains (5 rigid Fourier grains, 3 soft discs) in a box of width 3;
// the lid comes down from the deposit (inner height 3.55) to 2.7 at 0.5 and stops at t = 1.9;
// the run lasts 2.51, a series row every 0.05 and a snapshot every 0.25, so that the last
// series row (t = 2.5) is written at the same step as a snapshot. About 0.2 s on one thread.
#include <filesystem>

namespace sg::test {

struct TinyCompactionRun {
  // The run folder; <dir>/sample/sample.json is what `softgrain generate` writes for the
  // scenario (the same folder: <output root>/<name>/sample).
  std::filesystem::path dir;
  double width = 0.0;          // W
  double final_height = 0.0;   // the builder's CompactionBoxInfo::final_height
  double stop_time = 0.0;      // when the builder's lid history stops
  double lid_velocity = 0.0;   // V, reached after the ramp ...
  double lid_ramp_time = 0.0;  // ... of this duration (speed linear in time, 0 -> V)
};

const TinyCompactionRun& tiny_compaction_run();

}  // namespace sg::test
