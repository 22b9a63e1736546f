#include "egl_render_window.h"

#include <vtkObjectFactory.h>
#include <vtk_glew.h>

namespace limber::render {

vtkStandardNewMacro(EglRenderWindow);

void EglRenderWindow::attach_to_current_context(int width, int height) {
  // Single-sampled: software multisampling costs ~6x a frame (docs/benchmarks.md).
  SetMultiSamples(0);
  SetSize(width, height);
  SetMapped(1);
  SetIsCurrent(true);
  SetReadyForRendering(true);
  SetFrameBlitModeToNoBlit();
  InitializeFromCurrentContext();
}

void EglRenderWindow::OpenGLInitContext() {
  ContextCreationTime.Modified();
  if (Initialized) return;

  // Load the OpenGL entry points; a GLX-display failure comes after they were all loaded.
  const GLenum result = glewInit();
  const bool gl_loaded = result == GLEW_OK || result == GLEW_ERROR_NO_GLX_DISPLAY;
  if (!gl_loaded) {
    vtkErrorMacro("GLEW could not load OpenGL: "
                  << reinterpret_cast<const char*>(glewGetErrorString(result)));
    return;
  }
  if (!GLEW_VERSION_3_2) {
    vtkErrorMacro("the EGL context does not provide OpenGL 3.2, which VTK needs");
    return;
  }
  GlewInitValid = true;
  Initialized = true;

  // The rest of the base initialisation: the hardware line-width limit.
  GLfloat range[2] = {1.0f, 1.0f};
  MaximumHardwareLineWidth = 1.0f;
  glGetFloatv(LineSmoothing ? GL_SMOOTH_LINE_WIDTH_RANGE : GL_ALIASED_LINE_WIDTH_RANGE, range);
  if (glGetError() == GL_NO_ERROR) MaximumHardwareLineWidth = range[1];
}

}  // namespace limber::render
