#pragma once
// Atomic writes: the content goes to "<path>.tmp" then is renamed over <path>, so a reader
// (or a run killed mid-write) never sees a half-written file.
// The writer is a std::function (called once per file, never inside a time step).
//
// Nothing written outside a run folder (issue #26, item 4): once a folder is declared a run
// folder (guard_run_folder; io/run_directory.h does it for every run folder it prepares or
// checks), a file written under it is created relative to the folder's own descriptor, each
// path component below it opened with O_NOFOLLOW (a missing subfolder is created the same
// way) and the temporary created with O_EXCL | O_NOFOLLOW: a subfolder or file replaced by a
// symbolic link, even mid-run, is refused, never written through.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace sg {

// Calls write(stream) on a temporary file next to `path`, then renames it to `path`.
// Throws sg::Error naming the path if anything fails (the temporary is then removed), or
// naming the link if `path` lies in a guarded run folder through a symbolic link.
// The parent folder is created if needed.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);
// Same with the whole content given.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// Declares `run_folder` a run folder for the rest of the process (see above). Thread-safe.
void guard_run_folder(const std::filesystem::path& run_folder);

}  // namespace sg
