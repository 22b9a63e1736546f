// Options of `limber render` and their validation (docs/rendering.md).
#pragma once

#include "color_map.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>

namespace limber::render {

// View directions; ground is the z = const plane, +z up.
enum class CameraPreset { kIso, kFront, kTop, kSide };

// Anti-aliasing of the frames (docs/rendering.md; costs in docs/benchmarks.md).
enum class AntiAliasing {
  kFxaa,    // FXAA on the CPU on the read-back frame (render/edge_smoothing.h), text and
            // colour bar left as drawn
  kGlFxaa,  // VTK's OpenGL FXAA pass before the text: about half the frame rate in llvmpipe
  kNone,    // jagged edges
};

// What flexible bodies are coloured by: elastic displacement magnitude |u| [m], or the
// recovered stress of each element [MPa] (results.h5 "Stress": a shell's larger surface von
// Mises stress, a beam's extreme-fibre stress; docs/stress-recovery.md).
enum class ColorBy { kDeflection, kVonMises };

// ParaView output in DIR/vtk (docs/rendering.md): the one-file XDMF scene (scene.xmf over
// scene.h5, render/xdmf_export.h, with open_in_paraview.py), the VTU/PVD series (scene.pvd and
// one .vtu per body and sample, render/vtk_export.h), both, or none.
enum class ParaViewOutput { kXdmf, kPvd, kBoth, kNone };

struct RenderOptions {
  std::filesystem::path directory;  // run directory holding results.h5; outputs go there
  // Sampling and playback are separate: `fps` frames are rendered per second of simulated time,
  // played at `playback_fps`, so one simulated second lasts fps / playback_fps seconds of video
  // (the slow-motion factor; `--slow-motion F` sets fps = F x playback_fps).
  double fps = 30.0;                // frames per second of simulated time [1/s]
  double playback_fps = 30.0;       // frames per second of video [1/s]
  int width = 1280;                 // frame size [pixels]
  int height = 720;
  CameraPreset camera = CameraPreset::kIso;
  bool follow = false;        // camera focal point follows the bodies' centroid
  double scale = 1.0;         // deformation scale factor (shown on the frame when != 1)
  ColorBy color = ColorBy::kDeflection;
  ColorMap color_map = ColorMap::kViridis;  // color_map.h; rainbow: limber's map before issue 28
  std::optional<double> t0;   // time range [s]; default: the whole run
  std::optional<double> t1;
  bool ground = true;         // draw a ground plane under the scene
  bool time_stamp = true;     // "t = ... s" bottom left (off for mode shapes)
  bool world_triad = true;    // ground x, y, z arrows of a round length (world_triad.h)
  // Orientation aids (scene_extras.h): joint axis glyphs and slider rails, an undeformed ghost
  // outline of flexible bodies, reaction force and torque arrows with scale legends.
  bool joint_axes = true;
  bool ghost = false;
  bool forces = false;
  // A camera direction (from the focal point towards the eye, ground axes) that replaces the
  // preset's; mode animations look along the normal of the mode's plane.
  std::optional<std::array<double, 3>> camera_direction;
  AntiAliasing anti_aliasing = AntiAliasing::kFxaa;  // ~2 ms per 1280 x 720 frame
  bool write_png = true;      // DIR/frames/frame_00000.png ...
  ParaViewOutput paraview = ParaViewOutput::kXdmf;
  bool write_video = true;    // DIR/animation.mp4 through the ffmpeg program
  bool write_gif = false;     // DIR/animation.gif
  bool progress = true;       // progress bar, shown only when stderr is a terminal
};

// Limits on the frame size [pixels]: at least kMinFrameSize, at most kMaxFrameSize per side.
inline constexpr int kMinFrameSize = 16;
inline constexpr int kMaxFrameSize = 8192;

// Parses "WxH" (e.g. "1280x720") into width and height; throws InputError (expected/got) on
// anything else or on sizes outside [kMinFrameSize, kMaxFrameSize].
void parse_frame_size(const std::string& text, int& width, int& height);

// Parses "iso", "front", "top" or "side"; throws InputError otherwise.
CameraPreset parse_camera_preset(const std::string& text);

// Parses "deflection" or "von_mises"; throws InputError otherwise.
ColorBy parse_color_by(const std::string& text);

// Parses "xdmf", "pvd", "both" or "none"; throws InputError otherwise.
ParaViewOutput parse_paraview_output(const std::string& text);

// The camera's direction, from the focal point towards the eye, ground axes, unit length:
// options.camera_direction when set, else the preset's.
std::array<double, 3> view_direction(const RenderOptions& options);

// Parses "fxaa", "gl-fxaa" or "none"; throws InputError otherwise.
AntiAliasing parse_anti_aliasing(const std::string& text);

// fps / playback_fps: how many times slower than real time the video runs (< 1: faster).
inline double slow_motion(const RenderOptions& options) { return options.fps / options.playback_fps; }

// Checks fps and playback_fps in (0, 1000] (fps up to 1e6: slow motion of fast events), a valid size, a finite scale and t0 <= t1 when both are given; throws
// InputError naming the option.
void validate(const RenderOptions& options);

}  // namespace limber::render
