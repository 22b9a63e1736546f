#include "color_map.h"

#include "core/error.h"

#include <vtkLookupTable.h>

#include <algorithm>
#include <cmath>

namespace limber::render {
namespace {

// Viridis at s = 0, 1/8, ..., 1: entries 0, 32, ..., 224 and 255 of matplotlib's 256-entry
// table (Smith & van der Walt 2015, CC0). Linear interpolation between them stays within
// 0.01 of the full table, well under one 8-bit step of visible change.
constexpr std::array<std::array<double, 3>, 9> kViridis{{
    {0.267004, 0.004874, 0.329415},
    {0.282623, 0.140926, 0.457517},
    {0.229739, 0.322361, 0.545706},
    {0.172719, 0.448791, 0.557885},
    {0.127568, 0.566949, 0.550556},
    {0.157851, 0.683765, 0.501686},
    {0.369214, 0.788888, 0.382914},
    {0.678489, 0.863742, 0.189503},
    {0.993248, 0.906157, 0.143936},
}};

// HSV hue 2/3 (blue) down to 0 (red) at full saturation and value: VTK's table as limber set
// it before (SetHueRange(0.667, 0)).
std::array<double, 3> rainbow(double s) {
  const double h = 6.0 * 0.667 * (1.0 - s);  // hue in sixths of the circle
  const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
  if (h < 1.0) return {1.0, x, 0.0};
  if (h < 2.0) return {x, 1.0, 0.0};
  if (h < 3.0) return {0.0, 1.0, x};
  return {0.0, x, 1.0};
}

}  // namespace

ColorMap parse_color_map(const std::string& text) {
  if (text == "viridis") return ColorMap::kViridis;
  if (text == "rainbow") return ColorMap::kRainbow;
  throw InputError("--color-map: expected viridis or rainbow, got '" + text + "'");
}

std::array<double, 3> color_map_rgb(ColorMap map, double s) {
  s = std::clamp(s, 0.0, 1.0);
  if (map == ColorMap::kRainbow) return rainbow(s);
  const double x = s * static_cast<double>(kViridis.size() - 1);
  const auto k = std::min(static_cast<std::size_t>(x), kViridis.size() - 2);
  const double w = x - static_cast<double>(k);
  std::array<double, 3> rgb{};
  for (int c = 0; c < 3; ++c) rgb[c] = (1.0 - w) * kViridis[k][c] + w * kViridis[k + 1][c];
  return rgb;
}

void fill_lookup_table(vtkLookupTable* table, ColorMap map, double range_max) {
  constexpr int kEntries = 256;
  table->SetNumberOfTableValues(kEntries);
  table->SetTableRange(0.0, range_max);
  for (int i = 0; i < kEntries; ++i) {
    const std::array<double, 3> rgb = color_map_rgb(map, i / (kEntries - 1.0));
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  table->SetNanColor(0.6, 0.6, 0.6, 1.0);  // elements without a stress history
  // Table values set one by one: the NaN and out-of-range entries follow (vtkLookupTable.h).
  table->BuildSpecialColors();
}

}  // namespace limber::render
