// The colour maps (color_map.h): viridis ends on matplotlib's published end colours and its
// CIE L* rises monotonically (what makes it perceptually ordered; Smith & van der Walt 2015);
// the rainbow map is the blue-to-red HSV ramp limber used before.
#include "color_map.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace limber::render {
namespace {

// CIE 1976 L* of an sRGB colour (IEC 61966-2-1 transfer curve, D65 luminance weights).
double lightness(const std::array<double, 3>& rgb) {
  auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  const double y = 0.2126 * linear(rgb[0]) + 0.7152 * linear(rgb[1]) + 0.0722 * linear(rgb[2]);
  return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

TEST(ColorMap, ViridisEndsOnThePublishedColours) {
  // matplotlib's _viridis_data[0] and [255], to the 6 digits published.
  const std::array<double, 3> lo = color_map_rgb(ColorMap::kViridis, 0.0);
  const std::array<double, 3> hi = color_map_rgb(ColorMap::kViridis, 1.0);
  const std::array<double, 3> published_lo{0.267004, 0.004874, 0.329415};
  const std::array<double, 3> published_hi{0.993248, 0.906157, 0.143936};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(lo[c], published_lo[c], 1e-6);
    EXPECT_NEAR(hi[c], published_hi[c], 1e-6);
  }
}

TEST(ColorMap, ViridisLightnessRisesMonotonically) {
  // Over 256 steps L* rises every step, from about 16 to about 92 (Smith & van der Walt's
  // design: near-linear lightness); the rainbow's falls and rises (its hue ramp is not ordered).
  double previous = -1.0;
  for (int i = 0; i < 256; ++i) {
    const double l = lightness(color_map_rgb(ColorMap::kViridis, i / 255.0));
    EXPECT_GT(l, previous) << "at entry " << i;
    previous = l;
  }
  EXPECT_NEAR(lightness(color_map_rgb(ColorMap::kViridis, 0.0)), 16.0, 2.0);
  EXPECT_NEAR(lightness(color_map_rgb(ColorMap::kViridis, 1.0)), 92.0, 2.0);
  const double blue = lightness(color_map_rgb(ColorMap::kRainbow, 0.0));
  const double cyan_green = lightness(color_map_rgb(ColorMap::kRainbow, 0.5));
  const double red = lightness(color_map_rgb(ColorMap::kRainbow, 1.0));
  EXPECT_GT(cyan_green, blue);
  EXPECT_GT(cyan_green, red);
}

TEST(ColorMap, RainbowRunsFromBlueToRed) {
  const std::array<double, 3> blue = color_map_rgb(ColorMap::kRainbow, 0.0);
  const std::array<double, 3> red = color_map_rgb(ColorMap::kRainbow, 1.0);
  // VTK's hue 0.667 is 0.002 short of pure blue: green 0.012 of full scale.
  EXPECT_NEAR(blue[0], 0.0, 1e-12);
  EXPECT_NEAR(blue[1], 0.0, 0.02);
  EXPECT_NEAR(blue[2], 1.0, 1e-12);
  EXPECT_NEAR(red[0], 1.0, 1e-12);
  EXPECT_NEAR(red[1], 0.0, 1e-12);
  EXPECT_NEAR(red[2], 0.0, 1e-12);
}

TEST(ColorMap, NamesParse) {
  EXPECT_EQ(parse_color_map("viridis"), ColorMap::kViridis);
  EXPECT_EQ(parse_color_map("rainbow"), ColorMap::kRainbow);
  EXPECT_THROW(parse_color_map("jet"), InputError);
}

}  // namespace
}  // namespace limber::render
