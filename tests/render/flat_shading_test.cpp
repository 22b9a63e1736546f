// flat_surface_color against VTK's own shader: a plane drawn lit by the light kit (the
// renderer's fragment shader, rendered offscreen) must have the colour computed on the CPU,
// and drawn unlit in that colour the same pixels. Tolerance: 1 of 255, the 8-bit rounding of
// the frame buffer (the shader computes in single precision, the CPU in double).
#include "flat_shading.h"

#include "egl_context.h"
#include "egl_render_window.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkLightKit.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <cstdlib>

namespace limber::render {
namespace {

constexpr int kSize = 64;
constexpr int kTolerance = 1;  // of 255: the frame buffer's rounding

class FlatShadingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    unsetenv("DISPLAY");
    try {
      context_.emplace(kSize, kSize);
    } catch (const std::exception& error) {
      GTEST_SKIP() << "no offscreen OpenGL context: " << error.what();
    }
    window_->attach_to_current_context(kSize, kSize);
    window_->AddRenderer(renderer_);
    renderer_->SetBackground(0.0, 0.0, 0.0);
    vtkNew<vtkLightKit> lights;
    lights->AddLightsToRenderer(renderer_);
    // A plane of 2 x 2 m through the origin with normal n, as the scene's ground is drawn.
    plane_->SetOrigin(-1.0, -1.0, 0.0);
    plane_->SetPoint1(1.0, -1.0, 0.0);
    plane_->SetPoint2(-1.0, 1.0, 0.0);
    mapper_->SetInputConnection(plane_->GetOutputPort());
    actor_->SetMapper(mapper_);
    actor_->GetProperty()->SetColor(0.72, 0.72, 0.68);
    actor_->GetProperty()->SetAmbient(0.3);
    renderer_->AddActor(actor_);
  }
  void TearDown() override {
    if (!context_) return;
    context_->make_current();
    window_->Finalize();
  }

  // Camera 3 m from the origin along `from` (unit), looking at it; the plane fills the middle.
  void look_from(const Eigen::Vector3d& from) {
    vtkCamera* camera = renderer_->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(3.0 * from.x(), 3.0 * from.y(), 3.0 * from.z());
    const bool vertical = std::abs(from.z()) > 0.99;
    camera->SetViewUp(0.0, vertical ? 1.0 : 0.0, vertical ? 0.0 : 1.0);
    renderer_->ResetCameraClippingRange();
  }

  // The centre pixel of a render, 0..255.
  Eigen::Vector3i centre_pixel() {
    window_->Render();
    vtkNew<vtkUnsignedCharArray> pixel;
    window_->GetPixelData(kSize / 2, kSize / 2, kSize / 2, kSize / 2, 0, pixel, 0);
    return {pixel->GetValue(0), pixel->GetValue(1), pixel->GetValue(2)};
  }

  static Eigen::Vector3i bytes(const Eigen::Vector3d& color) {
    return (255.0 * color).array().round().cast<int>();
  }

  std::optional<EglContext> context_;
  vtkNew<EglRenderWindow> window_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<vtkPlaneSource> plane_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
};

TEST_F(FlatShadingTest, LitPlaneHasTheComputedColourAndUnlitDrawsTheSame) {
  // Above (as the iso, top and follow cameras see the ground), from below (two-sided
  // lighting), and grazing.
  for (const Eigen::Vector3d& from :
       {Eigen::Vector3d(1.0, -1.0, 0.8).normalized(), Eigen::Vector3d(0.0, 0.0, 1.0),
        Eigen::Vector3d(0.3, 0.5, -0.8).normalized(), Eigen::Vector3d(-0.9, 0.2, 0.3).normalized()}) {
    SCOPED_TRACE(::testing::Message() << "camera from " << from.transpose());
    actor_->GetProperty()->LightingOn();
    actor_->GetProperty()->SetAmbient(0.3);
    actor_->GetProperty()->SetDiffuse(1.0);
    actor_->GetProperty()->SetColor(0.72, 0.72, 0.68);
    look_from(from);
    const Eigen::Vector3i lit = centre_pixel();
    const std::optional<Eigen::Vector3d> color = flat_surface_color(
        renderer_, actor_->GetProperty(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
    ASSERT_TRUE(color.has_value());
    EXPECT_LE((bytes(*color) - lit).cwiseAbs().maxCoeff(), kTolerance)
        << "computed " << bytes(*color).transpose() << ", VTK drew " << lit.transpose();

    set_unlit_color(actor_->GetProperty(), *color);
    const Eigen::Vector3i unlit = centre_pixel();
    EXPECT_LE((unlit - lit).cwiseAbs().maxCoeff(), kTolerance)
        << "unlit " << unlit.transpose() << ", lit " << lit.transpose();
  }
}

TEST_F(FlatShadingTest, NoSingleColourWithSpecularOrPositionalLights) {
  look_from(Eigen::Vector3d::UnitZ());
  actor_->GetProperty()->SetSpecular(0.2);
  EXPECT_FALSE(flat_surface_color(renderer_, actor_->GetProperty(), Eigen::Vector3d::Zero(),
                                  Eigen::Vector3d::UnitZ()));
  actor_->GetProperty()->SetSpecular(0.0);
  vtkNew<vtkLight> spot;
  spot->SetPositional(true);
  renderer_->AddLight(spot);
  EXPECT_FALSE(flat_surface_color(renderer_, actor_->GetProperty(), Eigen::Vector3d::Zero(),
                                  Eigen::Vector3d::UnitZ()));
}

}  // namespace
}  // namespace limber::render
