// An 8-bit RGB frame in memory, as read back from the renderer and written to PNG.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace limber::render {

// An 8-bit RGB image, rows from the top.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3

  // Pixel at column x (from the left) and row y (from the top).
  std::array<int, 3> pixel(int x, int y) const {
    const std::size_t k = 3 * (static_cast<std::size_t>(y) * width + x);
    return {rgb[k], rgb[k + 1], rgb[k + 2]};
  }
};

// A rectangle of pixels: columns [x0, x1), rows [y0, y1) from the top.
struct PixelBox {
  int x0 = 0;
  int y0 = 0;
  int x1 = 0;
  int y1 = 0;
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

}  // namespace limber::render
