#include "render_job.h"

#include "core/error.h"
#include "png_frame_writer.h"
#include "progress_bar.h"
#include "video_encoder.h"
#include "paraview_script.h"
#include "vtk_export.h"
#include "xdmf_export.h"
#include "xdmf_layout.h"
#include "results/directory_lock.h"
#include "results/file_names.h"
#include "results/results_layout.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace limber::render {
namespace {

// Removes files of an earlier render whose names start with `prefix` and end with `suffix`.
void remove_stale(const std::filesystem::path& directory, const std::string& prefix,
                  const std::string& suffix) {
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error)) return;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name.size() >= prefix.size() + suffix.size() && name.rfind(prefix, 0) == 0 &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      std::filesystem::remove(entry.path(), error);
    }
  }
}

std::string seconds(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", t);
  return text;
}

}  // namespace

std::pair<double, double> resolve_time_range(const Results& results, const RenderOptions& options) {
  const Eigen::Index ns = results.sample_count();
  if (ns == 0) {
    throw InputError("results file '" + results.file.string() +
                     "': expected at least one sample, got none (status '" + results.status +
                     "')");
  }
  const double first = results.time(0);
  const double last = results.time(ns - 1);
  const double t0 = std::max(options.t0.value_or(first), first);
  const double t1 = std::min(options.t1.value_or(last), last);
  if (t0 > t1) {
    throw InputError("empty time range: expected [t0, t1] to overlap the results' [" +
                     seconds(first) + ", " + seconds(last) + "], got [" +
                     seconds(options.t0.value_or(first)) + ", " +
                     seconds(options.t1.value_or(last)) + "]");
  }
  return {t0, t1};
}

std::vector<double> frame_times(double t0, double t1, double fps) {
  const auto count = static_cast<long>(std::floor((t1 - t0) * fps + 1e-9)) + 1;
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(count));
  for (long k = 0; k < count; ++k) times.push_back(t0 + static_cast<double>(k) / fps);
  return times;
}

namespace {

// Frames: rendered on this thread; FXAA and PNG encoding on the writer threads. Fills the
// summary's frame count, backend and timings.
void render_frames(const Results& results, const RenderOptions& options,
                   const std::vector<double>& times, RenderSummary& summary) {
  const std::filesystem::path frames = options.directory / results::kFramesFolder;
  std::filesystem::create_directories(frames);
  remove_stale(frames, "frame_", ".png");
  remove_stale(frames, "frame_", ".png.part");  // left by an interrupted render
  const auto start = std::chrono::steady_clock::now();
  FrameRenderer renderer(results, options, summary.t0, summary.t1);
  summary.backend = renderer.backend();
  {
    PngFrameWriter writer;
    ProgressBar progress("rendering", static_cast<int>(times.size()), options.progress);
    for (std::size_t k = 0; k < times.size(); ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05zu.png", k);
      // The CPU FXAA runs on the writers, beside the next frame's draw.
      auto [image, smooth] = renderer.render_deferred(times[k]);
      writer.push(std::move(image), frames / name, std::move(smooth));
      progress.update(static_cast<int>(k) + 1);
    }
    writer.finish();
    summary.png_seconds = writer.encode_seconds();
    summary.smoothing_seconds = writer.prepare_seconds();
  }
  summary.frames = static_cast<int>(times.size());
  summary.timing = renderer.timing();
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The one-file XDMF scene and the ParaView script that opens it, viewed and coloured as the
// video; returns the number of samples written.
int write_xdmf_output(const Results& results, const RenderOptions& options,
                      const std::filesystem::path& vtk, double t0, double t1) {
  const XdmfSceneSummary scene = write_xdmf_scene(results, vtk, t0, t1, options.progress);
  ParaViewView view = fit_view(view_direction(options), scene.lo, scene.hi);
  view.title = results.title;
  view.scale = options.scale;
  // Coloured as the video: by stress only with --color von_mises, in the same map.
  view.color_by_stress = options.color == ColorBy::kVonMises && scene.stress;
  view.viridis = options.color_map == ColorMap::kViridis;
  view.beams = scene.beams;
  view.relative = scene.relative;
  view.color_max = view.color_by_stress ? scene.stress_max : scene.relative_deflection_max;
  view.width = options.width;
  view.height = options.height;
  write_paraview_script(view, std::filesystem::absolute(vtk));
  return scene.samples;
}

// ParaView output: the XDMF scene and/or the VTU/PVD series. The other kind's files of an
// earlier render are removed, so DIR/vtk holds what was asked for.
void write_paraview_output(const Results& results, const RenderOptions& options,
                           RenderSummary& summary) {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path vtk = options.directory / results::kVtkFolder;
  const bool xdmf = options.paraview != ParaViewOutput::kPvd;
  const bool pvd = options.paraview != ParaViewOutput::kXdmf;
  remove_stale(vtk, "", ".vtu");
  if (!pvd) remove_stale(vtk, results::kVtkSceneFileName, "");
  if (!xdmf) {
    for (const char* name : {xdmf::kFileName, xdmf::kDescriptionName, xdmf::kScriptName}) {
      remove_stale(vtk, name, "");
    }
  }
  if (xdmf) summary.xdmf_samples = write_xdmf_output(results, options, vtk, summary.t0, summary.t1);
  if (pvd) summary.vtu_files = write_vtk_series(results, vtk, summary.t0, summary.t1);
  summary.paraview_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Videos (MP4, GIF) from the frames, when ffmpeg is installed; a warning otherwise.
void encode_videos(const RenderOptions& options, RenderSummary& summary) {
  const std::filesystem::path frames = options.directory / results::kFramesFolder;
  const auto ffmpeg = find_ffmpeg();
  if (!ffmpeg) {
    summary.warnings.push_back(
        "ffmpeg not found on PATH: no video written (install Debian's ffmpeg package); "
        "the PNG frames are in " + frames.string());
    return;
  }
  for (const auto& [wanted, name, target] :
       {std::tuple{options.write_video, results::kAnimationVideoFileName, &summary.video},
        std::tuple{options.write_gif, results::kAnimationGifFileName, &summary.gif}}) {
    if (!wanted) continue;
    const std::filesystem::path output = options.directory / name;
    const std::string problem = encode_video(*ffmpeg, frames, options.playback_fps, output);
    if (problem.empty()) *target = output;
    else summary.warnings.push_back(problem);
  }
}

}  // namespace

RenderSummary render_results(const RenderOptions& options) {
  validate(options);
  // One render at a time writes into a run directory (results/directory_lock.h).
  std::error_code missing;
  const results::DirectoryLock lock =
      std::filesystem::is_directory(options.directory, missing)
          ? results::DirectoryLock(options.directory, results::kRenderLock)
          : results::DirectoryLock();
  const Results results = read_results(options.directory);
  RenderSummary summary;
  std::tie(summary.t0, summary.t1) = resolve_time_range(results, options);
  // A run still being written (or killed) is drawn as far as its file was flushed.
  if (results.status == results::layout::status::kRunning) {
    summary.warnings.push_back(
        "run not finished (status 'running': still being written, or killed): rendered the " +
        std::to_string(results.sample_count()) + " samples written so far, up to t = " +
        seconds(results.time(results.sample_count() - 1)));
  }

  // Frames, ParaView output, then videos from the frames.
  if (options.write_png) {
    render_frames(results, options, frame_times(summary.t0, summary.t1, options.fps), summary);
  }
  if (options.paraview != ParaViewOutput::kNone) write_paraview_output(results, options, summary);
  if (options.write_png && (options.write_video || options.write_gif)) {
    encode_videos(options, summary);
  }
  return summary;
}

}  // namespace limber::render
