#include "io/atomic_file.h"

#include <fstream>

#include "core/error.h"

namespace sg {

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    SG_VERIFY(out, "cannot open '" << temporary.string() << "' for writing");
    write(out);
    out.flush();
    SG_VERIFY(out, "failed writing '" << temporary.string() << "' (disk full?)");
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  SG_VERIFY(!error, "cannot rename '" << temporary.string() << "' to '" << path.string()
                                      << "': " << error.message());
}

}  // namespace sg
