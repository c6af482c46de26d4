#pragma once
// Runs a scenario text through `softgrain run`'s engine (run/run.h) on a given number of
// OpenMP threads: the thread-independence and resume tests of the shear cells.
#include <omp.h>

#include <filesystem>
#include <string>

#include "run/run.h"
#include "scenes/scenario_files.h"

namespace sg::scenes {

// Writes `text` to <dir>/<file> and runs it into <dir>/out with `threads` threads (set back
// to 1 after); `stop_after` >= 0 stops after that many steps, `resume` continues a stopped run.
inline RunSummary run_scenario_text(const std::filesystem::path& dir, const std::string& file,
                                    const std::string& text, int threads, long stop_after = -1,
                                    bool resume = false) {
  write_text_file(dir / file, text);
  omp_set_num_threads(threads);
  RunOptions options;
  options.output_root_override = dir / "out";
  options.stop_after_steps = stop_after;
  options.resume = resume;
  const RunSummary summary = run_scenario(load_scenario(dir / file), options);
  omp_set_num_threads(1);
  return summary;
}

}  // namespace sg::scenes
