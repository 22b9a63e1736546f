// PNG encoding of an RGB frame in memory: 8-bit truecolour, no interlace, one IDAT chunk
// (W3C, "Portable Network Graphics (PNG) Specification", 2nd ed., 2003: sec. 5 file and chunk
// layout, 9 row filters, 10 zlib/deflate compression). The deflate stream comes from libdeflate
// (Debian package libdeflate-dev), faster than zlib at a better ratio: with the Sub filter at
// level 2 a 1280 x 720 frame of `limber render` takes about 4 ms of CPU and 81 KiB, where
// libpng's fast mode (no filter, zlib) took about 5.7 ms and 135 KiB (docs/benchmarks.md).
// The container (signature, IHDR, IDAT, IEND, CRC-32 per chunk) is written here.
#pragma once

#include "image.h"

#include <cstdint>
#include <vector>

struct libdeflate_compressor;

namespace limber::render {

// The row filter applied to every row (PNG spec. sec. 9.2): kNone stores bytes as they are,
// kSub stores each byte minus the same channel of the pixel to its left, which turns the
// frames' flat areas and smooth gradients into runs of zeros.
enum class PngFilter { kNone = 0, kSub = 1 };

struct PngSettings {
  PngFilter filter = PngFilter::kSub;
  int level = 2;  // libdeflate compression level, 0 (store) .. 12
};

// One encoder per thread: it holds libdeflate's compressor and the scratch buffers.
class PngEncoder {
 public:
  // Precondition (DEMAND): 0 <= settings.level <= 12.
  explicit PngEncoder(const PngSettings& settings = {});
  ~PngEncoder();
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  // The complete PNG file of `image`; valid until the next call.
  // Precondition (DEMAND): width, height >= 1 and image.rgb.size() == 3 * width * height.
  const std::vector<std::uint8_t>& encode(const Image& image);

 private:
  PngSettings settings_;
  libdeflate_compressor* compressor_ = nullptr;
  std::vector<std::uint8_t> scanlines_;  // filter byte + filtered row, per row
  std::vector<std::uint8_t> file_;
};

}  // namespace limber::render
