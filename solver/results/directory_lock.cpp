#include "results/directory_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include "core/error.h"

namespace limber::results {

DirectoryLock::DirectoryLock(const std::filesystem::path& directory, LockKind kind)
    : path_(directory / kind.file_name) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InputError("cannot create the lock file '" + path_.string() + "': " + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    const std::string holder = kind.holder;
    throw InputError("expected a results directory no other " + holder + " is writing, got '" +
                     directory.string() + "' locked by a running limber " + holder + " (" +
                     kind.file_name + "): " + kind.advice);
  }
}

DirectoryLock::~DirectoryLock() { release(); }

DirectoryLock::DirectoryLock(DirectoryLock&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), path_(std::move(other.path_)) {}

DirectoryLock& DirectoryLock::operator=(DirectoryLock&& other) noexcept {
  if (this != &other) {
    release();
    fd_ = std::exchange(other.fd_, -1);
    path_ = std::move(other.path_);
  }
  return *this;
}

void DirectoryLock::release() {
  if (fd_ < 0) return;
  // The file stays: unlinking it would let a run that opened it before and one that creates
  // it anew both hold "the" lock.
  ::close(fd_);
  fd_ = -1;
}

}  // namespace limber::results
