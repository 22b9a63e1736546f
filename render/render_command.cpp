#include "render_command.h"

#include "render_job.h"
#include "results/file_names.h"
#include "xdmf_layout.h"

#include <fmt/core.h>

#include <algorithm>
#include <memory>
#include <string>

namespace limber::render {
namespace {

// The options given as text or as negative flags, turned into RenderOptions after parsing.
struct RenderCommandText {
  std::string size = "1280x720";
  std::string camera = "iso";
  double slow_motion = 1.0;
  double t0 = 0.0;
  double t1 = 0.0;
  bool no_video = false;
  std::string anti_aliasing = "fxaa";
  bool no_fxaa = false;
  std::string color = "deflection";
  std::string color_map = "viridis";
  std::string paraview = "xdmf";
  bool no_vtk = false;
  CLI::Option* fps_option = nullptr;  // given or not: --slow-motion sets fps otherwise
  CLI::Option* t0_option = nullptr;
  CLI::Option* t1_option = nullptr;
};

// Frame rate, size, camera, colours and time range: what each frame shows.
void add_frame_options(CLI::App& command, RenderOptions& options, RenderCommandText& text) {
  text.fps_option =
      command.add_option("--fps", options.fps,
                         "frames rendered per second of simulated time (default: slow motion "
                         "x playback rate)");
  command.add_option("--slow-motion", text.slow_motion,
                     "seconds of video per second of simulated time (e.g. 50: 0.1 s of "
                     "motion lasts 5 s); sets --fps to this x the playback rate")
      ->capture_default_str()
      ->excludes(text.fps_option);
  command.add_option("--playback-fps", options.playback_fps,
                     "frames per second of the video (MP4, GIF)")
      ->capture_default_str();
  command.add_option("--size", text.size, "frame size WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  command.add_option("--camera", text.camera, "view: iso, front, top or side")
      ->capture_default_str();
  command.add_flag("--follow", options.follow, "camera follows the bodies' centroid");
  command.add_option("--scale", options.scale, "deformation scale factor")->capture_default_str();
  command.add_option("--color", text.color,
                     "colour flexible bodies by: deflection (|u| [m]) or von_mises (recovered "
                     "element stress [MPa]: shells' von Mises, beams' extreme-fibre stress; needs "
                     "a run whose bodies have 'stress' output)")
      ->capture_default_str();
  command.add_option("--color-map", text.color_map,
                     "viridis (perceptually uniform) or rainbow (blue to red, the map before)")
      ->capture_default_str();
  text.t0_option = command.add_option("--t0", text.t0, "first time rendered [s]");
  text.t1_option = command.add_option("--t1", text.t1, "last time rendered [s]");
}

// The files written (video, GIF, ParaView), the scene's extras, anti-aliasing and progress.
void add_output_options(CLI::App& command, RenderOptions& options, RenderCommandText& text) {
  command.add_flag("--gif", options.write_gif, "also write DIR/animation.gif");
  command.add_flag("--no-video", text.no_video, "skip DIR/animation.mp4");
  CLI::Option* paraview_option = command.add_option(
      "--paraview", text.paraview,
      "ParaView output in DIR/vtk: xdmf (one scene.xmf over one scene.h5, every sample, and "
      "open_in_paraview.py: paraview --script=DIR/vtk/open_in_paraview.py), pvd (scene.pvd and "
      "one .vtu per body and sample), both, or none");
  paraview_option->capture_default_str();
  command.add_flag("--no-vtk", text.no_vtk, "same as --paraview none")->excludes(paraview_option);
  command.add_flag("!--no-ground", options.ground, "no ground plane");
  command.add_flag("!--no-joint-axes", options.joint_axes,
                   "no joint axis glyphs (revolute: a cylinder along the pin axis; "
                   "translational: an arrow along the slide axis and the rail over its travel)");
  command.add_flag("--ghost", options.ghost,
                   "draw each flexible body's undeformed outline (at the rigid fit through its "
                   "joints) under the deformed, scaled shape");
  command.add_flag("--forces", options.forces,
                   "draw the reaction force and torque on body j at every joint as arrows over "
                   "the bodies (the torque double-headed, right-hand rule), each scaled to a "
                   "round number of N (N m) per metre stated in a legend");
  CLI::Option* aa_option = command.add_option(
      "--anti-aliasing", text.anti_aliasing,
      "fxaa (on the finished frame, on the CPU), gl-fxaa (VTK's OpenGL pass: about half the "
      "frame rate in software) or none (jagged edges)");
  aa_option->capture_default_str();
  command.add_flag("--no-fxaa", text.no_fxaa, "same as --anti-aliasing none")->excludes(aa_option);
  command.add_flag("!--no-progress", options.progress, "no progress bar");
}

// Turns the textual options into RenderOptions (InputError on a bad value).
void resolve_options(const RenderCommandText& text, RenderOptions& options) {
  parse_frame_size(text.size, options.width, options.height);
  options.camera = parse_camera_preset(text.camera);
  options.color = parse_color_by(text.color);
  options.color_map = parse_color_map(text.color_map);
  options.paraview = text.no_vtk ? ParaViewOutput::kNone : parse_paraview_output(text.paraview);
  options.anti_aliasing =
      text.no_fxaa ? AntiAliasing::kNone : parse_anti_aliasing(text.anti_aliasing);
  if (text.fps_option->count() == 0) options.fps = text.slow_motion * options.playback_fps;
  if (text.t0_option->count() > 0) options.t0 = text.t0;
  if (text.t1_option->count() > 0) options.t1 = text.t1;
  options.write_video = !text.no_video;
}

// What was written, the frame rates, and the warnings (on stderr).
void print_summary(const RenderSummary& summary, const RenderOptions& options) {
  fmt::print("rendered {} frames of t = [{}, {}] s at {}x{} ({})\n", summary.frames, summary.t0,
             summary.t1, options.width, options.height, summary.backend);
  const std::filesystem::path vtk = options.directory / results::kVtkFolder;
  if (summary.xdmf_samples > 0) {
    fmt::print("  ParaView: {} ({} time steps over {}); open with\n"
               "    paraview --script={}\n",
               (vtk / xdmf::kDescriptionName).string(), summary.xdmf_samples, xdmf::kFileName,
               (vtk / xdmf::kScriptName).string());
  }
  if (summary.vtu_files > 0) {
    fmt::print("  ParaView: {} ({} VTU files)\n", (vtk / results::kVtkSceneFileName).string(),
               summary.vtu_files);
  }
  if (options.paraview != ParaViewOutput::kNone) {
    fmt::print("  ParaView output written in {:.2f} s\n", summary.paraview_seconds);
  }
  fmt::print("  {:g} frames per simulated second played at {:g} frames/s: {:g}x slow motion, "
             "{:.2f} s of video\n",
             options.fps, options.playback_fps, render::slow_motion(options),
             summary.frames / options.playback_fps);
  if (summary.frames > 0) {
    fmt::print("  {:.1f} frames/s wall clock; {}\n",
               summary.frames / std::max(summary.wall_seconds, 1e-9),
               (options.directory / results::kFramesFolder).string());
  }
  if (!summary.video.empty()) fmt::print("  video: {}\n", summary.video.string());
  if (!summary.gif.empty()) fmt::print("  gif: {}\n", summary.gif.string());
  for (const std::string& warning : summary.warnings) {
    fmt::print(stderr, "limber render: warning: {}\n", warning);
  }
}

}  // namespace

cli::Command add_render_command(CLI::App& app) {
  // Options live as long as the app (run() is called after parsing).
  auto options = std::make_shared<RenderOptions>();
  auto text = std::make_shared<RenderCommandText>();
  CLI::App* command = app.add_subcommand(
      "render", "Render DIR/results.h5 offscreen: PNG, MP4, a ParaView scene");
  command->add_option("DIR", options->directory, "run directory holding results.h5")
      ->required();
  add_frame_options(*command, *options, *text);
  add_output_options(*command, *options, *text);

  auto run = [=] {
    resolve_options(*text, *options);
    print_summary(render_results(*options), *options);
    return cli::kExitOk;
  };
  return {command, run};
}

}  // namespace limber::render
