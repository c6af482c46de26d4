#pragma once
// Exit statuses of the softgrain commands that a script or `softgrain sweep` reads
// (README "Using it"): besides 0 (done) and 1 (an error, said on stderr), `analyze` exits with
// kExitUnmeasured when it wrote its summary but could not measure what the run asks for (the
// friction coefficient of a shear cell, the compaction curve of a compaction box):
// summary.json lists those under "unmeasured" with the reason. `sweep` counts such runs apart
// ("done without mu") and exits with the same status when it has such runs and no failure.
namespace sg {

inline constexpr int kExitUnmeasured = 3;

}  // namespace sg
