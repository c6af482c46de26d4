#include "io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
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
  // A leftover of a killed run, or a symbolic link someone put there: removed (the link, not
  // what it points to), so that the new file is created here and nothing is written through a
  // link (issue #26).
  std::filesystem::remove(temporary, error);
  // On any failure (a full disk) the half-written temporary is removed: nothing is left
  // behind but the previous complete file (issue #26).
  auto remove_temporary = [&] {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
  };
  try {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    SG_VERIFY(out, "cannot open '" << temporary.string() << "' for writing");
    errno = 0;
    write(out);
    out.flush();
    if (out) out.close();
    SG_VERIFY(out, "failed writing '" << temporary.string() << "': "
                                      << (errno != 0 ? std::strerror(errno) : "disk full?"));
  } catch (const Error&) {
    remove_temporary();
    throw;
  } catch (const std::exception& e) {  // the writer's own failure (an allocation)
    remove_temporary();
    SG_THROW("failed writing '" << temporary.string() << "': " << e.what());
  }
  kill_here_if_asked();
  std::filesystem::rename(temporary, path, error);
  if (error) {
    remove_temporary();
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
