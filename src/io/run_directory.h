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
//     not be resumed into this one), and nothing else.
#include <filesystem>
#include <string>

namespace sg {

// Checks the above, creates the folder and returns its path. Throws sg::Error naming the
// folder and the rule broken.
std::filesystem::path prepare_run_directory(const std::filesystem::path& output_root,
                                            const std::string& name, bool resume);

// True if `dir` is empty or a softgrain run folder as defined above.
bool is_softgrain_run_folder(const std::filesystem::path& dir);

}  // namespace sg
