// The world triad (world_triad.h) as the layout places it (scene_layout.h): its labels are 2D
// texts, so no prop of the scene needs VTK's order-independent translucency pass (several
// full-frame passes, about 11 ms of CPU per 1280 x 720 frame in llvmpipe, docs/benchmarks.md);
// the labels lie inside the frame; and the triad sits where no body is drawn: every pixel it
// changes is background without it (drawn in the overlay layer, it would show over a body).
#include "frame_renderer.h"

#include "scene.h"
#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

namespace limber::render {
namespace {

// Shows or hides the triad's arrows (by their colours, world_triad.cpp) and labels, drawn in the
// scene's overlay layer.
void show_triad(vtkRenderer* renderer, bool visible) {
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it)) {
    if (auto* text = vtkTextActor::SafeDownCast(prop)) {
      const std::string input = text->GetInput() != nullptr ? text->GetInput() : "";
      if (input == "x" || input == "y" || input.rfind("z (arrows ", 0) == 0) text->SetVisibility(visible);
    }
    if (auto* actor = vtkActor::SafeDownCast(prop)) {
      double c[3];
      actor->GetProperty()->GetColor(c);
      for (const auto& triad : {std::array<double, 3>{0.80, 0.15, 0.15}, std::array<double, 3>{0.15, 0.60, 0.20},
                                std::array<double, 3>{0.15, 0.30, 0.85}}) {
        if (std::abs(c[0] - triad[0]) + std::abs(c[1] - triad[1]) + std::abs(c[2] - triad[2]) < 1e-9) {
          actor->SetVisibility(visible);
        }
      }
    }
  }
}

int difference(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

class WorldTriadTest : public ::testing::Test {
 protected:
  void SetUp() override {
    unsetenv("DISPLAY");
    const auto dir = testing::fresh_directory("world_triad");
    testing::write_test_results(dir, testing::TestScene{});
    results_ = read_results(dir);
  }
  Results results_;
};

TEST_F(WorldTriadTest, LabelsAreTextsInsideTheFrameWithoutTheTranslucentPass) {
  RenderOptions o;
  o.width = 640;
  o.height = 360;
  FrameRenderer renderer(results_, o, 0.0, 1.0);
  renderer.render(0.5);
  bool translucent = false;
  ASSERT_NE(renderer.scene().overlay_renderer(), nullptr);  // the triad's layer
  for (vtkRenderer* layer : {renderer.scene().renderer(), renderer.scene().overlay_renderer()}) {
    vtkPropCollection* props = layer->GetViewProps();
    vtkCollectionSimpleIterator it;
    props->InitTraversal(it);
    while (vtkProp* prop = props->GetNextProp(it)) translucent = translucent || prop->HasTranslucentPolygonalGeometry();
  }
  EXPECT_FALSE(translucent);
  int labels = 0;
  for (const Scene::DrawnText& text : renderer.scene().drawn_texts()) {
    if (text.text == "x" || text.text == "y" || text.text.rfind("z (arrows ", 0) == 0) ++labels;
    EXPECT_FALSE(text.clipped) << "'" << text.text << "'";
  }
  EXPECT_EQ(labels, 3);
}

TEST_F(WorldTriadTest, TheTriadCoversNoBody) {
  // At 720p in the iso and front views, through the motion (0, 0.5, 1 s), without the ground
  // plane (the triad may stand on it): a pixel the triad
  // changes by more than rounding (6 levels over the three channels) is background (within the
  // same 6 levels) in the frame without it.
  for (const CameraPreset camera : {CameraPreset::kIso, CameraPreset::kFront}) {
    RenderOptions o;
    o.width = 1280;
    o.height = 720;
    o.camera = camera;
    o.scale = 5.0;
    o.ground = false;  // the triad may stand on the ground, which is not a body
    o.anti_aliasing = AntiAliasing::kNone;
    FrameRenderer renderer(results_, o, 0.0, 1.0);
    const std::array<int, 3> background{static_cast<int>(std::lround(255 * kBackgroundColor[0])),
                                        static_cast<int>(std::lround(255 * kBackgroundColor[1])),
                                        static_cast<int>(std::lround(255 * kBackgroundColor[2]))};
    for (const double t : {0.0, 0.5, 1.0}) {
      show_triad(renderer.scene().overlay_renderer(), true);
      const Image with = renderer.render(t);
      show_triad(renderer.scene().overlay_renderer(), false);
      const Image without = renderer.render(t);
      int changed = 0, over_something = 0;
      for (int y = 0; y < with.height; ++y) {
        for (int x = 0; x < with.width; ++x) {
          if (difference(with.pixel(x, y), without.pixel(x, y)) <= 6) continue;
          ++changed;
          over_something += difference(without.pixel(x, y), background) > 6;
        }
      }
      EXPECT_GT(changed, 500) << "the triad is drawn";
      EXPECT_EQ(over_something, 0) << "camera " << static_cast<int>(camera) << ", t = " << t;
    }
  }
}

}  // namespace
}  // namespace limber::render
