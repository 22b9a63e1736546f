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

AntiAliasing parse_anti_aliasing(const std::string& text) {
  if (text == "fxaa") return AntiAliasing::kFxaa;
  if (text == "gl-fxaa") return AntiAliasing::kGlFxaa;
  if (text == "none") return AntiAliasing::kNone;
  throw InputError("--anti-aliasing: expected fxaa, gl-fxaa or none, got '" + text + "'");
}

void validate(const RenderOptions& options) {
  if (!(options.fps > 0.0) || !std::isfinite(options.fps) || options.fps > 1000.0) {
    throw InputError("--fps: expected a frame rate in (0, 1000] frames/s, got " +
                     std::to_string(options.fps));
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
