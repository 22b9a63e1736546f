// Option parsing and the time range: exact integer/sample arithmetic, InputError on bad input.
#include "render_job.h"
#include "render_options.h"

#include "core/error.h"
#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

namespace limber::render {
namespace {

TEST(RenderOptions, ParsesFrameSizes) {
  int w = 0, h = 0;
  parse_frame_size("1280x720", w, h);
  EXPECT_EQ(w, 1280);
  EXPECT_EQ(h, 720);
  parse_frame_size(" 64X48 ", w, h);
  EXPECT_EQ(w, 64);
  EXPECT_EQ(h, 48);
}

TEST(RenderOptions, ImpossibleSizesAreInputErrors) {
  int w = 0, h = 0;
  for (const char* bad : {"0x720", "1280", "1280x-5", "axb", "100000x100000", "8x8", "1280x720x3"}) {
    EXPECT_THROW(parse_frame_size(bad, w, h), InputError) << bad;
  }
  RenderOptions options;
  options.width = 0;
  EXPECT_THROW(validate(options), InputError);
  options = RenderOptions{};
  options.fps = 0.0;
  EXPECT_THROW(validate(options), InputError);
  options = RenderOptions{};
  options.t0 = 2.0;
  options.t1 = 1.0;
  EXPECT_THROW(validate(options), InputError);
  EXPECT_THROW(parse_camera_preset("diagonal"), InputError);
  EXPECT_EQ(parse_camera_preset("top"), CameraPreset::kTop);
}

TEST(RenderOptions, ParsesColourModes) {
  EXPECT_EQ(RenderOptions{}.color, ColorBy::kDeflection);
  EXPECT_EQ(parse_color_by("deflection"), ColorBy::kDeflection);
  EXPECT_EQ(parse_color_by("von_mises"), ColorBy::kVonMises);
  for (const char* bad : {"", "vonmises", "stress", "Von_Mises"}) {
    EXPECT_THROW(parse_color_by(bad), InputError) << bad;
  }
}

TEST(RenderOptions, ParsesAntiAliasingModes) {
  EXPECT_EQ(RenderOptions{}.anti_aliasing, AntiAliasing::kFxaa);
  EXPECT_EQ(parse_anti_aliasing("fxaa"), AntiAliasing::kFxaa);
  EXPECT_EQ(parse_anti_aliasing("gl-fxaa"), AntiAliasing::kGlFxaa);
  EXPECT_EQ(parse_anti_aliasing("none"), AntiAliasing::kNone);
  for (const char* bad : {"", "FXAA", "msaa", "gl"}) {
    EXPECT_THROW(parse_anti_aliasing(bad), InputError) << bad;
  }
}

TEST(RenderOptions, FrameTimesCoverTheRangeAtTheFrameRate) {
  // [0, 1] s at 10 frames/s: 11 frames, the last exactly at t1.
  const std::vector<double> times = frame_times(0.0, 1.0, 10.0);
  ASSERT_EQ(times.size(), 11u);
  EXPECT_DOUBLE_EQ(times.back(), 1.0);
  EXPECT_EQ(frame_times(0.2, 0.2, 30.0).size(), 1u);
}

TEST(RenderOptions, TimeRangeIsClippedAndAnEmptyOneIsAnInputError) {
  const auto dir = testing::fresh_directory("range");
  testing::write_test_results(dir, testing::TestScene{});  // samples over [0, 1] s
  const Results results = read_results(dir);
  RenderOptions options;
  options.t0 = -1.0;
  options.t1 = 0.5;
  EXPECT_EQ(resolve_time_range(results, options), std::make_pair(0.0, 0.5));
  options.t0 = 2.0;
  options.t1 = 3.0;
  EXPECT_THROW(resolve_time_range(results, options), InputError);
}

}  // namespace
}  // namespace limber::render
