#include "io/run_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "core/error.h"

namespace sg {

namespace {

// The command line of process `pid`, its arguments separated by spaces ("" if unknown).
std::string command_line(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/cmdline", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (char& c : text)
    if (c == '\0') c = ' ';
  while (!text.empty() && text.back() == ' ')
    text.pop_back();
  return text.size() > 200 ? text.substr(0, 200) + "..." : text;
}

}  // namespace

std::string lock_holder(const std::filesystem::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return "another process";
  // /proc/locks: "1: FLOCK  ADVISORY  WRITE 1234 08:01:5678 0 EOF" (pid, major:minor:inode).
  std::ifstream locks("/proc/locks");
  std::string line;
  while (std::getline(locks, line)) {
    std::istringstream fields(line);
    std::string number, kind, mode, access, device;
    long pid = 0;
    if (!(fields >> number >> kind)) continue;
    if (kind == "->") fields >> kind;  // a blocked waiter's line
    if (!(fields >> mode >> access >> pid >> device) || kind != "FLOCK") continue;
    const auto colon = device.rfind(':');
    if (colon == std::string::npos) continue;
    if (std::strtoull(device.c_str() + colon + 1, nullptr, 10) != st.st_ino) continue;
    const std::string command = command_line(pid);
    return "process " + std::to_string(pid) + (command.empty() ? "" : " (" + command + ")");
  }
  return "another process";
}

void RunFolderLock::acquire(const std::filesystem::path& dir, std::chrono::milliseconds wait,
                            const char* file_name, const char* what) {
  SG_ASSERT(fd_ < 0, "the run folder lock is taken once");
  const std::filesystem::path file = dir / file_name;
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  SG_VERIFY(fd_ >= 0, "cannot open the lock file '"
                          << file.string() << "': " << std::strerror(errno)
                          << (errno == ELOOP ? " (a symbolic link)" : ""));
  const auto deadline = std::chrono::steady_clock::now() + wait;
  while (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    if (error == EINTR) continue;
    if (error != EWOULDBLOCK || std::chrono::steady_clock::now() >= deadline) {
      const std::string holder = error == EWOULDBLOCK ? lock_holder(file) : "";
      ::close(fd_);
      fd_ = -1;
      SG_VERIFY(error != EWOULDBLOCK,
                what << " '" << dir.string() << "' is in use: " << holder
                     << " is writing it (it holds '" << file.string()
                     << "'); wait for it to end, or stop it, before running there");
      SG_THROW("cannot lock '" << file.string() << "': " << std::strerror(error));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

RunFolderLock::~RunFolderLock() {
  release();
}

void RunFolderLock::release() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
  fd_ = -1;
}

}  // namespace sg
