#include "png_frame_writer.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPointData.h>

#include <chrono>
#include <cstring>
#include <stdexcept>

namespace limber::render {
namespace {

// Writes one RGB image as PNG (compression level 1: fast, files ~2x level 6).
void write_png(const Image& image, const std::filesystem::path& path) {
  // VTK images are stored bottom-up: flip rows while copying.
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* target = static_cast<std::uint8_t*>(data->GetScalarPointer());
  const std::size_t row = static_cast<std::size_t>(image.width) * 3;
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(target + row * (image.height - 1 - y), image.rgb.data() + row * y, row);
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetCompressionLevel(1);
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0) {
    throw std::runtime_error("cannot write frame '" + path.string() + "'");
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
