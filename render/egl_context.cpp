#include "egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <vector>

namespace limber::render {
namespace {

[[noreturn]] void fail(const char* step) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  throw std::runtime_error(std::string("offscreen rendering: EGL failed to ") + step +
                           " (EGL error " + code + ")");
}

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + n, name)) {
    const bool starts = p == list || p[-1] == ' ';
    const bool ends = p[n] == '\0' || p[n] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

// An initialised display on the first non-software EGL device, or EGL_NO_DISPLAY.
EGLDisplay device_display(PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_EXT_platform_device")) return EGL_NO_DISPLAY;
  auto query_devices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto query_device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
      eglGetProcAddress("eglQueryDeviceStringEXT"));
  if (query_devices == nullptr || query_device_string == nullptr) return EGL_NO_DISPLAY;

  // Enumerate the devices, skip Mesa's software one (the surfaceless route covers it).
  EGLint count = 0;
  if (!query_devices(0, nullptr, &count) || count <= 0) return EGL_NO_DISPLAY;
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (!query_devices(count, devices.data(), &count)) return EGL_NO_DISPLAY;
  for (EGLint i = 0; i < count; ++i) {
    const char* extensions = query_device_string(devices[i], EGL_EXTENSIONS);
    if (has_extension(extensions, "EGL_MESA_device_software")) continue;
    EGLDisplay display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  }
  return EGL_NO_DISPLAY;
}

}  // namespace

EglContext::EglContext(int width, int height) {
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display == nullptr) fail("find eglGetPlatformDisplayEXT");

  // A GPU through the device platform first, else Mesa's surfaceless platform.
  EGLDisplay display = device_display(get_platform_display);
  platform_ = "EGL device";
  if (display == EGL_NO_DISPLAY) {
    display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
      fail("open a device or Mesa surfaceless display");
    }
    platform_ = "EGL surfaceless (Mesa)";
  }
  display_ = display;

  // An RGBA8 + depth24 pbuffer-capable desktop OpenGL configuration.
  const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                      EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                      EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                      EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &config_count) ||
      config_count == 0) {
    fail("find an RGBA8/depth24 pbuffer configuration");
  }

  // The pbuffer, then an OpenGL 3.2 core context on it.
  const EGLint pbuffer_attributes[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  surface_ = eglCreatePbufferSurface(display, config, pbuffer_attributes);
  if (surface_ == EGL_NO_SURFACE) fail("create a pbuffer");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("bind the desktop OpenGL API");
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                                       EGL_CONTEXT_MINOR_VERSION, 2,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  context_ = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context_ == EGL_NO_CONTEXT) fail("create an OpenGL 3.2 core context");
  make_current();
}

EglContext::~EglContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != nullptr) eglDestroyContext(display_, context_);
  if (surface_ != nullptr) eglDestroySurface(display_, surface_);
  eglTerminate(display_);
}

void EglContext::make_current() {
  if (!eglMakeCurrent(display_, surface_, surface_, context_)) fail("make the context current");
}

}  // namespace limber::render
