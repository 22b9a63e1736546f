#include "scene_labels.h"

#include "event_stamp.h"

#include <vtkCoordinate.h>
#include <vtkLookupTable.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>

namespace limber::render {
namespace {

// Display coordinates (pixels, x right, y up) to columns and rows from the top, widened by
// `margin` pixels and clipped to the frame.
PixelBox pixel_box(int width, int height, double x_min, double x_max, double y_min, double y_max,
                   int margin) {
  PixelBox b;
  b.x0 = std::max(0, static_cast<int>(std::floor(x_min)) - margin);
  b.x1 = std::min(width, static_cast<int>(std::ceil(x_max)) + 1 + margin);
  b.y0 = std::max(0, height - 1 - static_cast<int>(std::ceil(y_max)) - margin);
  b.y1 = std::min(height, height - static_cast<int>(std::floor(y_min)) + margin);
  return b;
}

// A text's display bounds (pixels, x right, y up: x min, x max, y min, y max): its bounding box
// about the anchor (justification included) moved to the anchor's pixel; nothing for an empty
// text.
std::optional<std::array<double, 4>> display_bounds(vtkTextActor* text, vtkRenderer* renderer) {
  double b[4];  // x min, x max, y min, y max
  text->GetBoundingBox(renderer, b);
  const int* anchor = text->GetPositionCoordinate()->GetComputedDisplayValue(renderer);
  if (b[1] < b[0] || b[3] < b[2]) return std::nullopt;  // nothing drawn
  return std::array<double, 4>{anchor[0] + b[0], anchor[0] + b[1], anchor[1] + b[2], anchor[1] + b[3]};
}

// A text's pixels widened by `margin`, clipped to the frame; nothing for an empty text.
std::optional<PixelBox> text_box(vtkTextActor* text, vtkRenderer* renderer, int width, int height,
                                 int margin) {
  const auto b = display_bounds(text, renderer);
  if (!b) return std::nullopt;
  return pixel_box(width, height, (*b)[0], (*b)[1], (*b)[2], (*b)[3], margin);
}

// A text's box in pixels before it is drawn (at kTextDpi, frame_layout.h): width and height.
Eigen::Vector2d measured_size(vtkTextActor* text) {
  int b[4];
  if (!vtkTextRenderer::GetInstance()->GetBoundingBox(text->GetTextProperty(), text->GetInput(), b, kTextDpi)) {
    return Eigen::Vector2d::Zero();
  }
  return {b[1] - b[0] + 1.0, b[3] - b[2] + 1.0};
}

// Where the title is anchored (normalised viewport coordinates, bottom left of its last line).
constexpr double kTitleX = 0.02;
constexpr double kTitleY = 0.93;

}  // namespace

SceneLabels::SceneLabels(vtkRenderer* renderer, const RenderOptions& options)
    : renderer_(renderer), options_(options), time_text_(vtkSmartPointer<vtkTextActor>::New()),
      event_text_(vtkSmartPointer<vtkTextActor>::New()) {}

void SceneLabels::add_texts(const std::vector<vtkSmartPointer<vtkTextActor>>& texts) {
  for (const auto& text : texts) texts_.push_back(text);
}

void SceneLabels::add_color_bar(vtkLookupTable* lut, const std::string& title) {
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(lut);
  bar->SetTitle(title.c_str());
  bar->SetLabelFormat("%.3g");
  bar->SetNumberOfLabels(5);
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(kColorBarBox[0], kColorBarBox[1]);
  bar->SetWidth(kColorBarBox[2]);
  bar->SetHeight(kColorBarBox[3]);
  bar->SetBarRatio(0.3);
  bar->SetTextPositionToSucceedScalarBar();
  bar->UnconstrainedFontSizeOn();
  bar_font_ = std::max(kMinFontSize, options_.height / 45);
  // Labels clear of the bar and the title clear of the top label (VTK's defaults let them
  // touch).
  bar->SetTextPad(std::max(4, bar_font_ / 2));
  bar->SetVerticalTitleSeparation(bar_font_);
  for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
    text->SetColor(0.1, 0.1, 0.15);
    text->SetFontSize(bar_font_);
    text->ShadowOff();
    text->BoldOff();
    text->ItalicOff();
  }
  renderer_->AddViewProp(bar);
  bar_ = bar;
}

int SceneLabels::stamp_font() const { return std::max(kMinFontSize, options_.height / 36); }

void SceneLabels::add_title_legend_and_stamps(const Results& results, const std::vector<RigidFitBasis>& fits,
                                              const std::vector<std::vector<std::string>>& fit_joints) {
  // Title, deformation scale note, time stamp.
  const RenderOptions& options = options_;
  const int font = stamp_font();
  title_ = add_text(results.title, std::max(kMinFontSize, options.height / 30), kTitleX, kTitleY, false);
  // What is scaled, and what the colours measure: the elastic displacement relative to a rigid
  // fit through each flexible body's joint nodes (those without joints: relative to their
  // floating frame).
  // Only when some body is fitted: otherwise what is scaled is plain u, as always.
  std::string legend;
  bool fitted = false;
  for (const RigidFitBasis& fit : fits) fitted = fitted || !fit.anchors.empty();
  for (std::size_t b = 0; b < results.bodies.size() && fitted; ++b) {
    if (!results.bodies[b].flexible) continue;
    std::string joints;
    for (const std::string& name : fit_joints[b]) joints += (joints.empty() ? "" : ", ") + name;
    legend += "\n" + results.bodies[b].name + ": " +
              (joints.empty() ? "u in its floating frame" : "u relative to a rigid fit through " + joints);
  }
  // Top right under the title until the layout places it (place_legend).
  if (options.scale != 1.0 || !legend.empty()) {
    char note[64];
    std::snprintf(note, sizeof note, legend.empty() ? "deformation x %g" : "deformation x %g of the elastic displacement u",
                  options.scale);
    legend_ = add_text(note + legend, std::max(kMinFontSize, options.height / 40), 0.98, title_bottom(), true);
    legend_->GetTextProperty()->SetVerticalJustificationToTop();
  }
  time_text_->GetTextProperty()->SetFontSize(font);
  time_text_->GetTextProperty()->SetColor(0.1, 0.1, 0.15);
  time_text_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  time_text_->GetPositionCoordinate()->SetValue(0.02, 0.03);
  if (options.time_stamp) {
    renderer_->AddViewProp(time_text_);
    texts_.push_back(time_text_);
  }
  // Hinge events, right of the time stamp, dark red (event_stamp.h).
  event_hold_ = event_hold(options.fps, options.playback_fps);
  if (options.time_stamp && !results.events.empty()) {
    event_text_->GetTextProperty()->SetFontSize(font);
    event_text_->GetTextProperty()->SetColor(0.6, 0.05, 0.05);
    event_text_->GetTextProperty()->BoldOn();
    event_text_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    event_text_->GetPositionCoordinate()->SetValue(0.36, 0.03);
    renderer_->AddViewProp(event_text_);
    texts_.push_back(event_text_);
  }
}

double SceneLabels::title_bottom() const {
  int b[4];  // about the anchor, bottom-left justified
  vtkTextRenderer* measure = vtkTextRenderer::GetInstance();
  if (!title_ || !measure->GetBoundingBox(title_->GetTextProperty(), title_->GetInput(), b, kTextDpi)) {
    return kTitleY;
  }
  // A gap of a quarter of the title's font under its lowest pixel.
  const double gap = 0.25 * title_->GetTextProperty()->GetFontSize();
  return kTitleY + (std::min(b[2], 0) - gap) / options_.height;
}

Eigen::Vector2d SceneLabels::legend_size() const {
  if (!legend_) return Eigen::Vector2d::Zero();
  const Eigen::Vector2d pixels = measured_size(legend_);
  return {pixels.x() / options_.width, pixels.y() / options_.height};
}

void SceneLabels::place_legend(const ViewRect& rect, bool right) {
  if (!legend_) return;
  vtkTextProperty* text = legend_->GetTextProperty();
  if (right) {
    text->SetJustificationToRight();
  } else {
    text->SetJustificationToLeft();
  }
  legend_->GetPositionCoordinate()->SetValue(right ? rect.x1 : rect.x0, rect.y1);
}

void SceneLabels::update(const Results& results, double t) {
  char stamp[96];
  const double slow = slow_motion(options_);
  if (std::abs(slow - 1.0) < 1e-9) {
    std::snprintf(stamp, sizeof stamp, "t = %.4f s", t);
  } else {
    std::snprintf(stamp, sizeof stamp, "t = %.4f s  (%.3gx slow motion)", t, slow);
  }
  time_text_->SetInput(stamp);
  event_text_->SetInput(event_stamp(results.events, t, event_hold_).c_str());
}

vtkSmartPointer<vtkTextActor> SceneLabels::add_text(const std::string& text, int size, double x, double y,
                                                    bool right) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.c_str());
  actor->GetTextProperty()->SetFontSize(size);
  actor->GetTextProperty()->SetColor(0.1, 0.1, 0.15);
  if (right) actor->GetTextProperty()->SetJustificationToRight();
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  renderer_->AddViewProp(actor);
  texts_.push_back(actor);
  return actor;
}

std::vector<PixelBox> SceneLabels::overlay_boxes() const {
  const int width = options_.width;
  const int height = options_.height;
  std::vector<PixelBox> boxes;

  // Texts, plus 2 pixels (FXAA reads the neighbours).
  for (const auto& text : texts_) {
    if (const auto b = text_box(text, renderer_, width, height, 2)) boxes.push_back(*b);
  }

  // Colour bar: its box, plus one label height, which its title and labels may overrun.
  if (bar_) {
    const double x = kColorBarBox[0] * width;
    const double y = kColorBarBox[1] * height;
    boxes.push_back(pixel_box(width, height, x, x + kColorBarBox[2] * width, y,
                              y + kColorBarBox[3] * height, bar_font_));
  }
  return boxes;
}

std::vector<Scene::DrawnText> SceneLabels::drawn_texts() const {
  std::vector<Scene::DrawnText> drawn;
  for (const auto& text : texts_) {
    const auto b = text_box(text, renderer_, options_.width, options_.height, 0);
    if (!b) continue;
    const std::string input = text->GetInput() != nullptr ? text->GetInput() : "";
    // Display pixels run from 0 to width - 1 (height - 1): a box past them is cut off.
    const std::array<double, 4> d = *display_bounds(text, renderer_);
    const bool clipped = d[0] < 0.0 || d[1] > options_.width - 1.0 || d[2] < 0.0 || d[3] > options_.height - 1.0;
    drawn.push_back({input, 1 + static_cast<int>(std::count(input.begin(), input.end(), '\n')), *b, clipped});
  }
  return drawn;
}

}  // namespace limber::render
