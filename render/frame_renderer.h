// Renders frames of a results file offscreen (EGL, no X server) into RGB images.
// One FrameRenderer owns one OpenGL context: use it from the thread that created it.
#pragma once

#include "image.h"
#include "render_options.h"
#include "results_reader.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace limber::render {

class Scene;

// Wall-clock seconds spent per phase, summed over the frames rendered.
struct RenderTiming {
  double scene_update = 0.0;  // poses, deformed meshes, text
  double draw = 0.0;          // VTK render (llvmpipe rasterisation; VTK's FXAA pass if asked)
  double readback = 0.0;      // glReadPixels and row flip
  double smoothing = 0.0;     // FXAA on the CPU (the default anti-aliasing), when not deferred
  int frames = 0;
};

class FrameRenderer {
 public:
  // Creates the EGL context, window and scene for results sampled in [t0, t1] [s].
  // Throws std::runtime_error when no offscreen OpenGL 3.2 context can be created.
  FrameRenderer(const Results& results, const RenderOptions& options, double t0, double t1);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Renders the scene at time t [s] (interpolated between samples), anti-aliased as the
  // options say.
  Image render(double t);
  // As render(), but the CPU FXAA (when the options ask for it) is returned as a step still to
  // run on the image, on any thread (the PNG writers: it then overlaps the next frame's draw);
  // an empty function when there is nothing left to do.
  std::pair<Image, std::function<void(Image&)>> render_deferred(double t);
  // Pixel (x from the left, y from the top) where ground point p_W projects with the camera of
  // the last render.
  Eigen::Vector2d project(const Eigen::Vector3d& p_W) const;
  // "EGL surfaceless (Mesa)" / "EGL device", and the OpenGL renderer string.
  std::string backend() const;
  const RenderTiming& timing() const;
  // Upper end of the colour bar (largest |u| in the range) [m].
  double color_range_max() const;
  // The scene drawn (its glyphs and arrow scales: scene.h).
  const Scene& scene() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace limber::render
