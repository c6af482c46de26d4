#pragma once
// The run folder <output root>/<name>/ and what a run may do there (issue #15;
// docs/scenario.md, "Safety"). A run writes and deletes only inside this folder:
//   - `name` must be a plain file name (core/file_name.h): no separator, not "." or "..";
//   - the folder must not be a symbolic link (it would lead elsewhere);
//   - starting over (not resuming) in an existing, non-empty folder is refused unless it is
//     a softgrain run folder: it holds a run.log written by softgrain, or only entries a
//     softgrain command writes there (fields/, grains/, sample/, sweep.log, scenario.toml,
//     ...: a run that failed before its log, a `generate`d sample, a campaign run about to
//     start);
//   - starting over removes the folder's checkpoint.bin (an earlier run's checkpoint must
//     not be resumed into this one), and nothing else;
//   - nothing in the folder, and nothing in its subfolders fields/, grains/, contacts/,
//     sample/, render/, analysis/, may be a symbolic link: a linked fields/ would take the
//     snapshots elsewhere, a linked series.csv.partial its rows (issue #26);
//   - from then on every file written atomically there is created through the folder's own
//     descriptor with no link followed (io/atomic_file.h, guard_run_folder): a subfolder
//     replaced by a link mid-run is refused too;
//   - the output root, when it exists, must be a folder;
//   - starting over in the folder of another scenario's run (its run.log names another
//     scenario file) is refused: the new run would leave the old one's snapshots, grains and
//     contact files beside its own (issue #26). With `overwrite` the run's outputs of the
//     folder (run.log, series.csv*, *.pvd, checkpoint.bin, fields/, grains/, contacts/,
//     sample/, render/, analysis/ and their .tmp leftovers) are removed first, whatever run
//     they come from; a campaign's scenario.toml and sweep.* stay.
#include <filesystem>
#include <string>

#include "io/run_lock.h"

namespace sg {

// Checks the above, creates the folder and returns its path. Throws sg::Error naming the
// folder and the rule broken.
// `scenario_file`: the scenario about to run (empty: no check of the run.log's scenario).
// `lock`: if given, the folder's lock (io/run_lock.h) is taken once the checks pass and
// before anything is removed or written there.
std::filesystem::path prepare_run_directory(const std::filesystem::path& output_root,
                                            const std::string& name, bool resume,
                                            const std::filesystem::path& scenario_file = {},
                                            bool overwrite = false, RunFolderLock* lock = nullptr);

// True if `dir` is empty or a softgrain run folder as defined above.
bool is_softgrain_run_folder(const std::filesystem::path& dir);

// Throws sg::Error naming the link if `dir` or one of the subfolders above holds a symbolic
// link (every command that writes into a run folder checks this first).
void refuse_links_in_run_folder(const std::filesystem::path& dir);

// Creates the subfolder `name` of the run folder `dir` if needed; throws sg::Error if it is
// a symbolic link or not a folder. Returns its path.
std::filesystem::path make_run_subfolder(const std::filesystem::path& dir, const std::string& name);

}  // namespace sg
