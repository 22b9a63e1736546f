// Pixels of a known scene rendered offscreen with DISPLAY unset: background colour, the red box
// where the camera projects its centre, the colour bar, the plate moving between frames, the
// anti-aliasing modes, and no VTK warning (in particular no "GLEW could not be initialized").
#include "frame_renderer.h"

#include "scene.h"
#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkStringOutputWindow.h>

#include <cmath>
#include <cstdlib>

namespace limber::render {
namespace {

using testing::TestScene;

constexpr int kWidth = 320;
constexpr int kHeight = 240;

// Frames are 8-bit: a flat colour comes back within 1 of round(255 c) (rounding of the blend).
constexpr int kColorTolerance = 1;

bool is_background(const std::array<int, 3>& p) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(p[c] - static_cast<int>(std::lround(255 * kBackgroundColor[c]))) > kColorTolerance)
      return false;
  }
  return true;
}

class FrameRendererTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Headless: no X display may be needed.
    unsetenv("DISPLAY");
    vtkOutputWindow::SetInstance(messages_);
  }
  void TearDown() override { vtkOutputWindow::SetInstance(nullptr); }

  Results scene_results(const TestScene& scene, const std::string& name) {
    const auto dir = testing::fresh_directory(name);
    testing::write_test_results(dir, scene);
    return read_results(dir);
  }

  RenderOptions options(CameraPreset camera) const {
    RenderOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.camera = camera;
    return o;
  }

  vtkNew<vtkStringOutputWindow> messages_;
};

TEST_F(FrameRendererTest, BackgroundBoxAndColorBar) {
  const Results results = scene_results(TestScene{}, "pixels");
  FrameRenderer renderer(results, options(CameraPreset::kIso), 0.0, 1.0);
  const Image image = renderer.render(0.5);
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);

  // Background in the top corners (nothing drawn there).
  EXPECT_TRUE(is_background(image.pixel(kWidth - 2, 1)));
  EXPECT_TRUE(is_background(image.pixel(1, 1)));

  // The red box (0.85, 0.1, 0.1) where its centre projects: red dominates after shading.
  const Eigen::Vector2d box = renderer.project(testing::box_position(0.5));
  const auto p = image.pixel(static_cast<int>(box.x()), static_cast<int>(box.y()));
  EXPECT_GT(p[0], 80) << p[0] << " " << p[1] << " " << p[2];
  EXPECT_GT(p[0], 3 * p[1]);
  EXPECT_GT(p[0], 3 * p[2]);

  // Colour bar: both ends of the viridis table appear in its box (dark purple (68, 1, 84) and
  // yellow (253, 231, 37) in 8 bits; 20 levels cover the ends' neighbouring table entries).
  int purple = 0, yellow = 0;
  for (int y = static_cast<int>((1.0 - kColorBarBox[1] - kColorBarBox[3]) * kHeight);
       y < static_cast<int>((1.0 - kColorBarBox[1]) * kHeight); ++y) {
    for (int x = static_cast<int>(kColorBarBox[0] * kWidth); x < kWidth; ++x) {
      const auto c = image.pixel(x, y);
      auto near = [&](int r, int g, int b) {
        return std::abs(c[0] - r) < 20 && std::abs(c[1] - g) < 20 && std::abs(c[2] - b) < 20;
      };
      purple += near(68, 1, 84);
      yellow += near(253, 231, 37);
    }
  }
  EXPECT_GT(purple, 10);
  EXPECT_GT(yellow, 10);

  // No VTK message at all (GLEW, shaders, framebuffers).
  EXPECT_EQ(std::string(messages_->GetOutput()), "");
  // Colour range = largest |u| over the run: the beam tip, B sqrt(sin^2 + cos^2) = B = 0.05 m,
  // or the plate centre, sqrt(A^2 + (A/2 * 0.5)^2) at the samples' peak; the larger one.
  const TestScene scene;
  double umax = 0.0;
  for (int k = 0; k < scene.samples; ++k) {
    const double t = scene.duration * k / (scene.samples - 1);
    umax = std::max(umax, testing::beam_displacement(scene, 1.0, t).norm());
    for (int i = 0; i <= scene.nx; ++i) {
      for (int j = 0; j <= scene.ny; ++j) {
        umax = std::max(umax, testing::plate_displacement(scene, scene.lx * i / scene.nx,
                                                          scene.ly * j / scene.ny, t)
                                  .norm());
      }
    }
  }
  // Same arithmetic up to summation order: 1e-12 relative.
  EXPECT_NEAR(renderer.color_range_max(), umax, 1e-12 * umax);
}

TEST_F(FrameRendererTest, ColorBarLabelsAndTitleKeepClearOfTheBar) {
  // At the main job's frame size: in the colour bar's box, the bar's coloured columns and the
  // labels' dark columns are at least 3 px apart, and the title and the five labels are six
  // separate bands of rows (the title does not run into the top label).
  const Results results = scene_results(TestScene{}, "bar_labels");
  RenderOptions o = options(CameraPreset::kFront);
  o.width = 1280;
  o.height = 720;
  o.anti_aliasing = AntiAliasing::kNone;
  FrameRenderer renderer(results, o, 0.0, 1.0);
  const Image image = renderer.render(0.5);
  const int x0 = static_cast<int>(kColorBarBox[0] * o.width);
  const int y0 = static_cast<int>((1.0 - kColorBarBox[1] - kColorBarBox[3]) * o.height) - o.height / 20;
  const int y1 = static_cast<int>((1.0 - kColorBarBox[1]) * o.height) + o.height / 50;
  int bar_right = -1, bar_top = o.height, label_left = o.width;
  std::vector<bool> dark_row(static_cast<std::size_t>(o.height), false);
  // The bar: saturated colours (its colour table); then text: near black (0.1, 0.1, 0.15),
  // anti-aliased over the grey-blue background, so dark and unsaturated (viridis's dark purple
  // end is saturated), anywhere in the box (labels on the bar's left would count as overlapping).
  for (int pass = 0; pass < 2; ++pass) {
    for (int y = std::max(0, y0); y < std::min(o.height, y1); ++y) {
      for (int x = x0; x < o.width; ++x) {
        const auto c = image.pixel(x, y);
        const int lo = std::min({c[0], c[1], c[2]}), hi = std::max({c[0], c[1], c[2]});
        if (pass == 0 && hi - lo > 120) bar_right = std::max(bar_right, x), bar_top = std::min(bar_top, y);
        if (pass == 1 && hi < 110 && hi - lo < 40) {
          dark_row[static_cast<std::size_t>(y)] = true;
          // The title sits above the bar, centred over it: only rows beside the bar's colours
          // count (the bar's top rows are viridis's yellow end, saturated).
          const bool beside = y >= bar_top;
          if (beside) label_left = std::min(label_left, x);
        }
      }
    }
  }
  ASSERT_GT(bar_right, x0);
  ASSERT_LT(label_left, o.width);
  EXPECT_GE(label_left - bar_right, 3) << "labels touch the bar";
  int bands = 0;
  for (int y = 1; y < o.height; ++y) bands += dark_row[static_cast<std::size_t>(y)] && !dark_row[static_cast<std::size_t>(y - 1)];
  EXPECT_EQ(bands, 6) << "title and labels overlap";
}

TEST_F(FrameRendererTest, NoColorBarWithoutFlexibleBodies) {
  TestScene scene;
  scene.plates = 0;
  scene.with_beam = false;
  const Results results = scene_results(scene, "no_bar");
  FrameRenderer renderer(results, options(CameraPreset::kIso), 0.0, 1.0);
  const Image image = renderer.render(0.5);
  // The colour bar's box holds neither end of the colour table (viridis: (68, 1, 84) and
  // (253, 231, 37) in 8 bits; 30 levels cover the bar's shading-free blend with its edges).
  int saturated = 0;
  for (int y = static_cast<int>((1.0 - kColorBarBox[1] - kColorBarBox[3]) * kHeight);
       y < static_cast<int>((1.0 - kColorBarBox[1]) * kHeight); ++y) {
    for (int x = static_cast<int>(kColorBarBox[0] * kWidth); x < kWidth; ++x) {
      const auto c = image.pixel(x, y);
      for (const std::array<int, 3>& end : {std::array<int, 3>{68, 1, 84}, std::array<int, 3>{253, 231, 37}}) {
        if (std::abs(c[0] - end[0]) < 30 && std::abs(c[1] - end[1]) < 30 && std::abs(c[2] - end[2]) < 30) ++saturated;
      }
    }
  }
  EXPECT_EQ(saturated, 0);
}

TEST_F(FrameRendererTest, CpuFxaaSmoothsEdgesOnlyAndSparesTextAndColorBar) {
  const Results results = scene_results(TestScene{}, "anti_aliasing");
  // One renderer at a time: each owns the EGL display while it lives.
  auto render_with = [&](AntiAliasing mode, double* smoothing_seconds) {
    RenderOptions o = options(CameraPreset::kIso);
    o.anti_aliasing = mode;
    FrameRenderer renderer(results, o, 0.0, 1.0);
    Image image = renderer.render(0.5);
    *smoothing_seconds = renderer.timing().smoothing;
    return image;
  };
  double smoothing = -1.0;
  const Image jagged = render_with(AntiAliasing::kNone, &smoothing);
  EXPECT_EQ(smoothing, 0.0);
  const Image smooth = render_with(AntiAliasing::kFxaa, &smoothing);
  EXPECT_GT(smoothing, 0.0);

  // Changed pixels: some, each on an edge of the jagged frame (a 4-neighbour of another
  // colour), none in the title band (top 10 %) or the colour bar's box.
  int changed = 0, off_edge = 0, in_overlay = 0;
  for (int y = 1; y + 1 < kHeight; ++y) {
    for (int x = 1; x + 1 < kWidth; ++x) {
      const auto p = jagged.pixel(x, y);
      if (smooth.pixel(x, y) == p) continue;
      ++changed;
      const bool on_edge = jagged.pixel(x - 1, y) != p || jagged.pixel(x + 1, y) != p ||
                           jagged.pixel(x, y - 1) != p || jagged.pixel(x, y + 1) != p;
      if (!on_edge) ++off_edge;
      if (y < kHeight / 10 || x >= kColorBarBox[0] * kWidth) ++in_overlay;
    }
  }
  EXPECT_GT(changed, 50);
  EXPECT_EQ(off_edge, 0);
  EXPECT_EQ(in_overlay, 0);

  // VTK's OpenGL pass (--anti-aliasing gl-fxaa) draws too, without any VTK message.
  const Image gl = render_with(AntiAliasing::kGlFxaa, &smoothing);
  EXPECT_TRUE(is_background(gl.pixel(1, 1)));
  EXPECT_NE(gl.rgb, jagged.rgb);
  EXPECT_EQ(std::string(messages_->GetOutput()), "");
}

TEST_F(FrameRendererTest, DeferredFxaaGivesTheFrameOfRender) {
  // render_deferred's step, run later (as the PNG writers do), must give render()'s frame
  // exactly: the same drawing and the overlay boxes of that frame. Without CPU FXAA there is
  // no step at all.
  const Results results = scene_results(TestScene{}, "deferred_fxaa");
  {
    FrameRenderer renderer(results, options(CameraPreset::kIso), 0.0, 1.0);
    const Image direct = renderer.render(0.5);
    auto [deferred, smooth] = renderer.render_deferred(0.5);
    ASSERT_TRUE(smooth);
    EXPECT_NE(deferred.rgb, direct.rgb);  // not smoothed yet
    renderer.render(0.9);                 // another frame drawn in between
    smooth(deferred);
    EXPECT_EQ(deferred.rgb, direct.rgb);
  }
  RenderOptions jagged = options(CameraPreset::kIso);
  jagged.anti_aliasing = AntiAliasing::kNone;
  FrameRenderer renderer(results, jagged, 0.0, 1.0);
  EXPECT_FALSE(renderer.render_deferred(0.5).second);
}

TEST_F(FrameRendererTest, DeformedPlateMovesBetweenFrames) {
  // Front view (looking along +y): the plate is seen edge-on; its centre line rises to
  // z = 0.3 + A at t = 0.25 s and sinks to z = 0.3 - A at t = 0.75 s (A = 0.1 m).
  TestScene scene;
  scene.with_box = false;
  scene.samples = 41;  // the peaks are samples: t = 0.25 and 0.75 s
  const Results results = scene_results(scene, "moving");
  FrameRenderer renderer(results, options(CameraPreset::kFront), 0.0, 1.0);
  const Image up = renderer.render(0.25);
  const Eigen::Vector2d above = renderer.project({0.5, 0.3, 0.36});
  const Eigen::Vector2d below = renderer.project({0.5, 0.3, 0.24});
  const Image down = renderer.render(0.75);
  const auto pixel = [](const Image& image, const Eigen::Vector2d& at) {
    return image.pixel(static_cast<int>(at.x()), static_cast<int>(at.y()));
  };
  // The fixed camera projects both points to the same pixels in both frames.
  EXPECT_FALSE(is_background(pixel(up, above)));
  EXPECT_TRUE(is_background(pixel(up, below)));
  EXPECT_TRUE(is_background(pixel(down, above)));
  EXPECT_FALSE(is_background(pixel(down, below)));
  EXPECT_EQ(std::string(messages_->GetOutput()), "");
}

TEST_F(FrameRendererTest, ScaleFactorAmplifiesTheDeformation) {
  // With scale 2 the plate centre reaches z = 0.3 + 2A = 0.5 m at t = 0.25 s.
  TestScene scene;
  scene.with_box = false;
  scene.with_beam = false;
  scene.samples = 41;
  const Results results = scene_results(scene, "scaled");
  RenderOptions o = options(CameraPreset::kFront);
  // Unscaled: nothing at z = 0.46 m above the centre.
  {
    FrameRenderer plain(results, o, 0.0, 1.0);
    const Image image = plain.render(0.25);
    const Eigen::Vector2d high = plain.project({0.5, 0.3, 0.46});
    EXPECT_TRUE(is_background(image.pixel(static_cast<int>(high.x()), static_cast<int>(high.y()))));
  }
  // Scaled by 2: the plate covers that point; the note "deformation x 2" is drawn top right,
  // under the title.
  o.scale = 2.0;
  FrameRenderer scaled(results, o, 0.0, 1.0);
  const Image image = scaled.render(0.25);
  const Eigen::Vector2d high = scaled.project({0.5, 0.3, 0.46});
  EXPECT_FALSE(is_background(image.pixel(static_cast<int>(high.x()), static_cast<int>(high.y()))));
  int note = 0;
  for (const Scene::DrawnText& text : scaled.scene().drawn_texts()) {
    if (text.text.rfind("deformation x 2", 0) != 0) continue;
    EXPECT_GE(text.box.x0, kWidth / 2);
    EXPECT_LT(text.box.y1, kHeight / 4);
    for (int y = text.box.y0; y < text.box.y1; ++y) {
      for (int x = text.box.x0; x < text.box.x1; ++x) note += is_background(image.pixel(x, y)) ? 0 : 1;
    }
  }
  EXPECT_GT(note, 20);
}

}  // namespace
}  // namespace limber::render
