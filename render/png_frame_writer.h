// Encodes and writes PNG frames on worker threads, beside rendering: the renderer hands over
// an image and goes on drawing the next frame (png_encoding.h: about 4 ms of CPU for 1280 x 720,
// a fraction of a software-drawn frame; docs/benchmarks.md).
//
// Memory is bounded: at most `max_queued` images wait, plus one per worker being encoded.
// Files appear in frame order and complete: each is written to "NAME.part" and renamed, and
// frame k + 1 is renamed only after frame k, so an interrupted render leaves the first frames,
// never a gap or a truncated file. After a failure no later frame is written; the failure
// (naming the file) is rethrown by the next push() or by finish().
#pragma once

#include "image.h"
#include "png_encoding.h"

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace limber::render {

class PngFrameWriter {
 public:
  // `workers` encoder threads (at least 1); push() blocks while `max_queued` images wait.
  explicit PngFrameWriter(std::size_t workers = 2, std::size_t max_queued = 4,
                          const PngSettings& settings = {});
  // Writes whatever is queued (unless a frame failed), then joins the workers.
  ~PngFrameWriter();
  PngFrameWriter(const PngFrameWriter&) = delete;
  PngFrameWriter& operator=(const PngFrameWriter&) = delete;

  // Queues `image` to be written to `path`, after every frame pushed before it; `prepare`, when
  // given, runs on the image first, on the worker (the deferred CPU FXAA,
  // FrameRenderer::render_deferred). Rethrows a worker's failure (std::runtime_error naming the
  // file) once one has happened.
  void push(Image image, std::filesystem::path path, std::function<void(Image&)> prepare = {});
  // Waits until every queued frame is written; rethrows the first failure.
  void finish();
  // Seconds the workers spent encoding and writing, and in `prepare` steps, summed over workers.
  double encode_seconds() const;
  double prepare_seconds() const;

 private:
  void run(const PngSettings& settings);

  struct Job {
    Image image;
    std::filesystem::path path;
    std::function<void(Image&)> prepare;
    long sequence = 0;  // push order
  };
  std::size_t max_queued_;
  std::deque<Job> queue_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  long pushed_ = 0;   // frames pushed
  long written_ = 0;  // frames renamed into place: the next one to rename has this sequence
  bool closing_ = false;
  double encode_seconds_ = 0.0;
  double prepare_seconds_ = 0.0;
  std::exception_ptr failure_;
  std::vector<std::thread> workers_;
};

}  // namespace limber::render
