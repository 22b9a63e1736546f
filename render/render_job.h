// `limber render` as a library call: results.h5 -> PNG frames, MP4 (+ GIF), ParaView output
// (XDMF scene and script, VTU/PVD series).
#pragma once

#include "frame_renderer.h"
#include "render_options.h"
#include "results_reader.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace limber::render {

struct RenderSummary {
  double t0 = 0.0, t1 = 0.0;  // time range rendered [s]
  int frames = 0;             // PNG frames written
  int vtu_files = 0;          // .vtu files written
  int xdmf_samples = 0;       // time steps of DIR/vtk/scene.xmf (0: not written)
  double paraview_seconds = 0.0;  // writing the ParaView output (XDMF and/or PVD) [s]
  std::filesystem::path video, gif;  // written videos (empty when not written)
  std::vector<std::string> warnings;  // e.g. ffmpeg missing: the frames are still there
  std::string backend;        // EGL route and OpenGL renderer
  RenderTiming timing;        // render-thread split
  double png_seconds = 0.0;   // PNG encoding on the writer threads
  double smoothing_seconds = 0.0;  // CPU FXAA, deferred to the writer threads
  double wall_seconds = 0.0;  // whole frame loop, including waiting for the last PNG
};

// The rendered time range: options' t0/t1 clipped to the samples. Throws InputError when the
// file has no sample or the range holds no sample time and does not overlap the run.
std::pair<double, double> resolve_time_range(const Results& results, const RenderOptions& options);

// Frame times t0, t0 + 1/fps, ... up to t1 (inclusive within 1e-9 of a frame).
std::vector<double> frame_times(double t0, double t1, double fps);

// Runs everything the options ask for. Throws InputError for bad input (missing or damaged
// file, empty range, bad options), std::runtime_error when rendering or writing fails.
RenderSummary render_results(const RenderOptions& options);

}  // namespace limber::render
