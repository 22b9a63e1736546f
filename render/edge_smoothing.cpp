#include "edge_smoothing.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace limber::render {
namespace {

// A pixel's new colour, applied once every decision has been made on the original image.
struct Blend {
  std::size_t index;  // pixel index y * width + x
  std::uint8_t rgb[3];
};

bool in_any(const std::vector<PixelBox>& boxes, int x, int y) {
  for (const PixelBox& box : boxes) {
    if (box.contains(x, y)) return true;
  }
  return false;
}

}  // namespace

void smooth_edges(Image& image, const std::vector<PixelBox>& keep,
                  const EdgeSmoothingOptions& options) {
  const int w = image.width;
  const int h = image.height;
  const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  LIMBER_DEMAND(w >= 0 && h >= 0 && image.rgb.size() == 3 * count);
  if (w < 3 || h < 3) return;
  const std::uint8_t* rgb = image.rgb.data();

  // Luma 0..255 per pixel, Rec. 601 weights (0.299, 0.587, 0.114) in 1/256.
  std::vector<std::uint8_t> luma(count);
  for (std::size_t k = 0; k < count; ++k) {
    luma[k] = static_cast<std::uint8_t>(
        (77 * rgb[3 * k] + 150 * rgb[3 * k + 1] + 29 * rgb[3 * k + 2] + 128) >> 8);
  }

  // Early-exit thresholds in integers: a pixel is processed when its luma range is at least
  // `hard` and at least relative_contrast x its largest luma (in 1/256).
  const int hard = static_cast<int>(std::ceil(255.0 * options.hard_contrast));
  const int relative = static_cast<int>(std::lround(256.0 * options.relative_contrast));
  const float subpixel_limit = static_cast<float>(options.subpixel_limit);
  std::vector<Blend> blends;
  std::vector<std::uint8_t> candidate(w);
  for (int y = 1; y + 1 < h; ++y) {
    const std::uint8_t* up = luma.data() + static_cast<std::size_t>(y - 1) * w;
    const std::uint8_t* row = up + w;
    const std::uint8_t* down = row + w;

    // Early exit, decided for the whole row at once: flag the pixels whose luma range over
    // themselves and their 4 neighbours reaches both thresholds.
    for (int x = 1; x + 1 < w; ++x) {
      const int hi = std::max(std::max(std::max(row[x], up[x]), std::max(down[x], row[x - 1])),
                              row[x + 1]);
      const int lo = std::min(std::min(std::min(row[x], up[x]), std::min(down[x], row[x - 1])),
                              row[x + 1]);
      const int range = hi - lo;
      candidate[x] = range >= hard && 256 * range >= relative * hi;
    }

    for (int x = 1; x + 1 < w; ++x) {
      // Skip 8 flags at a time: most rows hold only a few edge pixels.
      if (x + 8 < w) {
        std::uint64_t flags = 0;
        std::memcpy(&flags, candidate.data() + x, sizeof flags);
        if (flags == 0) {
          x += 7;
          continue;
        }
      }
      if (!candidate[x] || in_any(keep, x, y)) continue;
      const int c = row[x];
      const int n = up[x];
      const int s = down[x];
      const int west = row[x - 1];
      const int east = row[x + 1];
      const int range = std::max({c, n, s, west, east}) - std::min({c, n, s, west, east});

      // Edge direction from second differences of the 3 x 3 lumas: across rows (the edge runs
      // along x) or across columns (it runs along y).
      const int nw = up[x - 1];
      const int ne = up[x + 1];
      const int sw = down[x - 1];
      const int se = down[x + 1];
      const int across_rows =
          2 * std::abs(n + s - 2 * c) + std::abs(nw + sw - 2 * west) + std::abs(ne + se - 2 * east);
      const int across_cols =
          2 * std::abs(west + east - 2 * c) + std::abs(nw + ne - 2 * n) + std::abs(sw + se - 2 * s);
      const bool along_x = across_rows >= across_cols;

      // Partner: the neighbour across the edge with the larger luma step (ties: north, west).
      const int before = along_x ? n : west;
      const int after = along_x ? s : east;
      const bool towards_after = std::abs(after - c) > std::abs(before - c);
      const int p = towards_after ? after : before;
      const std::ptrdiff_t partner = (along_x ? w : 1) * (towards_after ? 1 : -1);
      const std::ptrdiff_t along = along_x ? 1 : w;
      const int position = along_x ? x : y;
      const int length = along_x ? w : h;

      // Search both ways along the edge for the first pixel pair whose average luma differs
      // from the pair (c, p) by a quarter of the step |p - c| (sums of two lumas throughout).
      const std::ptrdiff_t centre = static_cast<std::ptrdiff_t>(y) * w + x;
      const int pair = c + p;
      const int step = std::abs(p - c);
      auto search = [&](int direction, int& end_delta) {
        end_delta = 0;
        int k = 1;
        for (; k <= options.search_steps; ++k) {
          const int at = position + direction * k;
          if (at < 0 || at >= length) break;
          const std::ptrdiff_t i = centre + direction * k * along;
          end_delta = luma[i] + luma[i + partner] - pair;
          if (2 * std::abs(end_delta) >= step) break;
        }
        return k;
      };
      int end_before = 0;
      int end_after = 0;
      const int d_before = search(-1, end_before);
      const int d_after = search(+1, end_after);

      // Edge blend: only a pixel on the side of the edge opposite to the nearer end's step
      // moves towards its partner, the more the nearer it is to that end (0 .. 1/2).
      const int d = std::min(d_before, d_after);
      const int end = d_before < d_after ? end_before : end_after;
      const bool centre_darker = 2 * c < pair;
      float offset = 0.0f;
      if ((end < 0) != centre_darker) {
        offset = 0.5f - static_cast<float>(d) / static_cast<float>(d_before + d_after);
      }

      // Subpixel blend: contrast of the pixel with the weighted 3 x 3 average, smoothstep'd
      // and squared, at most `subpixel_limit`.
      const float average =
          (2.0f * static_cast<float>(n + s + west + east) + static_cast<float>(nw + ne + sw + se)) /
          12.0f;
      const float contrast = std::min(1.0f, std::abs(average - static_cast<float>(c)) /
                                                static_cast<float>(std::max(range, 1)));
      const float smooth = (3.0f - 2.0f * contrast) * contrast * contrast;
      offset = std::max(offset, smooth * smooth * subpixel_limit);
      if (offset <= 0.0f) continue;

      // New colour: the original one moved `offset` of the way to the partner's.
      Blend blend{static_cast<std::size_t>(centre), {}};
      const std::uint8_t* from = rgb + 3 * centre;
      const std::uint8_t* to = rgb + 3 * (centre + partner);
      for (int ch = 0; ch < 3; ++ch) {
        const float value = static_cast<float>(from[ch]) +
                            offset * (static_cast<float>(to[ch]) - static_cast<float>(from[ch]));
        blend.rgb[ch] = static_cast<std::uint8_t>(value + 0.5f);
      }
      blends.push_back(blend);
    }
  }

  // Apply the blends (decided on the original image, so their order does not matter).
  for (const Blend& blend : blends) {
    std::copy(blend.rgb, blend.rgb + 3, image.rgb.begin() + 3 * blend.index);
  }
}

}  // namespace limber::render
