// A headless OpenGL context through EGL: no X server, no DISPLAY, no window.
//
// Display choice, in order:
//   1. the EGL device platform (EGL_EXT_platform_device) on the first device that is not Mesa's
//      software device — a GPU when a vendor driver (NVIDIA) or a Mesa DRM driver is present;
//   2. Mesa's surfaceless platform (EGL_PLATFORM_SURFACELESS_MESA), rendered by llvmpipe.
// On it: an RGBA8 + depth24 pbuffer of the frame size and an OpenGL 3.2 core-profile context,
// made current on the calling thread (VTK's OpenGL2 backend needs 3.2; docs/rendering.md).
#pragma once

#include <string>

namespace limber::render {

class EglContext {
 public:
  // Creates the context with a width x height pbuffer [pixels] and makes it current.
  // Throws std::runtime_error with the failing EGL step and error code when no display,
  // configuration or 3.2 core context is available.
  EglContext(int width, int height);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // Makes the context current on the calling thread again.
  void make_current();
  // "EGL device" or "EGL surfaceless (Mesa)": which route was taken.
  const std::string& platform() const { return platform_; }

 private:
  void* display_ = nullptr;
  void* surface_ = nullptr;
  void* context_ = nullptr;
  std::string platform_;
};

}  // namespace limber::render
