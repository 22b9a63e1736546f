// The animation's layout at 720p (issue 28): the fixed camera fits the whole motion into the
// frame left of the colour bar, every text is at least 14 px tall, a hinge event is stamped on
// the frames after it for half a second of video, and the colour bar reads in millimetres.
#include "frame_renderer.h"

#include "scene.h"
#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace limber::render {
namespace {

using testing::TestScene;

class AnimationLayoutTest : public ::testing::Test {
 protected:
  void SetUp() override { unsetenv("DISPLAY"); }

  static Results results(const TestScene& scene, const std::string& name) {
    const auto dir = testing::fresh_directory(name);
    testing::write_test_results(dir, scene);
    return read_results(dir);
  }

  static RenderOptions options_720p() {
    RenderOptions o;
    o.width = 1280;
    o.height = 720;
    o.camera = CameraPreset::kIso;
    o.anti_aliasing = AntiAliasing::kNone;
    return o;
  }
};

TEST_F(AnimationLayoutTest, TheMotionFillsTheFrameLeftOfTheColorBar) {
  // The box slides from x = -0.8 to -0.4 m, the plate spans [0, 1] x [0, 0.6] m, the beam
  // [0, 1] m along x at y = 0.9 m: the projected box of every point of the motion (the
  // extreme corners at t = 0 and 1) covers at least 60 % of the frame's width or height, and
  // stays left of the colour bar and inside the frame.
  TestScene scene;
  const Results r = results(scene, "layout_fill");
  RenderOptions o = options_720p();
  o.world_triad = false;  // the motion alone
  FrameRenderer renderer(r, o, 0.0, 1.0);
  renderer.render(0.0);
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (double t : {0.0, 1.0}) {
    for (double dx : {-0.1, 0.1}) {
      for (double dy : {-0.1, 0.1}) {
        for (double dz : {-0.1, 0.1}) {
          const Eigen::Vector2d p = renderer.project(testing::box_position(t) + Eigen::Vector3d(dx, dy, dz));
          x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
        }
      }
    }
  }
  for (const Eigen::Vector3d& corner :
       {Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d(1, 0, 0.3), Eigen::Vector3d(0, 0.6, 0.3),
        Eigen::Vector3d(1, 0.6, 0.3), Eigen::Vector3d(0, 0.9, 0.3), Eigen::Vector3d(1, 0.9, 0.3)}) {
    const Eigen::Vector2d p = renderer.project(corner);
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  const double width = (x1 - x0) / o.width, height = (y1 - y0) / o.height;
  EXPECT_TRUE(width >= 0.6 || height >= 0.6) << "covers " << width << " x " << height;
  EXPECT_GE(x0, 0.0);
  EXPECT_LE(x1, kColorBarBox[0] * o.width);
  EXPECT_GE(y0, 0.0);
  EXPECT_LE(y1, o.height);
}

TEST_F(AnimationLayoutTest, TextsAreAtLeast14PixelsTallAt720p) {
  // Title, the legend's per-body lines ("beam: u relative to a rigid fit through mid"), the
  // time and event stamps: each line's share of its text's box >= 14 px.
  TestScene scene;
  scene.beam_mid_joint = true;
  scene.latch_time = 0.5;
  const Results r = results(scene, "layout_texts");
  RenderOptions o = options_720p();
  o.scale = 20.0;
  FrameRenderer renderer(r, o, 0.0, 1.0);
  renderer.render(0.5);
  const std::vector<Scene::DrawnText> texts = renderer.scene().drawn_texts();
  ASSERT_GE(texts.size(), 4u);  // title, legend, time, event
  int legend_lines = 0;
  for (const Scene::DrawnText& text : texts) {
    const double per_line = static_cast<double>(text.box.y1 - text.box.y0) / text.lines;
    EXPECT_GE(per_line, 14.0) << "'" << text.text << "'";
    if (text.text.find("rigid fit through mid") != std::string::npos) legend_lines = text.lines;
  }
  EXPECT_GE(legend_lines, 2);
}

TEST_F(AnimationLayoutTest, AnEventIsStampedForHalfASecondOfVideo) {
  // The latch locks at 0.5 s; at 30 frames per simulated second played at 30/s the stamp
  // stays 0.5 s: on the frames at 0.5 and 0.9 s, not at 0.45 or 1.0 s. Drawn dark red
  // (0.6, 0.05, 0.05) right of the time stamp.
  TestScene scene;
  scene.latch_time = 0.5;
  const Results r = results(scene, "layout_event");
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_EQ(r.events[0].joint, "pin");
  EXPECT_EQ(r.events[0].kind, "latch");
  RenderOptions o = options_720p();
  FrameRenderer renderer(r, o, 0.0, 1.0);
  auto stamp = [&](double t, int* red_pixels) {
    const Image image = renderer.render(t);
    *red_pixels = 0;
    for (const Scene::DrawnText& text : renderer.scene().drawn_texts()) {
      if (text.text.find("latched") == std::string::npos) continue;
      for (int y = text.box.y0; y < text.box.y1; ++y) {
        for (int x = text.box.x0; x < text.box.x1; ++x) {
          const auto p = image.pixel(x, y);
          *red_pixels += p[0] > 100 && p[0] > 3 * p[1] && p[0] > 3 * p[2];
        }
      }
      return text.text;
    }
    return std::string();
  };
  int red = 0;
  EXPECT_EQ(stamp(0.45, &red), "");
  EXPECT_EQ(stamp(0.5, &red), "pin latched at 0.5000 s");
  EXPECT_GT(red, 100);
  EXPECT_EQ(stamp(0.9, &red), "pin latched at 0.5000 s");
  EXPECT_EQ(stamp(1.0, &red), "");
}

TEST_F(AnimationLayoutTest, ColorBarInMillimetres) {
  // The beam's tip swings by B = 0.05 m, the plate's centre by A = 0.1 m: |u| up to about
  // 0.11 m, in mm; with amplitudes of 1e-4 m, micrometres.
  TestScene scene;
  {
    FrameRenderer renderer(results(scene, "layout_mm"), options_720p(), 0.0, 1.0);
    EXPECT_EQ(renderer.scene().color_unit(), "mm");
  }
  scene.amplitude = 1e-4;
  scene.beam_amplitude = 1e-4;
  FrameRenderer renderer(results(scene, "layout_um"), options_720p(), 0.0, 1.0);
  EXPECT_EQ(renderer.scene().color_unit(), "\xC2\xB5m");
}

}  // namespace
}  // namespace limber::render
