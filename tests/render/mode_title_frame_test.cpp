// A mode animation's frame as `limber modes` draws it (640 x 480, its default, and 1280 x 720):
// the title (body, mode, label, frequency, amplitude, and for a slender body the plane it is
// seen square to) and the triad's labels lie whole inside the frame (issue 28: the title was
// cut at 640 x 480). The longest title of the shipped cases' modes: the satellite panel's
// attachment modes ("attachment uy at node 10001", 3170 Hz), here on a slender beam so that the
// plane line is there too, under a body name of the satellite's length.
#include "mode_animation.h"

#include "frame_renderer.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace limber::render {
namespace {

// A 1.2 m beam along x of 13 nodes, bending along z as x² (a slender mesh: mode_view.h names
// the x-z plane).
BodyModeShapes slender_beam() {
  constexpr int kNodes = 13;
  BodyModeShapes body;
  body.name = "panel_outer_right";
  body.mesh.nodes.setZero(kNodes, 3);
  body.mesh.lines.resize(kNodes - 1, 2);
  body.mesh.mode_translations.setZero(3 * kNodes, 1);
  for (int n = 0; n < kNodes; ++n) {
    const double x = 1.2 * n / (kNodes - 1);
    body.mesh.nodes(n, 0) = x;
    body.mesh.mode_translations(3 * n + 2, 0) = x * x;
    if (n + 1 < kNodes) body.mesh.lines.row(n) << n, n + 1;
  }
  body.mesh.frequencies_hz = Eigen::VectorXd::Constant(1, 3170.0);
  body.kinds = {"attachment"};
  body.labels = {"attachment uy at node 10001"};
  return body;
}

void expect_texts_inside(int width, int height) {
  const BodyModeShapes body = slender_beam();
  ModeAnimationOptions options;
  options.width = width;
  options.height = height;
  const Results results = mode_results(body, 0, options);
  // The title is the two-line one, with the plane named.
  ASSERT_NE(results.title.find("x-z plane"), std::string::npos) << results.title;

  RenderOptions view = mode_render_options(body, 0, options);
  view.anti_aliasing = AntiAliasing::kNone;
  FrameRenderer renderer(results, view, 0.0, results.time(results.time.size() - 1));
  renderer.render(results.time(6));  // the peak of the cycle
  int texts = 0;
  bool title_seen = false;
  for (const Scene::DrawnText& text : renderer.scene().drawn_texts()) {
    EXPECT_FALSE(text.clipped) << width << " x " << height << ": '" << text.text << "'";
    if (text.text.find("attachment uy at node 10001") != std::string::npos) {
      title_seen = true;
      std::printf("%d x %d, title in %d lines:\n%s\n", width, height, text.lines, text.text.c_str());
    }
    ++texts;
  }
  EXPECT_TRUE(title_seen);
  EXPECT_GE(texts, 4);  // title, the triad's three labels
}

TEST(ModeTitleFrame, TitleWholeInsideAt640x480) {
  unsetenv("DISPLAY");
  expect_texts_inside(640, 480);
}

TEST(ModeTitleFrame, TitleWholeInsideAt1280x720) {
  unsetenv("DISPLAY");
  expect_texts_inside(1280, 720);
}

}  // namespace
}  // namespace limber::render
