// FXAA on the CPU (render/edge_smoothing.*): a flat image is left alone, an aliased straight
// edge comes out closer to the exact pixel coverage (a supersampled reference), and kept boxes
// and the frame border are untouched.
#include "edge_smoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <ostream>

namespace limber::render {
namespace {

constexpr int kSize = 64;
constexpr double kDark = 40.0;    // grey level below the line
constexpr double kLight = 220.0;  // grey level above it

// A grey image whose pixel (x, y) has the value `level(x, y)`.
template <typename Level>
Image grey_image(Level level) {
  Image image;
  image.width = image.height = kSize;
  image.rgb.resize(3 * kSize * kSize);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const auto v = static_cast<std::uint8_t>(std::lround(level(x, y)));
      for (int c = 0; c < 3; ++c) image.rgb[3 * (y * kSize + x) + c] = v;
    }
  }
  return image;
}

// The straight line through the image centre at `angle` [rad] from the x axis: signed distance
// of (x, y) from it, positive on the dark side.
double side(double angle, double x, double y) {
  return -std::sin(angle) * (x - 0.5 * kSize) + std::cos(angle) * (y - 0.5 * kSize);
}

// Aliased: each pixel takes the colour of its centre, as a rasteriser without anti-aliasing.
Image aliased_edge(double angle) {
  return grey_image(
      [&](int x, int y) { return side(angle, x + 0.5, y + 0.5) > 0 ? kDark : kLight; });
}

// Reference: the area fraction of each pixel on either side, from 32 x 32 samples per pixel.
Image covered_edge(double angle) {
  return grey_image([&](int x, int y) {
    constexpr int n = 32;
    int dark = 0;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        if (side(angle, x + (i + 0.5) / n, y + (j + 0.5) / n) > 0) ++dark;
      }
    }
    const double f = static_cast<double>(dark) / (n * n);
    return f * kDark + (1.0 - f) * kLight;
  });
}

// Sum of |a - b| over the first channel, away from the 2-pixel frame border (left as is).
double total_error(const Image& a, const Image& b) {
  double sum = 0.0;
  for (int y = 2; y < kSize - 2; ++y) {
    for (int x = 2; x < kSize - 2; ++x) sum += std::abs(a.pixel(x, y)[0] - b.pixel(x, y)[0]);
  }
  return sum;
}

TEST(FrameEdgeSmoothing, FlatImageIsUnchanged) {
  Image image = grey_image([](int, int) { return 128.0; });
  const Image before = image;
  smooth_edges(image);
  EXPECT_EQ(image.rgb, before.rgb);
}

// An edge at `angle` [rad] from the x axis and the largest ratio of smoothed to aliased error.
struct EdgeCase {
  double angle;
  double max_error_ratio;
};

void PrintTo(const EdgeCase& edge, std::ostream* out) {
  *out << edge.angle << "rad_max" << edge.max_error_ratio;
}

class FrameAliasedEdge : public ::testing::TestWithParam<EdgeCase> {};

TEST_P(FrameAliasedEdge, ComesOutCloserToTheExactCoverage) {
  const EdgeCase edge = GetParam();
  Image image = aliased_edge(edge.angle);
  const Image reference = covered_edge(edge.angle);
  const double aliased = total_error(image, reference);
  smooth_edges(image);
  const double smoothed = total_error(image, reference);
  EXPECT_LT(smoothed, edge.max_error_ratio * aliased)
      << "aliased " << aliased << ", smoothed " << smoothed;
}

// FXAA turns each step of the staircase into a linear ramp between the step's ends (Lottes
// 2009), which matches the coverage the better the longer the steps: within 0.35 rad of an
// axis (steps of about 3 pixels and longer) the error at least halves (measured: 0.31 to 0.38
// of the aliased one); at 0.5 to 0.7 rad (steps of 1 to 2 pixels) it drops by a quarter at
// least (measured: 0.48 to 0.63). At exactly 45 degrees (steps of one pixel) FXAA hardly
// helps (measured: 0.95), so that angle is not asked for.
INSTANTIATE_TEST_SUITE_P(
    Angles, FrameAliasedEdge,
    ::testing::Values(EdgeCase{0.05, 0.5}, EdgeCase{0.12, 0.5}, EdgeCase{-0.12, 0.5},
                      EdgeCase{0.35, 0.5}, EdgeCase{M_PI / 2 - 0.12, 0.5},
                      EdgeCase{M_PI / 2 + 0.35, 0.5}, EdgeCase{0.5, 0.75}, EdgeCase{0.7, 0.75}));

TEST(FrameEdgeSmoothing, KeptBoxesAndTheBorderAreLeftAlone) {
  Image image = aliased_edge(0.12);
  const Image before = image;
  // Left half kept: nothing changes there; the right half is smoothed.
  smooth_edges(image, {PixelBox{0, 0, kSize / 2, kSize}});
  int changed_left = 0, changed_right = 0, changed_border = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if (image.pixel(x, y) == before.pixel(x, y)) continue;
      (x < kSize / 2 ? changed_left : changed_right) += 1;
      if (x == 0 || y == 0 || x == kSize - 1 || y == kSize - 1) ++changed_border;
    }
  }
  EXPECT_EQ(changed_left, 0);
  EXPECT_GT(changed_right, 10);
  EXPECT_EQ(changed_border, 0);
}

}  // namespace
}  // namespace limber::render
