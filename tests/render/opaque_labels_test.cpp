// The scene draws its 3D labels (the world triad's) as opaque geometry after every other prop,
// so VTK never runs its order-independent translucency pass (about 11 ms of CPU per 1280 x 720
// frame in llvmpipe, docs/benchmarks.md). Checked against the translucent pass itself: the
// same scene with the labels left translucent must give the same pixels, to 1 of 255 (the
// pass accumulates in floating-point buffers and divides before the 8-bit store; the opaque
// path blends in 8 bits).
#include "egl_context.h"
#include "egl_render_window.h"
#include "scene.h"
#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <vtkBillboardTextActor3D.h>
#include <vtkNew.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <cstdlib>
#include <optional>

namespace limber::render {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 360;

TEST(OpaqueLabels, SamePixelsAsTheTranslucentPass) {
  unsetenv("DISPLAY");
  std::optional<EglContext> context;
  try {
    context.emplace(kWidth, kHeight);
  } catch (const std::exception& error) {
    GTEST_SKIP() << "no offscreen OpenGL context: " << error.what();
  }
  const auto dir = testing::fresh_directory("opaque_labels");
  testing::write_test_results(dir, testing::TestScene{});
  const Results results = read_results(dir);
  RenderOptions options;
  options.width = kWidth;
  options.height = kHeight;
  Scene scene(results, options, 0.0, 1.0);
  vtkNew<EglRenderWindow> window;
  window->attach_to_current_context(kWidth, kHeight);
  window->AddRenderer(scene.renderer());

  // The labels of the scene, and whether any prop still needs the translucent pass.
  std::vector<vtkBillboardTextActor3D*> labels;
  bool translucent = false;
  vtkPropCollection* props = scene.renderer()->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it)) {
    if (auto* label = vtkBillboardTextActor3D::SafeDownCast(prop)) labels.push_back(label);
    translucent = translucent || prop->HasTranslucentPolygonalGeometry();
  }
  ASSERT_EQ(labels.size(), 3u);  // x, y, "z (arrows ... m)"
  EXPECT_FALSE(translucent);

  auto frame = [&] {
    scene.update(0.5);
    window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    window->GetPixelData(0, 0, kWidth - 1, kHeight - 1, 0, pixels, 0);
    return std::vector<std::uint8_t>(pixels->GetPointer(0), pixels->GetPointer(0) + pixels->GetNumberOfValues());
  };
  const std::vector<std::uint8_t> opaque = frame();
  for (vtkBillboardTextActor3D* label : labels) label->ForceOpaqueOff();
  const std::vector<std::uint8_t> blended = frame();
  ASSERT_EQ(opaque.size(), blended.size());
  int largest = 0;
  for (std::size_t k = 0; k < opaque.size(); ++k) largest = std::max(largest, std::abs(opaque[k] - blended[k]));
  EXPECT_LE(largest, 1);
  // The labels are drawn at all: some pixels differ from a frame without them.
  for (vtkBillboardTextActor3D* label : labels) label->VisibilityOff();
  const std::vector<std::uint8_t> without = frame();
  EXPECT_NE(without, opaque);

  context->make_current();
  window->Finalize();
}

}  // namespace
}  // namespace limber::render
