#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ext/stdio_filebuf.h>
#include <mutex>
#include <optional>
#include <set>
#include <utility>

#include "core/error.h"

namespace sg {

namespace fs = std::filesystem;

namespace {

// Test hook (tests/run/test_crash_resume.cpp): with SOFTGRAIN_TEST_KILL_AT_WRITE=N in the
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

// A file descriptor closed when it goes out of scope.
class Descriptor {
 public:
  explicit Descriptor(int fd = -1) : fd_(fd) {}
  Descriptor(Descriptor&& o) noexcept : fd_(std::exchange(o.fd_, -1)) {}
  Descriptor& operator=(Descriptor&& o) noexcept {
    std::swap(fd_, o.fd_);
    return *this;
  }
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }

 private:
  int fd_;
};

struct GuardedFolders {
  std::mutex mutex;
  std::set<fs::path> folders;  // absolute, lexically normal
};

GuardedFolders& guarded() {
  static GuardedFolders g;
  return g;
}

fs::path normal_absolute(const fs::path& p) {
  std::error_code error;
  const fs::path a = fs::absolute(p, error);
  return (error ? p : a).lexically_normal();
}

// The guarded run folder that holds `file`, if any (the innermost).
std::optional<fs::path> guarded_folder_of(const fs::path& file) {
  const fs::path f = normal_absolute(file);
  GuardedFolders& g = guarded();
  const std::lock_guard lock(g.mutex);
  std::optional<fs::path> found;
  for (const fs::path& folder : g.folders) {
    const fs::path rel = f.lexically_relative(folder);
    if (rel.empty() || *rel.begin() == ".." || rel == ".") continue;
    if (!found || folder.native().size() > found->native().size()) found = folder;
  }
  return found;
}

[[noreturn]] void refuse_link_or_file(int parent_fd, const std::string& name, const fs::path& at,
                                      int open_errno) {
  struct stat st {};
  if (::fstatat(parent_fd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(st.st_mode))
    SG_THROW("run folder entry '" << at.string()
                                  << "' is a symbolic link: refusing to write through it (remove "
                                     "the link)");
  SG_THROW("cannot open folder '" << at.string() << "' of the run folder: "
                                  << std::strerror(open_errno) << " (expected a folder)");
}

// The folder `file` goes into, opened: inside a guarded run folder component by component
// with no link followed (missing folders created), elsewhere as the path says.
Descriptor open_parent_folder(const fs::path& file) {
  constexpr int kFolderFlags = O_RDONLY | O_DIRECTORY | O_CLOEXEC;
  const fs::path parent = file.has_parent_path() ? file.parent_path() : fs::path(".");
  const std::optional<fs::path> run_folder = guarded_folder_of(file);
  if (!run_folder) {
    std::error_code error;
    fs::create_directories(parent, error);
    SG_VERIFY(!error, "cannot create folder '" << parent.string() << "': " << error.message());
    Descriptor fd(::open(parent.c_str(), kFolderFlags));
    SG_VERIFY(fd.get() >= 0,
              "cannot open folder '" << parent.string() << "': " << std::strerror(errno));
    return fd;
  }
  Descriptor fd(::open(run_folder->c_str(), kFolderFlags | O_NOFOLLOW));
  if (fd.get() < 0)
    SG_THROW("cannot open run folder '" << run_folder->string() << "': " << std::strerror(errno)
                                        << " (a symbolic link is refused)");
  fs::path at = *run_folder;
  for (const fs::path& component : normal_absolute(parent).lexically_relative(*run_folder)) {
    if (component == ".") continue;
    const std::string name = component.string();
    at /= component;
    int next = ::openat(fd.get(), name.c_str(), kFolderFlags | O_NOFOLLOW);
    if (next < 0 && errno == ENOENT) {
      if (::mkdirat(fd.get(), name.c_str(), 0755) != 0 && errno != EEXIST)
        SG_THROW("cannot create folder '" << at.string() << "': " << std::strerror(errno));
      next = ::openat(fd.get(), name.c_str(), kFolderFlags | O_NOFOLLOW);
    }
    if (next < 0) refuse_link_or_file(fd.get(), name, at, errno);
    fd = Descriptor(next);
  }
  return fd;
}

}  // namespace

void guard_run_folder(const fs::path& run_folder) {
  GuardedFolders& g = guarded();
  const std::lock_guard lock(g.mutex);
  g.folders.insert(normal_absolute(run_folder));
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  const Descriptor folder = open_parent_folder(path);
  const std::string name = path.filename().string();
  const std::string temporary_name = name + ".tmp";
  fs::path temporary = path;
  temporary += ".tmp";
  // A leftover of a killed run, or a symbolic link someone put there: removed (the link, not
  // what it points to); the new file is then created here, exclusively, and nothing is
  // written through a link (issue #26).
  ::unlinkat(folder.get(), temporary_name.c_str(), 0);
  // On any failure (a full disk) the half-written temporary is removed: nothing is left
  // behind but the previous complete file (issue #26).
  auto remove_temporary = [&] { ::unlinkat(folder.get(), temporary_name.c_str(), 0); };
  const int fd = ::openat(folder.get(), temporary_name.c_str(),
                          O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  SG_VERIFY(fd >= 0,
            "cannot open '" << temporary.string() << "' for writing: " << std::strerror(errno));
  try {
    // Owns fd from here (closed by close() or the destructor).
    __gnu_cxx::stdio_filebuf<char> buffer(fd, std::ios::out | std::ios::binary);
    std::ostream out(&buffer);
    errno = 0;
    write(out);
    out.flush();
    const int write_errno = errno;
    const bool closed = buffer.close() != nullptr;
    SG_VERIFY(out && closed, "failed writing '" << temporary.string() << "': "
                                                << (write_errno != 0 ? std::strerror(write_errno)
                                                    : errno != 0     ? std::strerror(errno)
                                                                     : "disk full?"));
  } catch (const Error&) {
    remove_temporary();
    throw;
  } catch (const std::exception& e) {  // the writer's own failure (an allocation)
    remove_temporary();
    SG_THROW("failed writing '" << temporary.string() << "': " << e.what());
  }
  kill_here_if_asked();
  if (::renameat(folder.get(), temporary_name.c_str(), folder.get(), name.c_str()) != 0) {
    const int rename_errno = errno;
    remove_temporary();
    SG_THROW("cannot rename '" << temporary.string() << "' to '" << path.string()
                               << "': " << std::strerror(rename_errno));
  }
}

void write_file_atomically(const fs::path& path, std::string_view content) {
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
  });
}

}  // namespace sg
