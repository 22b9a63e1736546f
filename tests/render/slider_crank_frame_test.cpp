// The slider-crank's animation frame as the main job draws it (scripts/main-job.sh: --scale 20
// --camera front --t0 0.5 --t1 0.6, 1280 x 720), on a run of the shipped case to 0.6 s: every
// text (title, legend, time stamp, the triad's labels) lies whole inside the frame (issue 28:
// the triad's label was cut off at the left edge), and the crank is drawn at its size: its
// orange 0.05 x 0.015 m face, seen square from the front, shows on 40 % to 105 % of the pixels
// it projects to. The grey hub at R1 and the amber pin caps at R1 and R2, discs of about
// 0.01 m radius centred on the face's ends, hide up to about half of it (measured: 274 of
// 505 px, 54 %); above 105 %, something else would be counted as the crank.
#include "frame_renderer.h"

#include "scene.h"
#include "test_dir.h"

#include <gtest/gtest.h>

#include <vtkRenderer.h>

#include <cstdlib>
#include <string>
#include <sys/wait.h>

namespace limber::render {
namespace {

TEST(SliderCrankFrame, TextsInsideTheFrameAndTheCrankDrawnAtItsSize) {
  unsetenv("DISPLAY");
  const auto dir = testing::fresh_directory("slider_crank_frame");
  const std::string run = std::string(LIMBER_EXE) + " run " + LIMBER_CASES_DIR + "/slider_crank.yaml --t-end 0.6 -o " +
                          dir.string() + " > " + (dir / "run.log").string() + " 2>&1";
  const int status = std::system(run.c_str());
  // 0 ok, 5 ok_inaccurate: both write the whole run.
  ASSERT_TRUE(WIFEXITED(status) && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 5)) << run;
  const Results results = read_results(dir);

  RenderOptions o;
  o.width = 1280;
  o.height = 720;
  o.scale = 20.0;
  o.camera = CameraPreset::kFront;
  o.anti_aliasing = AntiAliasing::kNone;
  FrameRenderer renderer(results, o, 0.5, 0.6);
  renderer.render(0.52);
  int texts = 0;
  for (const Scene::DrawnText& text : renderer.scene().drawn_texts()) {
    EXPECT_FALSE(text.clipped) << "'" << text.text << "'";
    ++texts;
  }
  EXPECT_GE(texts, 6);  // title, legend, time stamp, the triad's three labels

  // The crank's pixels, the triad (its red x arrow) not drawn.
  renderer.scene().overlay_renderer()->DrawOff();
  const Image image = renderer.render(0.52);

  // The crank's colour (0.85, 0.35, 0.2) under the lights: red well above green and blue (the
  // amber pin caps, the green slider and viridis have green near or above half their red).
  int crank = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto p = image.pixel(x, y);
      crank += p[0] > 60 && p[0] > 2 * p[1] && p[0] > 3 * p[2];
    }
  }
  // Pixels per metre at the crank's depth (y = 0): two ground points 0.05 m apart along x.
  const double per_metre = (renderer.project({0.05, 0.0, 0.0}) - renderer.project({0.0, 0.0, 0.0})).norm() / 0.05;
  const double face = 0.05 * 0.015 * per_metre * per_metre;
  std::printf("crank: %d pixels of a %.0f-pixel face (%.0f px per metre)\n", crank, face, per_metre);
  EXPECT_GE(crank, 0.4 * face);
  EXPECT_LE(crank, 1.05 * face);
}

}  // namespace
}  // namespace limber::render
