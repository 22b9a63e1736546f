#include "render_command.h"

#include "render_job.h"
#include "results/file_names.h"
#include "xdmf_layout.h"

#include <fmt/core.h>

#include <algorithm>
#include <memory>

namespace limber::render {

cli::Command add_render_command(CLI::App& app) {
  // Options live as long as the app (run() is called after parsing).
  auto options = std::make_shared<RenderOptions>();
  auto size = std::make_shared<std::string>("1280x720");
  auto camera = std::make_shared<std::string>("iso");
  auto t0 = std::make_shared<double>(0.0);
  auto t1 = std::make_shared<double>(0.0);
  auto no_video = std::make_shared<bool>(false);
  auto anti_aliasing = std::make_shared<std::string>("fxaa");
  auto no_fxaa = std::make_shared<bool>(false);
  auto color = std::make_shared<std::string>("deflection");
  auto color_map = std::make_shared<std::string>("viridis");
  auto paraview = std::make_shared<std::string>("xdmf");
  auto no_vtk = std::make_shared<bool>(false);

  CLI::App* command = app.add_subcommand(
      "render", "Render DIR/results.h5 offscreen: PNG, MP4, a ParaView scene");
  command->add_option("DIR", options->directory, "run directory holding results.h5")
      ->required();
  auto slow_motion = std::make_shared<double>(1.0);
  CLI::Option* fps_option =
      command->add_option("--fps", options->fps,
                          "frames rendered per second of simulated time (default: slow motion "
                          "x playback rate)");
  command->add_option("--slow-motion", *slow_motion,
                          "seconds of video per second of simulated time (e.g. 50: 0.1 s of "
                          "motion lasts 5 s); sets --fps to this x the playback rate")
          ->capture_default_str()
          ->excludes(fps_option);
  command->add_option("--playback-fps", options->playback_fps,
                      "frames per second of the video (MP4, GIF)")
      ->capture_default_str();
  command->add_option("--size", *size, "frame size WIDTHxHEIGHT in pixels")->capture_default_str();
  command->add_option("--camera", *camera, "view: iso, front, top or side")->capture_default_str();
  command->add_flag("--follow", options->follow, "camera follows the bodies' centroid");
  command->add_option("--scale", options->scale, "deformation scale factor")->capture_default_str();
  command->add_option("--color", *color,
                      "colour flexible bodies by: deflection (|u| [m]) or von_mises (recovered "
                      "element stress [MPa]: shells' von Mises, beams' extreme-fibre stress; needs "
                      "a run whose bodies have 'stress' output)")
      ->capture_default_str();
  command->add_option("--color-map", *color_map,
                      "viridis (perceptually uniform) or rainbow (blue to red, the map before)")
      ->capture_default_str();
  CLI::Option* t0_option = command->add_option("--t0", *t0, "first time rendered [s]");
  CLI::Option* t1_option = command->add_option("--t1", *t1, "last time rendered [s]");
  command->add_flag("--gif", options->write_gif, "also write DIR/animation.gif");
  command->add_flag("--no-video", *no_video, "skip DIR/animation.mp4");
  CLI::Option* paraview_option = command->add_option(
      "--paraview", *paraview,
      "ParaView output in DIR/vtk: xdmf (one scene.xmf over one scene.h5, every sample, and "
      "open_in_paraview.py: paraview --script=DIR/vtk/open_in_paraview.py), pvd (scene.pvd and "
      "one .vtu per body and sample), both, or none");
  paraview_option->capture_default_str();
  command->add_flag("--no-vtk", *no_vtk, "same as --paraview none")->excludes(paraview_option);
  command->add_flag("!--no-ground", options->ground, "no ground plane");
  command->add_flag("!--no-joint-axes", options->joint_axes,
                    "no joint axis glyphs (revolute: a cylinder along the pin axis; "
                    "translational: an arrow along the slide axis and the rail over its travel)");
  command->add_flag("--ghost", options->ghost,
                    "draw each flexible body's undeformed outline (at the rigid fit through its "
                    "joints) under the deformed, scaled shape");
  command->add_flag("--forces", options->forces,
                    "draw the reaction force and torque on body j at every joint as arrows over "
                    "the bodies (the torque double-headed, right-hand rule), each scaled to a "
                    "round number of N (N m) per metre stated in a legend");
  CLI::Option* aa_option = command->add_option(
      "--anti-aliasing", *anti_aliasing,
      "fxaa (on the finished frame, on the CPU), gl-fxaa (VTK's OpenGL pass: about half the "
      "frame rate in software) or none (jagged edges)");
  aa_option->capture_default_str();
  command->add_flag("--no-fxaa", *no_fxaa, "same as --anti-aliasing none")->excludes(aa_option);
  command->add_flag("!--no-progress", options->progress, "no progress bar");

  auto run = [=] {
    // Turn the textual options into RenderOptions, then run.
    parse_frame_size(*size, options->width, options->height);
    options->camera = parse_camera_preset(*camera);
    options->color = parse_color_by(*color);
    options->color_map = parse_color_map(*color_map);
    options->paraview = *no_vtk ? ParaViewOutput::kNone : parse_paraview_output(*paraview);
    options->anti_aliasing = *no_fxaa ? AntiAliasing::kNone : parse_anti_aliasing(*anti_aliasing);
    if (fps_option->count() == 0) options->fps = *slow_motion * options->playback_fps;
    if (t0_option->count() > 0) options->t0 = *t0;
    if (t1_option->count() > 0) options->t1 = *t1;
    options->write_video = !*no_video;
    const RenderSummary summary = render_results(*options);
    fmt::print("rendered {} frames of t = [{}, {}] s at {}x{} ({})\n", summary.frames,
               summary.t0, summary.t1, options->width, options->height, summary.backend);
    const std::filesystem::path vtk = options->directory / results::kVtkFolder;
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
    if (options->paraview != ParaViewOutput::kNone) {
      fmt::print("  ParaView output written in {:.2f} s\n", summary.paraview_seconds);
    }
    fmt::print("  {:g} frames per simulated second played at {:g} frames/s: {:g}x slow motion, "
               "{:.2f} s of video\n",
               options->fps, options->playback_fps, render::slow_motion(*options),
               summary.frames / options->playback_fps);
    if (summary.frames > 0) {
      fmt::print("  {:.1f} frames/s wall clock; {}\n",
                 summary.frames / std::max(summary.wall_seconds, 1e-9),
                 (options->directory / results::kFramesFolder).string());
    }
    if (!summary.video.empty()) fmt::print("  video: {}\n", summary.video.string());
    if (!summary.gif.empty()) fmt::print("  gif: {}\n", summary.gif.string());
    for (const std::string& warning : summary.warnings) {
      fmt::print(stderr, "limber render: warning: {}\n", warning);
    }
    return cli::kExitOk;
  };
  return {command, run};
}

}  // namespace limber::render
