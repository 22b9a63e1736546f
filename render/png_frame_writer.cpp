#include "png_frame_writer.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <system_error>

namespace limber::render {
namespace {

// Writes `bytes` to `path` through a temporary "path.part". Throws std::runtime_error naming
// the file.
void write_file(const std::vector<std::uint8_t>& bytes, const std::filesystem::path& path) {
  std::filesystem::path part = path;
  part += ".part";
  std::FILE* file = std::fopen(part.c_str(), "wb");
  if (file == nullptr) {
    throw std::runtime_error("cannot write frame '" + path.string() + "': " +
                             std::generic_category().message(errno));
  }
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  const int error = errno;
  if (std::fclose(file) != 0 || !written) {
    std::remove(part.c_str());
    throw std::runtime_error("cannot write frame '" + path.string() + "': " +
                             std::generic_category().message(written ? errno : error));
  }
}

// Renames "path.part" to `path`. Throws std::runtime_error naming the file.
void commit_file(const std::filesystem::path& path) {
  std::filesystem::path part = path;
  part += ".part";
  std::error_code error;
  std::filesystem::rename(part, path, error);
  if (error) {
    throw std::runtime_error("cannot write frame '" + path.string() + "': " + error.message());
  }
}

}  // namespace

PngFrameWriter::PngFrameWriter(std::size_t workers, std::size_t max_queued,
                               const PngSettings& settings)
    : max_queued_(std::max<std::size_t>(1, max_queued)) {
  for (std::size_t w = 0; w < std::max<std::size_t>(1, workers); ++w) {
    workers_.emplace_back([this, settings] { run(settings); });
  }
}

PngFrameWriter::~PngFrameWriter() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void PngFrameWriter::push(Image image, std::filesystem::path path,
                          std::function<void(Image&)> prepare) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < max_queued_ || failure_; });
  if (failure_) std::rethrow_exception(failure_);
  queue_.push_back({std::move(image), std::move(path), std::move(prepare), pushed_++});
  changed_.notify_all();
}

void PngFrameWriter::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return written_ == pushed_ || failure_; });
  if (failure_) std::rethrow_exception(failure_);
}

double PngFrameWriter::encode_seconds() const {
  std::lock_guard lock(mutex_);
  return encode_seconds_;
}

double PngFrameWriter::prepare_seconds() const {
  std::lock_guard lock(mutex_);
  return prepare_seconds_;
}

void PngFrameWriter::run(const PngSettings& settings) {
  PngEncoder encoder(settings);
  for (;;) {
    // Next job, or leave when closing with nothing queued (or after a failure).
    Job job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return !queue_.empty() || closing_ || failure_; });
      if (failure_ || queue_.empty()) return;
      job = std::move(queue_.front());
      queue_.pop_front();
    }
    changed_.notify_all();

    // Prepare, encode and write the temporary file outside the lock, beside the other workers.
    const auto start = std::chrono::steady_clock::now();
    double prepared = 0.0;
    std::exception_ptr failure;
    try {
      if (job.prepare) job.prepare(job.image);
      prepared = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      write_file(encoder.encode(job.image), job.path);
    } catch (...) {
      failure = std::current_exception();
    }
    const double spent =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - prepared;

    // Rename in push order: wait for the frames before this one; after an earlier frame
    // failed, drop this one.
    std::unique_lock lock(mutex_);
    encode_seconds_ += spent;
    prepare_seconds_ += prepared;
    changed_.wait(lock, [&] { return written_ == job.sequence || failure_; });
    if (!failure && !failure_) {
      try {
        commit_file(job.path);
        ++written_;
      } catch (...) {
        failure = std::current_exception();
      }
    } else if (!failure) {
      std::filesystem::path part = job.path;
      std::error_code ignored;  // best effort: the failure reported is the earlier frame's
      std::filesystem::remove(part += ".part", ignored);
    }
    if (failure && !failure_) failure_ = failure;
    lock.unlock();
    changed_.notify_all();
  }
}

}  // namespace limber::render
