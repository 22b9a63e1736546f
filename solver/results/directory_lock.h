// An exclusive lock on a run directory, held while a results file is written there: a second
// `limber run` into the same directory is refused before it touches the first one's
// results.h5 (which HDF5 would otherwise truncate on create while the first run still writes).
// The lock is flock(2) on DIR/.limber.lock, which stays in the directory: the kernel drops the
// lock when the process ends, killed or not, so the file left behind never blocks a later run.
// `limber render` holds a second lock of the same kind, DIR/.limber-render.lock, while it writes
// its outputs into the run directory: two renders of one folder would otherwise delete and
// write each other's frames, VTU files and video. It is independent of the run's lock, so a run
// still writing can be rendered (docs/results-format.md, "Reading a file still being written").
#pragma once

#include <filesystem>

namespace limber::results {

// Which lock: its file in the directory, who holds it and what to do, for messages.
struct LockKind {
  const char* file_name;
  const char* holder;  // "run", "render"
  const char* advice;
};
inline constexpr LockKind kRunLock{".limber.lock", "run", "wait for it or choose another output directory"};
inline constexpr LockKind kRenderLock{".limber-render.lock", "render", "wait for it to finish"};

class DirectoryLock {
 public:
  DirectoryLock() = default;
  // Locks `directory` (which must exist). Throws InputError naming the directory when another
  // process holds the lock, or when the lock file cannot be created.
  explicit DirectoryLock(const std::filesystem::path& directory, LockKind kind = kRunLock);
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

// Name of the run's lock file inside a run directory.
inline constexpr const char* kLockFileName = kRunLock.file_name;

}  // namespace limber::results
