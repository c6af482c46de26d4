#pragma once
// Atomic writes: the content goes to "<path>.tmp" then is renamed over <path>, so a reader
// (or a run killed mid-write) never sees a half-written file.
// The writer is a std::function (called once per file, never inside a time step).
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace sg {

// Calls write(stream) on a temporary file next to `path`, then renames it to `path`.
// Throws sg::Error naming the path if anything fails.
// The parent folder is created if needed.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);
// Same with the whole content given.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace sg
