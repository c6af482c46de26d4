#include "io/atomic_file.h"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <fstream>

#include "core/error.h"

namespace sg {

namespace {

// Test hook (tests/io/test_crash_resume.cpp): with SOFTGRAIN_TEST_KILL_AT_WRITE=N in the
// environment, the process kills itself with SIGKILL in its N-th atomic write, once the
// temporary file is written and before it replaces the file (the worst moment to die).
void kill_here_if_asked() {
  static const long kill_at = [] {
    const char* v = std::getenv("SOFTGRAIN_TEST_KILL_AT_WRITE");
    return v ? std::atol(v) : 0L;
  }();
  static std::atomic<long> writes{0};
  if (kill_at > 0 && ++writes == kill_at) std::raise(SIGKILL);
}

}  // namespace

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
  kill_here_if_asked();
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
