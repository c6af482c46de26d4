#pragma once
// Which snapshots of fields.pvd a render draws: every one, or those whose time lies in a window
// [t0, t1] (given, or the steady window `softgrain analyze` chose), and of those every one or
// the last only. The drawing box and the colour range follow the frames drawn
// (render/series_extent.h).
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "render/vtu_reader.h"

namespace sg {

// The entries to draw, in order. `window`: keep t0 <= time <= t1 (up to round-off of the
// times as written). Throws sg::Error naming `pvd`, the window and the snapshots' times when
// no snapshot is left.
std::vector<PvdEntry> select_frames(const std::vector<PvdEntry>& entries,
                                    const std::optional<std::pair<double, double>>& window,
                                    bool last_only, const std::filesystem::path& pvd);

// The steady window of RUN_DIR/analysis/summary.json (quantities window_begin, window_end).
// Throws sg::Error naming the file when it is missing (run `softgrain analyze` first), is not
// an analysis summary, or holds no window.
std::pair<double, double> analysed_window(const std::filesystem::path& run_dir);

}  // namespace sg
