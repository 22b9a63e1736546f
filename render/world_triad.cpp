#include "world_triad.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace limber::render {
namespace {

void add_label(vtkRenderer* renderer, const std::string& text, const Eigen::Vector3d& at, int font) {
  auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
  label->SetInput(text.c_str());
  label->SetPosition(at.x(), at.y(), at.z());
  label->GetTextProperty()->SetFontSize(font);
  label->GetTextProperty()->SetColor(0.1, 0.1, 0.15);
  label->GetTextProperty()->SetJustificationToCentered();
  label->GetTextProperty()->SetVerticalJustificationToCentered();
  renderer->AddActor(label);
}

}  // namespace

double round_length(double about) {
  const double decade = std::pow(10.0, std::floor(std::log10(about)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= 0.7 * about) return m * decade;
  }
  return 10.0 * decade;
}

void add_world_triad(vtkRenderer* renderer, const Eigen::Vector3d& origin, double length, int font,
                     const std::array<std::string, 3>& names) {
  const std::array<std::array<double, 3>, 3> colors{{{0.80, 0.15, 0.15}, {0.15, 0.60, 0.20}, {0.15, 0.30, 0.85}}};
  for (int axis = 0; axis < 3; ++axis) {
    // vtkArrowSource points along +x from 0 to 1: scale, then turn onto the axis.
    auto arrow = vtkSmartPointer<vtkArrowSource>::New();
    arrow->SetTipResolution(16);
    arrow->SetShaftResolution(16);
    auto transform = vtkSmartPointer<vtkTransform>::New();
    transform->Translate(origin.x(), origin.y(), origin.z());
    if (axis == 1) transform->RotateZ(90.0);
    if (axis == 2) transform->RotateY(-90.0);
    transform->Scale(length, length, length);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(arrow->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->SetUserTransform(transform);
    const auto& c = colors[static_cast<std::size_t>(axis)];
    actor->GetProperty()->SetColor(c[0], c[1], c[2]);
    actor->GetProperty()->SetAmbient(0.3);
    renderer->AddActor(actor);
    // The z label also states the arrows' length: above the triad it stays clear of the
    // ground and of the other arrows in every view.
    char length_text[48];
    std::snprintf(length_text, sizeof length_text, "%s (arrows %g m)",
                  names[static_cast<std::size_t>(axis)].c_str(), length);
    add_label(renderer, axis == 2 ? std::string(length_text) : names[static_cast<std::size_t>(axis)],
              origin + (axis == 2 ? 1.35 : 1.2) * length * Eigen::Vector3d::Unit(axis), font);
  }
}

}  // namespace limber::render
