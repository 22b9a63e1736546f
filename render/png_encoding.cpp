#include "png_encoding.h"

#include "core/error.h"

#include <libdeflate.h>

#include <cstring>
#include <new>

namespace limber::render {
namespace {

// Appends `count` bytes.
void put_bytes(std::vector<std::uint8_t>& out, const void* bytes, std::size_t count) {
  const std::size_t at = out.size();
  out.resize(at + count);
  std::memcpy(out.data() + at, bytes, count);
}

// Appends a 4-byte big-endian integer (PNG's byte order, spec. sec. 7.1).
void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  const std::uint8_t bytes[4] = {static_cast<std::uint8_t>(value >> 24),
                                 static_cast<std::uint8_t>(value >> 16),
                                 static_cast<std::uint8_t>(value >> 8),
                                 static_cast<std::uint8_t>(value)};
  put_bytes(out, bytes, 4);
}

// Closes the chunk whose type starts at `start`: writes its data length before the type and
// appends the CRC-32 of type and data (spec. sec. 5.3).
void close_chunk(std::vector<std::uint8_t>& out, std::size_t start) {
  const auto length = static_cast<std::uint32_t>(out.size() - start - 4);
  const std::uint8_t be[4] = {static_cast<std::uint8_t>(length >> 24),
                              static_cast<std::uint8_t>(length >> 16),
                              static_cast<std::uint8_t>(length >> 8),
                              static_cast<std::uint8_t>(length)};
  std::memcpy(out.data() + start - 4, be, 4);
  put_u32(out, libdeflate_crc32(0, out.data() + start, out.size() - start));
}

// Opens a chunk: a length placeholder and the 4-letter type; returns where the type starts.
std::size_t open_chunk(std::vector<std::uint8_t>& out, const char (&type)[5]) {
  put_u32(out, 0);
  const std::size_t start = out.size();
  put_bytes(out, type, 4);
  return start;
}

}  // namespace

PngEncoder::PngEncoder(const PngSettings& settings) : settings_(settings) {
  LIMBER_DEMAND(settings.level >= 0 && settings.level <= 12);
  compressor_ = libdeflate_alloc_compressor(settings.level);
  if (compressor_ == nullptr) throw std::bad_alloc();
}

PngEncoder::~PngEncoder() { libdeflate_free_compressor(compressor_); }

const std::vector<std::uint8_t>& PngEncoder::encode(const Image& image) {
  LIMBER_DEMAND(image.width >= 1 && image.height >= 1 &&
                image.rgb.size() == 3 * static_cast<std::size_t>(image.width) * image.height);
  const std::size_t row = 3 * static_cast<std::size_t>(image.width);

  // Scanlines: the filter type byte, then the filtered row (sec. 9.2; Sub's byte left of the
  // first pixel is 0).
  scanlines_.resize((row + 1) * image.height);
  for (int y = 0; y < image.height; ++y) {
    std::uint8_t* out = scanlines_.data() + y * (row + 1);
    const std::uint8_t* in = image.rgb.data() + y * row;
    out[0] = static_cast<std::uint8_t>(settings_.filter);
    ++out;
    if (settings_.filter == PngFilter::kNone) {
      std::memcpy(out, in, row);
    } else {
      std::memcpy(out, in, 3);
      for (std::size_t k = 3; k < row; ++k) out[k] = static_cast<std::uint8_t>(in[k] - in[k - 3]);
    }
  }

  // Signature (sec. 5.2).
  file_.clear();
  static constexpr std::uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  put_bytes(file_, kSignature, 8);

  // IHDR: size, 8 bits per channel, colour type 2 (RGB), deflate, adaptive filtering method 0,
  // no interlace (sec. 11.2.2).
  std::size_t chunk = open_chunk(file_, "IHDR");
  put_u32(file_, static_cast<std::uint32_t>(image.width));
  put_u32(file_, static_cast<std::uint32_t>(image.height));
  static constexpr std::uint8_t kFormat[5] = {8, 2, 0, 0, 0};
  put_bytes(file_, kFormat, 5);
  close_chunk(file_, chunk);

  // IDAT: the zlib stream of all scanlines, compressed straight into the file buffer.
  chunk = open_chunk(file_, "IDAT");
  const std::size_t bound =
      libdeflate_zlib_compress_bound(compressor_, scanlines_.size());
  const std::size_t data = file_.size();
  file_.resize(data + bound);
  const std::size_t packed = libdeflate_zlib_compress(compressor_, scanlines_.data(),
                                                      scanlines_.size(), file_.data() + data, bound);
  LIMBER_DEMAND(packed > 0);  // the bound is always enough
  file_.resize(data + packed);
  close_chunk(file_, chunk);

  // IEND (sec. 11.2.5).
  close_chunk(file_, open_chunk(file_, "IEND"));
  return file_;
}

}  // namespace limber::render
