#include "world_triad.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCoordinate.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkTransform.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace limber::render {
namespace {

// vtkArrowSource's tip radius, as a fraction of the arrow's length: the arrows' half width.
constexpr double kArrowRadius = 0.1;

vtkSmartPointer<vtkTextActor> make_label(const std::string& text, int font) {
  auto label = vtkSmartPointer<vtkTextActor>::New();
  label->SetInput(text.c_str());
  label->GetTextProperty()->SetFontSize(font);
  label->GetTextProperty()->SetColor(0.1, 0.1, 0.15);
  label->GetTextProperty()->SetJustificationToCentered();
  label->GetTextProperty()->SetVerticalJustificationToCentered();
  label->GetPositionCoordinate()->SetCoordinateSystemToWorld();
  return label;
}

}  // namespace

double round_length(double about) {
  const double decade = std::pow(10.0, std::floor(std::log10(about)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= 0.7 * about) return m * decade;
  }
  return 10.0 * decade;
}

WorldTriad::WorldTriad(vtkRenderer* renderer, double length, int font, const std::array<std::string, 3>& names)
    : length_(length), names_(names) {
  const std::array<std::array<double, 3>, 3> colors{{{0.80, 0.15, 0.15}, {0.15, 0.60, 0.20}, {0.15, 0.30, 0.85}}};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    auto arrow = vtkSmartPointer<vtkArrowSource>::New();
    arrow->SetTipResolution(16);
    arrow->SetShaftResolution(16);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(arrow->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    arrows_[axis] = vtkSmartPointer<vtkTransform>::New();
    actor->SetUserTransform(arrows_[axis]);
    actor->GetProperty()->SetColor(colors[axis][0], colors[axis][1], colors[axis][2]);
    actor->GetProperty()->SetAmbient(0.3);
    renderer->AddActor(actor);
    labels_.push_back(make_label(names[axis], font));
    renderer->AddViewProp(labels_.back());
  }
  set_length(length);
  place(Eigen::Vector3d::Zero());
}

void WorldTriad::set_length(double length) {
  length_ = length;
  // The z label also states the arrows' length: above the triad it stays clear of the other
  // arrows in every view.
  char length_text[48];
  std::snprintf(length_text, sizeof length_text, "%s (arrows %g m)", names_[2].c_str(), length);
  labels_[2]->SetInput(length_text);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    label_offsets_[axis] = (axis == 2 ? 1.35 : 1.2) * length * Eigen::Vector3d::Unit(static_cast<int>(axis));
  }
}

void WorldTriad::place(const Eigen::Vector3d& origin_W) {
  for (std::size_t axis = 0; axis < 3; ++axis) {
    // vtkArrowSource points along +x from 0 to 1: scale, then turn onto the axis.
    vtkTransform* transform = arrows_[axis];
    transform->Identity();
    transform->Translate(origin_W.x(), origin_W.y(), origin_W.z());
    if (axis == 1) transform->RotateZ(90.0);
    if (axis == 2) transform->RotateY(-90.0);
    transform->Scale(length_, length_, length_);
    const Eigen::Vector3d at = origin_W + label_offsets_[axis];
    labels_[axis]->GetPositionCoordinate()->SetValue(at.x(), at.y(), at.z());
  }
}

ViewRect WorldTriad::footprint(const Eigen::Vector3d& origin_W,
                               const std::function<Eigen::Vector2d(const Eigen::Vector3d&)>& to_viewport,
                               int width, int height) const {
  ViewRect r{1e300, -1e300, 1e300, -1e300};
  auto add = [&r](const Eigen::Vector2d& v) {
    r.x0 = std::min(r.x0, v.x()), r.x1 = std::max(r.x1, v.x());
    r.y0 = std::min(r.y0, v.y()), r.y1 = std::max(r.y1, v.y());
  };
  // Each arrow inside the box from its origin to its tip widened by its tip's radius.
  const double pad = kArrowRadius * length_;
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d tip = origin_W + length_ * Eigen::Vector3d::Unit(axis);
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d corner((c & 1) ? tip.x() + pad : origin_W.x() - pad,
                                   (c & 2) ? tip.y() + pad : origin_W.y() - pad,
                                   (c & 4) ? tip.z() + pad : origin_W.z() - pad);
      add(to_viewport(corner));
    }
  }
  // Each label's text box about its projected anchor (centred both ways).
  for (std::size_t axis = 0; axis < 3; ++axis) {
    int box[4];  // pixels about the anchor: x min, x max, y min, y max
    vtkTextActor* label = labels_[axis];
    if (!vtkTextRenderer::GetInstance()->GetBoundingBox(label->GetTextProperty(), label->GetInput(), box, kTextDpi)) {
      continue;
    }
    const Eigen::Vector2d anchor = to_viewport(origin_W + label_offsets_[axis]);
    add(anchor + Eigen::Vector2d(static_cast<double>(box[0]) / width, static_cast<double>(box[2]) / height));
    add(anchor + Eigen::Vector2d(static_cast<double>(box[1] + 1) / width, static_cast<double>(box[3] + 1) / height));
  }
  return r;
}

}  // namespace limber::render
