#include "edge_smoothing.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

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

// Luma 0..255 per pixel, Rec. 601 weights (0.299, 0.587, 0.114) in 1/256.
std::vector<std::uint8_t> luma_of(const Image& image) {
  const std::size_t count = image.rgb.size() / 3;
  const std::uint8_t* rgb = image.rgb.data();
  std::vector<std::uint8_t> luma(count);
  for (std::size_t k = 0; k < count; ++k) {
    luma[k] = static_cast<std::uint8_t>(
        (77 * rgb[3 * k] + 150 * rgb[3 * k + 1] + 29 * rgb[3 * k + 2] + 128) >> 8);
  }
  return luma;
}

// The early-exit thresholds in integers: a pixel is processed when its luma range is at least
// `hard` and at least `relative` / 256 of its largest luma.
struct ContrastThresholds {
  int hard;
  int relative;
};

// Early exit, decided for a whole row at once: flags the pixels whose luma range over
// themselves and their 4 neighbours reaches both thresholds.
void flag_candidates(const std::uint8_t* up, const std::uint8_t* row, const std::uint8_t* down,
                     int w, ContrastThresholds thresholds, std::vector<std::uint8_t>& candidate) {
  for (int x = 1; x + 1 < w; ++x) {
    const int hi = std::max(std::max(std::max(row[x], up[x]), std::max(down[x], row[x - 1])),
                            row[x + 1]);
    const int lo = std::min(std::min(std::min(row[x], up[x]), std::min(down[x], row[x - 1])),
                            row[x + 1]);
    const int range = hi - lo;
    candidate[x] = range >= thresholds.hard && 256 * range >= thresholds.relative * hi;
  }
}

// The lumas of a pixel (c) and its 8 neighbours.
struct Neighbourhood {
  int c, n, s, west, east, nw, ne, sw, se;
};

Neighbourhood neighbourhood(const std::uint8_t* up, const std::uint8_t* row,
                            const std::uint8_t* down, int x) {
  return {row[x],    up[x],     down[x],     row[x - 1], row[x + 1],
          up[x - 1], up[x + 1], down[x - 1], down[x + 1]};
}

// The neighbour across the edge the pixel blends towards (an offset in pixels) and the edge
// blend's share of the way to it.
struct EdgeBlend {
  std::ptrdiff_t partner;
  float offset;
};

// FXAA's edge blend of the pixel (x, y) of a w x h luma image.
EdgeBlend edge_blend(const std::uint8_t* luma, int w, int h, int x, int y,
                     const Neighbourhood& p, int search_steps) {
  // Edge direction from second differences of the 3 x 3 lumas: across rows (the edge runs
  // along x) or across columns (it runs along y).
  const int across_rows = 2 * std::abs(p.n + p.s - 2 * p.c) +
                          std::abs(p.nw + p.sw - 2 * p.west) + std::abs(p.ne + p.se - 2 * p.east);
  const int across_cols = 2 * std::abs(p.west + p.east - 2 * p.c) +
                          std::abs(p.nw + p.ne - 2 * p.n) + std::abs(p.sw + p.se - 2 * p.s);
  const bool along_x = across_rows >= across_cols;

  // Partner: the neighbour across the edge with the larger luma step (ties: north, west).
  const int before = along_x ? p.n : p.west;
  const int after = along_x ? p.s : p.east;
  const bool towards_after = std::abs(after - p.c) > std::abs(before - p.c);
  const int partner_luma = towards_after ? after : before;
  const std::ptrdiff_t partner = (along_x ? w : 1) * (towards_after ? 1 : -1);
  const std::ptrdiff_t along = along_x ? 1 : w;
  const int position = along_x ? x : y;
  const int length = along_x ? w : h;

  // Search both ways along the edge for the first pixel pair whose average luma differs
  // from the pair (c, partner) by a quarter of the step between them (sums of two lumas).
  const std::ptrdiff_t centre = static_cast<std::ptrdiff_t>(y) * w + x;
  const int pair = p.c + partner_luma;
  const int step = std::abs(partner_luma - p.c);
  auto search = [&](int direction, int& end_delta) {
    end_delta = 0;
    int k = 1;
    for (; k <= search_steps; ++k) {
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

  // Only a pixel on the side of the edge opposite to the nearer end's step moves towards its
  // partner, the more the nearer it is to that end (0 .. 1/2).
  const int d = std::min(d_before, d_after);
  const int end = d_before < d_after ? end_before : end_after;
  const bool centre_darker = 2 * p.c < pair;
  float offset = 0.0f;
  if ((end < 0) != centre_darker) {
    offset = 0.5f - static_cast<float>(d) / static_cast<float>(d_before + d_after);
  }
  return {partner, offset};
}

// Subpixel blend: contrast of the pixel with the weighted 3 x 3 average, smoothstep'd and
// squared, at most `subpixel_limit`.
float subpixel_offset(const Neighbourhood& p, float subpixel_limit) {
  const int range = std::max({p.c, p.n, p.s, p.west, p.east}) -
                    std::min({p.c, p.n, p.s, p.west, p.east});
  const float average = (2.0f * static_cast<float>(p.n + p.s + p.west + p.east) +
                         static_cast<float>(p.nw + p.ne + p.sw + p.se)) /
                        12.0f;
  const float contrast = std::min(1.0f, std::abs(average - static_cast<float>(p.c)) /
                                            static_cast<float>(std::max(range, 1)));
  const float smooth = (3.0f - 2.0f * contrast) * contrast * contrast;
  return smooth * smooth * subpixel_limit;
}

// New colour of pixel `centre`: the original one moved `offset` of the way to the partner's.
Blend blend_towards(const std::uint8_t* rgb, std::ptrdiff_t centre, std::ptrdiff_t partner,
                    float offset) {
  Blend blend{static_cast<std::size_t>(centre), {}};
  const std::uint8_t* from = rgb + 3 * centre;
  const std::uint8_t* to = rgb + 3 * (centre + partner);
  for (int ch = 0; ch < 3; ++ch) {
    const float value = static_cast<float>(from[ch]) +
                        offset * (static_cast<float>(to[ch]) - static_cast<float>(from[ch]));
    blend.rgb[ch] = static_cast<std::uint8_t>(value + 0.5f);
  }
  return blend;
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
  const std::vector<std::uint8_t> luma = luma_of(image);

  const ContrastThresholds thresholds{
      static_cast<int>(std::ceil(255.0 * options.hard_contrast)),
      static_cast<int>(std::lround(256.0 * options.relative_contrast))};
  const float subpixel_limit = static_cast<float>(options.subpixel_limit);
  std::vector<Blend> blends;
  std::vector<std::uint8_t> candidate(w);
  for (int y = 1; y + 1 < h; ++y) {
    const std::uint8_t* up = luma.data() + static_cast<std::size_t>(y - 1) * w;
    const std::uint8_t* row = up + w;
    const std::uint8_t* down = row + w;
    flag_candidates(up, row, down, w, thresholds, candidate);
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
      // The larger of the edge blend and the subpixel blend, towards the edge's partner.
      const Neighbourhood p = neighbourhood(up, row, down, x);
      const EdgeBlend edge = edge_blend(luma.data(), w, h, x, y, p, options.search_steps);
      const float offset = std::max(edge.offset, subpixel_offset(p, subpixel_limit));
      if (offset <= 0.0f) continue;
      blends.push_back(
          blend_towards(rgb, static_cast<std::ptrdiff_t>(y) * w + x, edge.partner, offset));
    }
  }

  // Apply the blends (decided on the original image, so their order does not matter).
  for (const Blend& blend : blends) {
    std::copy(blend.rgb, blend.rgb + 3, image.rgb.begin() + 3 * blend.index);
  }
}

}  // namespace limber::render
