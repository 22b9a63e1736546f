#include "primitive_source.h"

#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkSphereSource.h>

namespace limber::render {

vtkSmartPointer<vtkPolyDataAlgorithm> primitive_source(const Shape& shape, vtkTransform* transform) {
  if (shape.type == Shape::Type::kBox) {
    auto box = vtkSmartPointer<vtkCubeSource>::New();
    box->SetXLength(shape.size.x());
    box->SetYLength(shape.size.y());
    box->SetZLength(shape.size.z());
    return box;
  }
  if (shape.type == Shape::Type::kCylinder) {
    auto cylinder = vtkSmartPointer<vtkCylinderSource>::New();
    cylinder->SetRadius(shape.size.x());
    cylinder->SetHeight(shape.size.z());
    cylinder->SetResolution(32);
    transform->RotateX(90.0);
    return cylinder;
  }
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetRadius(shape.size.x());
  return sphere;
}

}  // namespace limber::render
