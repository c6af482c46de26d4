#include "io/atomic_file.h"

#include <fstream>

#include "core/error.h"

namespace sg {

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  std::error_code error;
  if (path.has_parent_path()) {
    std::filesystem::create_directories(path.parent_path(), error);
    SG_VERIFY(!error,
              "cannot create folder '" << path.parent_path().string() << "': " << error.message());
  }
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    SG_VERIFY(out, "cannot open '" << temporary.string() << "' for writing");
    write(out);
    out.flush();
    SG_VERIFY(out, "failed writing '" << temporary.string() << "' (disk full?)");
  }
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary);
    SG_THROW("cannot rename '" << temporary.string() << "' to '" << path.string()
                               << "': " << error.message());
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
  });
}

}  // namespace sg
