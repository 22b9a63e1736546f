// A still picture of a mode for the report (mode_view.h, issue 28): a plate is seen along its
// normal (its projected outline keeps the plate's side ratio: a plane parallel to the image
// plane projects without distortion), with no time stamp, and no text is cut by the frame's edge.
#include "frame_renderer.h"
#include "mode_view.h"

#include "scene.h"
#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace limber::render {
namespace {

TEST(ModeImage, APlateIsSeenAlongItsNormalWithoutTimeStampOrClippedText) {
  unsetenv("DISPLAY");
  testing::TestScene scene;
  scene.with_beam = false;
  scene.with_box = false;
  const auto dir = testing::fresh_directory("mode_image");
  testing::write_test_results(dir, scene);
  const Results results = read_results(dir);
  const BodyTrack& plate = results.bodies.at(0);

  // The plate lies in its body x-y plane: its nodes spread least along z, exactly.
  const Eigen::Vector3d n = mode_plane_direction(plate.mesh, 0);
  EXPECT_NEAR(n.z(), 1.0, 1e-12);

  // The report's image size; at t = 0.25 s the mode is at its peak.
  const RenderOptions options = mode_image_options(plate, 0, 480, 360);
  FrameRenderer renderer(results, options, 0.25, 0.25);
  const Image image = renderer.render(0.25);

  // Corners of the plate's frame plane (z = 0.3 m): the projected sides keep the 1 : 0.6 ratio
  // to round-off (1e-9: a plane parallel to the image plane is only scaled by perspective).
  const Eigen::Vector3d o = testing::plate_origin(0);
  const Eigen::Vector2d a = renderer.project(o);
  const Eigen::Vector2d bx = renderer.project(o + Eigen::Vector3d(scene.lx, 0, 0));
  const Eigen::Vector2d by = renderer.project(o + Eigen::Vector3d(0, scene.ly, 0));
  EXPECT_NEAR((bx - a).norm() / (by - a).norm(), scene.lx / scene.ly, 1e-9);
  EXPECT_NEAR((bx - a).dot(by - a), 0.0, 1e-9 * (bx - a).squaredNorm());

  // No time stamp among the texts.
  for (const Scene::DrawnText& text : renderer.scene().drawn_texts()) {
    EXPECT_EQ(text.text.find("t = "), std::string::npos) << text.text;
  }
  // No dark text pixel (near black, unsaturated) on the frame's outer two rows and columns: a
  // label or the colour bar's title cut by the edge would leave some there.
  int on_edge = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (x >= 2 && x < image.width - 2 && y >= 2 && y < image.height - 2) continue;
      const auto c = image.pixel(x, y);
      const int hi = std::max({c[0], c[1], c[2]}), lo = std::min({c[0], c[1], c[2]});
      on_edge += hi < 110 && hi - lo < 40;
    }
  }
  EXPECT_EQ(on_edge, 0);
}

}  // namespace
}  // namespace limber::render
