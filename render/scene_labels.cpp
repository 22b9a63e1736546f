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
#include <string>
#include <vector>

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

// Where the title is anchored (normalised viewport coordinates, bottom left of its first line;
// more lines go below it).
constexpr double kTitleX = 0.02;
constexpr double kTitleY = 0.93;
// The right end of the title's lines (normalised viewport x): the frame's margin.
constexpr double kTitleRight = 0.98;

// The size of `text` drawn with `property` [pixels] (at kTextDpi, frame_layout.h).
Eigen::Vector2d text_size(vtkTextProperty* property, const std::string& text) {
  int b[4];
  if (text.empty() || !vtkTextRenderer::GetInstance()->GetBoundingBox(property, text, b, kTextDpi)) {
    return Eigen::Vector2d::Zero();
  }
  return {b[1] - b[0] + 1.0, b[3] - b[2] + 1.0};
}

// A text's box in pixels before it is drawn: width and height.
Eigen::Vector2d measured_size(vtkTextActor* text) {
  return text_size(text->GetTextProperty(), text->GetInput() != nullptr ? text->GetInput() : "");
}

// The pieces a line may be broken between: its phrases (each up to and with its ", " or "; "
// separator's mark), and the words of a phrase wider than `max_width` pixels alone.
std::vector<std::string> line_pieces(const std::string& line, vtkTextProperty* property, double max_width) {
  std::vector<std::string> pieces;
  const auto add_phrase = [&](const std::string& phrase) {
    if (phrase.empty()) return;
    if (text_size(property, phrase).x() <= max_width) {
      pieces.push_back(phrase);
      return;
    }
    std::size_t start = 0;
    while (start < phrase.size()) {
      const std::size_t space = phrase.find(' ', start);
      const std::size_t end = space == std::string::npos ? phrase.size() : space;
      if (end > start) pieces.push_back(phrase.substr(start, end - start));
      start = end + 1;
    }
  };
  std::size_t start = 0;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    if ((line[k] == ',' || line[k] == ';') && line[k + 1] == ' ') {
      add_phrase(line.substr(start, k + 1 - start));
      start = k + 2;
    }
  }
  add_phrase(line.substr(start));
  return pieces;
}

// `text` with each line wider than `max_width` pixels broken, greedily, between its phrases
// (line_pieces), so that a long title stays whole inside a small frame.
std::string wrap_to_width(const std::string& text, vtkTextProperty* property, double max_width) {
  std::string wrapped;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t newline = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, newline - start);
    std::string current;
    for (const std::string& piece : text_size(property, line).x() <= max_width
                                        ? std::vector<std::string>{line}
                                        : line_pieces(line, property, max_width)) {
      const std::string longer = current.empty() ? piece : current + " " + piece;
      if (current.empty() || text_size(property, longer).x() <= max_width) {
        current = longer;
      } else {
        wrapped += current + "\n";
        current = piece;
      }
    }
    wrapped += current + (newline < text.size() ? "\n" : "");
    start = newline + 1;
  }
  return wrapped;
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

std::string SceneLabels::legend_text(const Results& results, double t) const {
  // What is scaled, and what the colours measure: the elastic displacement relative to a rigid
  // fit through the joint nodes that hold each flexible body at t (those without joints:
  // relative to their floating frame). Only when some body is fitted at some time: otherwise
  // what is scaled is plain u, as always.
  bool fitted = false;
  for (const TimedRigidFit& fit : *fits_) fitted = fitted || fit.any_anchor();
  std::string bodies;
  for (std::size_t b = 0; b < results.bodies.size() && fitted; ++b) {
    if (!results.bodies[b].flexible) continue;
    std::string joints;
    for (const std::string& name : (*fits_)[b].at(t).joints) joints += (joints.empty() ? "" : ", ") + name;
    bodies += "\n" + results.bodies[b].name + ": " +
              (joints.empty() ? "u in its floating frame" : "u relative to a rigid fit through " + joints);
  }
  if (options_.scale == 1.0 && bodies.empty()) return "";
  char note[64];
  std::snprintf(note, sizeof note, bodies.empty() ? "deformation x %g" : "deformation x %g of the elastic displacement u",
                options_.scale);
  return note + bodies;
}

void SceneLabels::add_title_legend_and_stamps(const Results& results, const std::vector<TimedRigidFit>& fits,
                                              double t0) {
  // Title, deformation legend, time stamp.
  const RenderOptions& options = options_;
  const int font = stamp_font();
  add_title(results.title);
  fits_ = &fits;
  // Top right under the title until the layout places it (place_legend). Joints are only ever
  // released: the legend at t0 is the longest the frames show, and the layout makes room for it.
  if (const std::string legend = legend_text(results, t0); !legend.empty()) {
    legend_ = add_text(legend, std::max(kMinFontSize, options.height / 40), 0.98, title_bottom(), true);
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

void SceneLabels::add_title(const std::string& title) {
  title_ = add_text(title, std::max(kMinFontSize, options_.height / 30), kTitleX, kTitleY, false);
  vtkTextProperty* property = title_->GetTextProperty();
  const std::string wrapped = wrap_to_width(title, property, (kTitleRight - kTitleX) * options_.width);
  title_->SetInput(wrapped.c_str());
  // The first line where a one-line title sits, the others below it (the text is anchored at
  // its last line's bottom).
  const std::string first_line = wrapped.substr(0, wrapped.find('\n'));
  const double below = text_size(property, wrapped).y() - text_size(property, first_line).y();
  title_y_ = kTitleY - below / options_.height;
  title_->GetPositionCoordinate()->SetValue(kTitleX, title_y_);
}

double SceneLabels::title_bottom() const {
  int b[4];  // about the anchor, bottom-left justified
  vtkTextRenderer* measure = vtkTextRenderer::GetInstance();
  if (!title_) return kTitleY;
  if (!measure->GetBoundingBox(title_->GetTextProperty(), title_->GetInput(), b, kTextDpi)) return title_y_;
  // A gap of a quarter of the title's font under its lowest pixel.
  const double gap = 0.25 * title_->GetTextProperty()->GetFontSize();
  return title_y_ + (std::min(b[2], 0) - gap) / options_.height;
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
  // The legend without the joints released by t.
  if (legend_) {
    const std::string legend = legend_text(results, t);
    if (legend != legend_->GetInput()) legend_->SetInput(legend.c_str());
  }
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
