// The VTK render window used for offscreen rendering: a vtkGenericOpenGLRenderWindow driven by
// an EglContext that the caller made current (docs/rendering.md).
//
// Why a subclass: Debian's GLEW is built for GLX, and its glewInit() loads the OpenGL entry
// points, then the GLX ones; without an X display the GLX part returns
// GLEW_ERROR_NO_GLX_DISPLAY although every OpenGL entry point was loaded. VTK 9.1's
// vtkOpenGLRenderWindow::OpenGLInitContext() treats that as fatal: it logs "GLEW could not be
// initialized" and returns before marking the window initialised, so it retries (and logs) on
// every render and never queries the line-width range. This class overrides OpenGLInitContext()
// to accept exactly that one GLX-only failure when the OpenGL part is complete (a 3.2 context),
// and then finishes the same initialisation the base class does.
#pragma once

#include <vtkGenericOpenGLRenderWindow.h>

namespace limber::render {

class EglRenderWindow : public vtkGenericOpenGLRenderWindow {
 public:
  static EglRenderWindow* New();
  vtkTypeMacro(EglRenderWindow, vtkGenericOpenGLRenderWindow)

  // Binds the window to the current (EGL) context: current, mapped, ready for rendering,
  // width x height [pixels], no multisampling (FXAA is set on the renderer instead).
  void attach_to_current_context(int width, int height);

 protected:
  EglRenderWindow() = default;
  ~EglRenderWindow() override = default;

  // Loads OpenGL through GLEW, tolerating only GLEW's GLX-display failure; see above.
  void OpenGLInitContext() override;

 private:
  EglRenderWindow(const EglRenderWindow&) = delete;
  void operator=(const EglRenderWindow&) = delete;
};

}  // namespace limber::render
