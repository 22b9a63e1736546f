#include "frame_renderer.h"

#include "edge_smoothing.h"
#include "egl_context.h"
#include "egl_render_window.h"
#include "scene.h"

#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtk_glew.h>

#include <chrono>
#include <cstring>

namespace limber::render {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

struct FrameRenderer::Impl {
  RenderOptions options;
  EglContext context;
  vtkNew<EglRenderWindow> window;
  Scene scene;
  vtkNew<vtkUnsignedCharArray> pixels;
  RenderTiming timing;

  Impl(const Results& results, const RenderOptions& o, double t0, double t1)
      : options(o), context(o.width, o.height), scene(results, o, t0, t1) {
    window->attach_to_current_context(o.width, o.height);
    window->AddRenderer(scene.renderer());
    // The reaction arrows over the bodies (scene_extras.h).
    if (vtkRenderer* overlay = scene.overlay_renderer()) {
      window->SetNumberOfLayers(2);
      window->AddRenderer(overlay);
    }
  }
};

FrameRenderer::FrameRenderer(const Results& results, const RenderOptions& options, double t0,
                             double t1)
    : impl_(std::make_unique<Impl>(results, options, t0, t1)) {}

FrameRenderer::~FrameRenderer() {
  // Free VTK's OpenGL resources while the context is still current.
  impl_->context.make_current();
  impl_->window->Finalize();
}

Image FrameRenderer::render(double t) {
  auto [image, smooth] = render_deferred(t);
  if (smooth) {
    const auto start = std::chrono::steady_clock::now();
    smooth(image);
    impl_->timing.smoothing += seconds_since(start);
  }
  return std::move(image);
}

std::pair<Image, std::function<void(Image&)>> FrameRenderer::render_deferred(double t) {
  Impl& m = *impl_;
  // Scene state at t.
  auto start = std::chrono::steady_clock::now();
  m.scene.update(t);
  m.timing.scene_update += seconds_since(start);

  // Draw, and wait for the rasteriser so the split of the time is honest.
  start = std::chrono::steady_clock::now();
  m.window->Render();
  glFinish();
  m.timing.draw += seconds_since(start);

  // Read the back buffer (bottom-up rows) into a top-down image.
  start = std::chrono::steady_clock::now();
  const int w = m.options.width;
  const int h = m.options.height;
  m.window->GetPixelData(0, 0, w - 1, h - 1, 0, m.pixels, 0);
  Image image;
  image.width = w;
  image.height = h;
  image.rgb.resize(static_cast<std::size_t>(w) * h * 3);
  const std::size_t row = static_cast<std::size_t>(w) * 3;
  const std::uint8_t* source = m.pixels->GetPointer(0);
  for (int y = 0; y < h; ++y) {
    std::memcpy(image.rgb.data() + row * y, source + row * (h - 1 - y), row);
  }
  m.timing.readback += seconds_since(start);

  ++m.timing.frames;
  // Anti-aliasing on the CPU (the default), sparing the texts and the colour bar as drawn now.
  if (m.options.anti_aliasing != AntiAliasing::kFxaa) return {std::move(image), {}};
  return {std::move(image),
          [keep = m.scene.overlay_boxes()](Image& frame) { smooth_edges(frame, keep); }};
}

Eigen::Vector2d FrameRenderer::project(const Eigen::Vector3d& p_W) const {
  vtkNew<vtkCoordinate> coordinate;
  coordinate->SetCoordinateSystemToWorld();
  coordinate->SetValue(p_W.x(), p_W.y(), p_W.z());
  const double* display = coordinate->GetComputedDoubleDisplayValue(impl_->scene.renderer());
  return {display[0], impl_->options.height - 1 - display[1]};
}

std::string FrameRenderer::backend() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return impl_->context.platform() + ", " + (renderer != nullptr ? renderer : "unknown renderer");
}

const RenderTiming& FrameRenderer::timing() const { return impl_->timing; }

double FrameRenderer::color_range_max() const { return impl_->scene.color_range_max(); }

const Scene& FrameRenderer::scene() const { return impl_->scene; }

}  // namespace limber::render
