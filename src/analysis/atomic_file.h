#pragma once
// Writing an output file so that a reader never sees half of it: the content goes to
// "<path>.tmp", is flushed and closed, then renamed over <path> (rename is atomic on
// POSIX within a file system). An interrupted analysis leaves the old file or none.
#include <string>
#include <string_view>

namespace sg {

// Creates the parent folder if needed. Throws sg::Error naming the path on failure.
void write_file_atomically(const std::string& path, std::string_view content);

}  // namespace sg
