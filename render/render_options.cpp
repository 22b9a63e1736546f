#include "render_options.h"

#include "core/error.h"

#include <cmath>
#include <regex>

namespace limber::render {

void parse_frame_size(const std::string& text, int& width, int& height) {
  // WxH with positive integers.
  static const std::regex pattern(R"(\s*(\d{1,6})\s*[xX]\s*(\d{1,6})\s*)");
  std::smatch match;
  if (!std::regex_match(text, match, pattern)) {
    throw InputError("--size: expected WIDTHxHEIGHT in pixels (e.g. 1280x720), got '" + text + "'");
  }
  const int w = std::stoi(match[1].str());
  const int h = std::stoi(match[2].str());
  if (w < kMinFrameSize || h < kMinFrameSize || w > kMaxFrameSize || h > kMaxFrameSize) {
    throw InputError("--size: expected each side in " + std::to_string(kMinFrameSize) + ".." +
                     std::to_string(kMaxFrameSize) + " pixels, got '" + text + "'");
  }
  width = w;
  height = h;
}

CameraPreset parse_camera_preset(const std::string& text) {
  if (text == "iso") return CameraPreset::kIso;
  if (text == "front") return CameraPreset::kFront;
  if (text == "top") return CameraPreset::kTop;
  if (text == "side") return CameraPreset::kSide;
  throw InputError("--camera: expected iso, front, top or side, got '" + text + "'");
}

ColorBy parse_color_by(const std::string& text) {
  if (text == "deflection") return ColorBy::kDeflection;
  if (text == "von_mises") return ColorBy::kVonMises;
  throw InputError("--color: expected deflection or von_mises, got '" + text + "'");
}

ParaViewOutput parse_paraview_output(const std::string& text) {
  if (text == "xdmf") return ParaViewOutput::kXdmf;
  if (text == "pvd") return ParaViewOutput::kPvd;
  if (text == "both") return ParaViewOutput::kBoth;
  if (text == "none") return ParaViewOutput::kNone;
  throw InputError("--paraview: expected xdmf, pvd, both or none, got '" + text + "'");
}

std::array<double, 3> view_direction(const RenderOptions& options) {
  std::array<double, 3> d{0.0, 0.0, 1.0};
  if (options.camera_direction) {
    d = *options.camera_direction;
  } else {
    switch (options.camera) {
      case CameraPreset::kIso: d = {1.0, -1.0, 0.8}; break;
      case CameraPreset::kFront: d = {0.0, -1.0, 0.0}; break;
      case CameraPreset::kTop: d = {0.0, 0.0, 1.0}; break;
      case CameraPreset::kSide: d = {1.0, 0.0, 0.0}; break;
    }
  }
  const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / norm, d[1] / norm, d[2] / norm};
}

AntiAliasing parse_anti_aliasing(const std::string& text) {
  if (text == "fxaa") return AntiAliasing::kFxaa;
  if (text == "gl-fxaa") return AntiAliasing::kGlFxaa;
  if (text == "none") return AntiAliasing::kNone;
  throw InputError("--anti-aliasing: expected fxaa, gl-fxaa or none, got '" + text + "'");
}

void validate(const RenderOptions& options) {
  if (!(options.playback_fps > 0.0) || !std::isfinite(options.playback_fps) ||
      options.playback_fps > 1000.0) {
    throw InputError("--playback-fps: expected a frame rate in (0, 1000] frames/s, got " +
                     std::to_string(options.playback_fps));
  }
  if (!(options.fps > 0.0) || !std::isfinite(options.fps) || options.fps > 1e6) {
    throw InputError("--fps/--slow-motion: expected a sampling rate in (0, 1e6] frames per "
                     "simulated second, got " + std::to_string(options.fps));
  }
  if (options.width < kMinFrameSize || options.height < kMinFrameSize ||
      options.width > kMaxFrameSize || options.height > kMaxFrameSize) {
    throw InputError("--size: expected each side in " + std::to_string(kMinFrameSize) + ".." +
                     std::to_string(kMaxFrameSize) + " pixels, got " +
                     std::to_string(options.width) + "x" + std::to_string(options.height));
  }
  if (!std::isfinite(options.scale)) {
    throw InputError("--scale: expected a finite deformation scale factor, got " +
                     std::to_string(options.scale));
  }
  if (options.t0 && options.t1 && *options.t0 > *options.t1) {
    throw InputError("--t0/--t1: expected t0 <= t1, got t0 = " + std::to_string(*options.t0) +
                     " s > t1 = " + std::to_string(*options.t1) + " s");
  }
}

}  // namespace limber::render
