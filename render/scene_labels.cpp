#include "scene_labels.h"

#include "event_stamp.h"

#include <vtkCoordinate.h>
#include <vtkLookupTable.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
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

// A text's pixels: its bounding box about the anchor (justification included) moved to the
// anchor's pixel, widened by `margin`; nothing for an empty text.
std::optional<PixelBox> text_box(vtkTextActor* text, vtkRenderer* renderer, int width, int height,
                                 int margin) {
  double b[4];  // x min, x max, y min, y max
  text->GetBoundingBox(renderer, b);
  const int* anchor = text->GetPositionCoordinate()->GetComputedDisplayValue(renderer);
  if (b[1] < b[0] || b[3] < b[2]) return std::nullopt;  // nothing drawn
  return pixel_box(width, height, anchor[0] + b[0], anchor[0] + b[1], anchor[1] + b[2],
                   anchor[1] + b[3], margin);
}

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

double SceneLabels::add_title_legend_and_stamps(const Results& results, const std::vector<RigidFitBasis>& fits,
                                                const std::vector<std::vector<std::string>>& fit_joints) {
  // Title, deformation scale note, time stamp.
  const RenderOptions& options = options_;
  const int font = stamp_font();
  add_text(results.title, std::max(kMinFontSize, options.height / 30), 0.02, 0.93, false);
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
  // Under the title, right-aligned: the content is fitted below its last line.
  const int legend_font = std::max(kMinFontSize, options.height / 40);
  double content_top = 0.88;
  if (options.scale != 1.0 || !legend.empty()) {
    char note[64];
    std::snprintf(note, sizeof note, legend.empty() ? "deformation x %g" : "deformation x %g of the elastic displacement u",
                  options.scale);
    constexpr double kLegendTop = 0.905;
    add_text(note + legend, legend_font, 0.98, kLegendTop, true);
    texts_.back()->GetTextProperty()->SetVerticalJustificationToTop();
    // VTK spaces lines by 1.1 font sizes (vtkTextProperty's LineSpacing); 1.25 leaves a gap.
    const auto lines = 1 + std::count(legend.begin(), legend.end(), '\n');
    content_top = kLegendTop - 1.25 * static_cast<double>(lines * legend_font) / options.height;
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
  return content_top;
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

void SceneLabels::add_text(const std::string& text, int size, double x, double y, bool right) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.c_str());
  actor->GetTextProperty()->SetFontSize(size);
  actor->GetTextProperty()->SetColor(0.1, 0.1, 0.15);
  if (right) actor->GetTextProperty()->SetJustificationToRight();
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  renderer_->AddViewProp(actor);
  texts_.push_back(actor);
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
    drawn.push_back({input, 1 + static_cast<int>(std::count(input.begin(), input.end(), '\n')), *b});
  }
  return drawn;
}

}  // namespace limber::render
