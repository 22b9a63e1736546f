// Encodes and writes PNG frames on a worker thread, beside rendering: the renderer hands over
// an image and goes on drawing the next frame (libpng, fast mode: about 6 ms for 1280 x 720,
// a fraction of a software-drawn frame; docs/benchmarks.md).
#pragma once

#include "frame_renderer.h"

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>

namespace limber::render {

class PngFrameWriter {
 public:
  // At most `max_queued` images wait in memory; push() blocks beyond that.
  explicit PngFrameWriter(std::size_t max_queued = 4);
  // Joins the worker (writing whatever is queued).
  ~PngFrameWriter();
  PngFrameWriter(const PngFrameWriter&) = delete;
  PngFrameWriter& operator=(const PngFrameWriter&) = delete;

  // Queues `image` to be written to `path`.
  void push(Image image, std::filesystem::path path);
  // Waits until every queued frame is written; rethrows the worker's first failure
  // (std::runtime_error naming the file).
  void finish();
  // Seconds the worker spent encoding and writing.
  double encode_seconds() const;

 private:
  void run();

  struct Job {
    Image image;
    std::filesystem::path path;
  };
  std::size_t max_queued_;
  std::deque<Job> queue_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  bool closing_ = false;
  bool busy_ = false;
  double encode_seconds_ = 0.0;
  std::exception_ptr failure_;
  std::thread worker_;
};

}  // namespace limber::render
