#pragma once
// The lock of a run folder, held while a run writes it (issue #26): a second `softgrain run`
// on the same folder (by hand, or a sweep restarted while the orphan of the killed one still
// runs) is refused, naming the process that holds it, instead of both writing the same files.
//
// flock() on <run folder>/run.lock, an empty file: the kernel releases the lock when its
// holder exits, however it dies, so a killed run never leaves a stale lock behind. The file
// stays after the run (removing it would let a process lock a file that another one is about
// to replace); it is opened without following a link.
#include <chrono>
#include <filesystem>
#include <string>

namespace sg {

// The name of the lock file in a run folder, and in a campaign folder (a sweep holds the
// latter while it runs: a second sweep of the same campaign is refused).
inline constexpr const char* kRunLockFile = "run.lock";
inline constexpr const char* kSweepLockFile = "sweep.lock";

class RunFolderLock {
 public:
  RunFolderLock() = default;
  ~RunFolderLock();
  RunFolderLock(const RunFolderLock&) = delete;
  RunFolderLock& operator=(const RunFolderLock&) = delete;

  // Takes the lock of the folder `dir` (which must exist), waiting up to `wait` for a holder
  // that is exiting (the child of a killed sweep dies with it, a moment later). Throws
  // sg::Error naming the folder (as `what`: "run folder", "campaign folder") and the holding
  // process if it stays held. `file`: the lock file's name in `dir`.
  void acquire(const std::filesystem::path& dir,
               std::chrono::milliseconds wait = std::chrono::milliseconds(3000),
               const char* file = kRunLockFile, const char* what = "run folder");
  bool held() const { return fd_ >= 0; }
  void release();  // before the end of its life (a run closed, its files complete)

 private:
  int fd_ = -1;
};

// "process 1234 (softgrain run ...)" holding an flock on `file` (from /proc/locks), or
// "another process" when it cannot be told.
std::string lock_holder(const std::filesystem::path& file);

}  // namespace sg
