// An exclusive lock on a run directory, held while a results file is written there: a second
// `limber run` into the same directory is refused before it touches the first one's
// results.h5 (which HDF5 would otherwise truncate on create while the first run still writes).
// The lock is flock(2) on DIR/.limber.lock, which stays in the directory: the kernel drops the
// lock when the process ends, killed or not, so the file left behind never blocks a later run.
#pragma once

#include <filesystem>

namespace limber::results {

class DirectoryLock {
 public:
  DirectoryLock() = default;
  // Locks `directory` (which must exist). Throws InputError naming the directory when another
  // process holds the lock, or when the lock file cannot be created.
  explicit DirectoryLock(const std::filesystem::path& directory);
  ~DirectoryLock();
  DirectoryLock(DirectoryLock&& other) noexcept;
  DirectoryLock& operator=(DirectoryLock&& other) noexcept;
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  void release();
  int fd_ = -1;
  std::filesystem::path path_;
};

// Name of the lock file inside a run directory.
inline constexpr const char* kLockFileName = ".limber.lock";

}  // namespace limber::results
