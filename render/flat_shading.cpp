#include "flat_shading.h"

#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace limber::render {

std::optional<Eigen::Vector3d> flat_surface_color(vtkRenderer* renderer, vtkProperty* property,
                                                  const Eigen::Vector3d& p_W,
                                                  const Eigen::Vector3d& n_W) {
  if (property->GetSpecular() > 0.0) return std::nullopt;

  // The normal on the side the camera sees (two-sided lighting).
  vtkCamera* camera = renderer->GetActiveCamera();
  Eigen::Vector3d eye_W;
  camera->GetPosition(eye_W.data());
  Eigen::Vector3d n = n_W.normalized();
  const double side = n.dot(eye_W - p_W);
  if (side == 0.0) return std::nullopt;
  if (side < 0.0) n = -n;

  // Lights placed for the camera as a render places them (camera lights, headlights).
  renderer->UpdateLightsGeometryToFollowCamera();
  Eigen::Vector3d lit = Eigen::Vector3d::Zero();
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it)) {
    if (!light->GetSwitch()) continue;
    if (light->GetPositional()) return std::nullopt;
    Eigen::Vector3d position, focal;
    light->GetTransformedPosition(position.data());
    light->GetTransformedFocalPoint(focal.data());
    const Eigen::Vector3d d = (focal - position).normalized();
    Eigen::Vector3d color;
    light->GetDiffuseColor(color.data());
    lit += std::max(0.0, -n.dot(d)) * light->GetIntensity() * color;
  }

  Eigen::Vector3d ambient, diffuse;
  property->GetAmbientColor(ambient.data());
  property->GetDiffuseColor(diffuse.data());
  const Eigen::Vector3d color = property->GetAmbient() * ambient +
                                property->GetDiffuse() * diffuse.cwiseProduct(lit);
  return color.cwiseMax(0.0).cwiseMin(1.0);
}

void set_unlit_color(vtkProperty* property, const Eigen::Vector3d& color) {
  property->LightingOff();
  property->SetAmbient(0.0);
  property->SetDiffuse(1.0);
  property->SetDiffuseColor(color.x(), color.y(), color.z());
}

}  // namespace limber::render
