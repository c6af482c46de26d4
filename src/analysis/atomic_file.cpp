#include "analysis/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/error.h"

namespace sg {

void write_file_atomically(const std::string& path, std::string_view content) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    SG_VERIFY(!ec, path << ": cannot create folder '" << target.parent_path().string()
                        << "': " << ec.message());
  }
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    SG_VERIFY(out, temporary << ": cannot open for writing");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    SG_VERIFY(out, temporary << ": write failed");
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    fs::remove(temporary);
    SG_THROW(path << ": cannot rename '" << temporary << "' into place: " << ec.message());
  }
}

}  // namespace sg
