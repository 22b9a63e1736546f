#include "png_frame_writer.h"

#include <png.h>

#include <chrono>
#include <cstring>
#include <stdexcept>

namespace limber::render {
namespace {

// Writes one RGB image as PNG through libpng's simplified API. PNG_IMAGE_FLAG_FAST (no row
// filtering, fast deflate) encodes a 1280 x 720 frame in about 6 ms where vtkPNGWriter at
// compression level 1 took about 26 ms (libpng's adaptive filtering tries five filters per
// row); the files are about a third larger (docs/benchmarks.md).
void write_png(const Image& image, const std::filesystem::path& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  png.flags = PNG_IMAGE_FLAG_FAST;
  // Rows from the top, tightly packed (row stride 0: width * 3).
  if (png_image_write_to_file(&png, path.c_str(), 0, image.rgb.data(), 0, nullptr) == 0) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw std::runtime_error("cannot write frame '" + path.string() + "': " + reason);
  }
}

}  // namespace

PngFrameWriter::PngFrameWriter(std::size_t max_queued)
    : max_queued_(max_queued), worker_([this] { run(); }) {}

PngFrameWriter::~PngFrameWriter() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void PngFrameWriter::push(Image image, std::filesystem::path path) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < max_queued_ || failure_; });
  if (failure_) return;  // reported by finish()
  queue_.push_back({std::move(image), std::move(path)});
  changed_.notify_all();
}

void PngFrameWriter::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return (queue_.empty() && !busy_) || failure_; });
  if (failure_) std::rethrow_exception(failure_);
}

double PngFrameWriter::encode_seconds() const {
  std::lock_guard lock(mutex_);
  return encode_seconds_;
}

void PngFrameWriter::run() {
  for (;;) {
    // Next job, or leave when closing with nothing queued.
    Job job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
      if (queue_.empty()) return;
      job = std::move(queue_.front());
      queue_.pop_front();
      busy_ = true;
    }
    changed_.notify_all();

    // Encode outside the lock; keep the first failure.
    const auto start = std::chrono::steady_clock::now();
    std::exception_ptr failure;
    try {
      write_png(job.image, job.path);
    } catch (...) {
      failure = std::current_exception();
    }
    const double spent =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    {
      std::lock_guard lock(mutex_);
      encode_seconds_ += spent;
      busy_ = false;
      if (failure && !failure_) failure_ = failure;
    }
    changed_.notify_all();
  }
}

}  // namespace limber::render
