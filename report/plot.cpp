#include "plot.h"

#include "egl_context.h"
#include "egl_render_window.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkPointData.h>
#include <vtkRect.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace limber::report {
namespace {

// Font sizes [pixels] for a 1200-pixel-wide plot printed ~17 cm wide: about 9–11 pt on paper.
constexpr int kTitleFont = 28;
constexpr int kAxisTitleFont = 24;
constexpr int kLabelFont = 20;
constexpr float kLineWidth = 2.5f;
// About this many tick intervals per linear axis.
constexpr int kTickIntervals = 6;

// Data bounds of every curve (x, and y restricted to positive values when `positive_y`).
struct Bounds {
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double y_lo = x_lo, y_hi = -x_lo;
};

Bounds data_bounds(const PlotSpec& plot) {
  Bounds b;
  for (const Curve& c : plot.curves) {
    for (Eigen::Index k = 0; k < std::min(c.x.size(), c.y.size()); ++k) {
      if (!std::isfinite(c.x(k)) || !std::isfinite(c.y(k))) continue;
      b.x_lo = std::min(b.x_lo, c.x(k));
      b.x_hi = std::max(b.x_hi, c.x(k));
      b.y_lo = std::min(b.y_lo, c.y(k));
      b.y_hi = std::max(b.y_hi, c.y(k));
    }
  }
  return b;
}

// Decades enclosing [lo, hi] (lo > 0) for a logarithmic axis.
std::array<double, 2> decade_range(double lo, double hi) {
  const double a = std::floor(std::log10(lo));
  double b = std::ceil(std::log10(hi));
  if (b <= a) b = a + 1;
  return {std::pow(10.0, a), std::pow(10.0, b)};
}

void style_axis(vtkAxis* axis, const std::string& title) {
  axis->SetTitle(title);
  axis->GetTitleProperties()->SetFontSize(kAxisTitleFont);
  axis->GetTitleProperties()->SetBold(false);
  axis->GetLabelProperties()->SetFontSize(kLabelFont);
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetGridVisible(true);
}

// A 1-2-5 step giving about `ticks` intervals over a span.
double nice_step(double span, int ticks) {
  const double raw = span / ticks;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= raw) return m * decade;
  }
  return 10.0 * decade;
}

// Ticks at the multiples of a nice step inside [lo, hi]: VTK's own choice crowds a wide axis
// with overlapping labels.
void set_nice_ticks(vtkAxis* axis, double lo, double hi) {
  const double step = nice_step(hi - lo, kTickIntervals);
  vtkNew<vtkDoubleArray> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1.0) {
    ticks->InsertNextValue(std::abs(k) < 0.5 ? 0.0 : k * step);
  }
  axis->SetCustomTickPositions(ticks);
}

}  // namespace

Eigen::Vector2d PlotFrame::to_pixel(double x, double y) const {
  const double fx = log_x ? (std::log10(x) - std::log10(x_min)) / (std::log10(x_max) - std::log10(x_min))
                          : (x - x_min) / (x_max - x_min);
  const double fy = log_y ? (std::log10(y) - std::log10(y_min)) /
                                (std::log10(y_max) - std::log10(y_min))
                          : (y - y_min) / (y_max - y_min);
  return {left_px + fx * (right_px - left_px), bottom_px + fy * (top_px - bottom_px)};
}

std::array<double, 2> nice_range(double lo, double hi, int ticks) {
  if (!(lo <= hi)) return {0.0, 1.0};
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    // A constant: one unit (of its own magnitude) either side.
    const double half = lo == 0.0 ? 1.0 : std::pow(10.0, std::floor(std::log10(std::abs(lo))));
    lo -= half;
    hi += half;
  }
  const double step = nice_step(hi - lo, ticks);
  return {std::floor(lo / step) * step, std::ceil(hi / step) * step};
}

struct ChartCanvas::Impl {
  int width, height;
  int context_height;  // height plus the room of the largest legend
  render::EglContext context;
  vtkNew<render::EglRenderWindow> window;
  vtkNew<vtkContextView> view;
  vtkNew<vtkChartXY> chart;
  vtkNew<vtkUnsignedCharArray> pixels;

  Impl(int w, int h)
      : width(w), height(h), context_height(h + kMaxLegendRows * kLegendRowPixels + kLegendPadding),
        context(w, context_height) {
    window->attach_to_current_context(w, context_height);
    view->SetRenderWindow(window);
    view->GetRenderer()->SetBackground(kPlotBackground[0] / 255.0, kPlotBackground[1] / 255.0,
                                       kPlotBackground[2] / 255.0);
    view->GetScene()->AddItem(chart);
    // Legend below the plot area, so it never hides a curve nor narrows the plot; the chart
    // fills the top of the context, as high as each plot's legend needs (draw).
    chart->SetShowLegend(true);
    chart->GetLegend()->SetInline(false);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::CENTER);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::BOTTOM);
    chart->SetLayoutStrategy(vtkChart::FILL_RECT);
    chart->GetLegend()->GetLabelProperties()->SetFontSize(kLabelFont);
    chart->GetTitleProperties()->SetFontSize(kTitleFont);
    chart->GetTitleProperties()->SetBold(true);
  }
};

namespace {

// The plot's fixed, rounded axis ranges (pixel positions are filled in after drawing).
PlotFrame axis_ranges(const PlotSpec& plot) {
  PlotFrame frame;
  const Bounds b = data_bounds(plot);
  const bool has_points = b.x_lo <= b.x_hi;
  frame.log_y = plot.log_y && has_points && b.y_lo > 0.0;
  const std::array<double, 2> xr =
      has_points ? nice_range(b.x_lo, b.x_hi) : std::array<double, 2>{0.0, 1.0};
  // Time axes start where the data start: no padding before the first sample.
  frame.x_min = has_points && b.x_lo < b.x_hi ? b.x_lo : xr[0];
  frame.x_max = has_points && b.x_lo < b.x_hi ? b.x_hi : xr[1];
  frame.log_x = plot.log_x && has_points && b.x_lo > 0.0;
  if (frame.log_x) {
    const std::array<double, 2> decades = decade_range(b.x_lo, b.x_hi);
    frame.x_min = decades[0];
    frame.x_max = decades[1];
  }
  const std::array<double, 2> yr = !has_points ? std::array<double, 2>{0.0, 1.0}
                                   : frame.log_y ? decade_range(b.y_lo, b.y_hi)
                                                 : nice_range(b.y_lo, b.y_hi);
  frame.y_min = yr[0];
  frame.y_max = yr[1];
  return frame;
}

// One table and line per curve (curves may have different abscissae).
void add_curves(vtkChartXY* chart, const PlotSpec& plot) {
  for (std::size_t i = 0; i < plot.curves.size(); ++i) {
    const Curve& curve = plot.curves[i];
    vtkNew<vtkDoubleArray> x, y;
    x->SetName("x");
    y->SetName(curve.label.c_str());
    const Eigen::Index n = std::min(curve.x.size(), curve.y.size());
    // A line needs two points (VTK logs an error otherwise); a marked curve of one is a point.
    if (n < (plot.markers ? 1 : 2)) continue;
    for (Eigen::Index k = 0; k < n; ++k) {
      x->InsertNextValue(curve.x(k));
      y->InsertNextValue(curve.y(k));
    }
    vtkNew<vtkTable> table;
    table->AddColumn(x);
    table->AddColumn(y);
    vtkPlot* line = chart->AddPlot(n < 2 ? vtkChart::POINTS : vtkChart::LINE);
    line->SetInputData(table, 0, 1);
    const auto& rgb = curve_color(curve, i);
    line->SetColor(rgb[0], rgb[1], rgb[2], 255);
    line->SetWidth(kLineWidth + curve.extra_width);
    // A curve lying on an earlier one is dashed or dotted so that both show (curve_styles.h).
    line->GetPen()->SetLineType(curve.style == LineStyle::kDashed    ? vtkPen::DASH_LINE
                                : curve.style == LineStyle::kDotted  ? vtkPen::DOT_LINE
                                : curve.style == LineStyle::kDashDot ? vtkPen::DASH_DOT_LINE
                                                                     : vtkPen::SOLID_LINE);
    line->SetLabel(curve.label);
    if (plot.markers) {
      vtkPlotPoints::SafeDownCast(line)->SetMarkerStyle(vtkPlotPoints::CIRCLE);
      vtkPlotPoints::SafeDownCast(line)->SetMarkerSize(8.0);
    }
  }

}

// The axes' titles, scales and ranges of `frame`.
void set_axes(vtkChartXY* chart, const PlotSpec& plot, const PlotFrame& frame) {
  vtkAxis* x_axis = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y_axis = chart->GetAxis(vtkAxis::LEFT);
  style_axis(x_axis, plot.x_label);
  style_axis(y_axis, plot.y_label);
  // The canvas is reused: a logarithmic axis of an earlier plot leaves VTK's range limits at
  // positive values, which clipped the next linear plot at 0 (its negative half off the chart).
  for (vtkAxis* axis : {x_axis, y_axis}) {
    axis->SetUnscaledMinimumLimit(std::numeric_limits<double>::lowest());
    axis->SetUnscaledMaximumLimit(std::numeric_limits<double>::max());
    axis->SetMinimumLimit(std::numeric_limits<double>::lowest());
    axis->SetMaximumLimit(std::numeric_limits<double>::max());
  }
  x_axis->SetLogScale(frame.log_x);
  if (frame.log_x) {
    x_axis->SetCustomTickPositions(nullptr);
    x_axis->SetUnscaledRange(frame.x_min, frame.x_max);
  } else {
    x_axis->SetRange(frame.x_min, frame.x_max);
    set_nice_ticks(x_axis, frame.x_min, frame.x_max);
  }
  y_axis->SetLogScale(frame.log_y);
  if (frame.log_y) {
    y_axis->SetCustomTickPositions(nullptr);
    y_axis->SetUnscaledRange(frame.y_min, frame.y_max);
  } else {
    y_axis->SetRange(frame.y_min, frame.y_max);
    set_nice_ticks(y_axis, frame.y_min, frame.y_max);
  }
}

}  // namespace

ChartCanvas::ChartCanvas(int width, int height) : impl_(std::make_unique<Impl>(width, height)) {}

ChartCanvas::~ChartCanvas() {
  // Free VTK's OpenGL resources while the context is still current.
  impl_->context.make_current();
  impl_->window->Finalize();
}

int ChartCanvas::width() const { return impl_->width; }
int ChartCanvas::height() const { return impl_->height; }

PlotFrame ChartCanvas::draw(const PlotSpec& plot, const std::filesystem::path& png) {
  Impl& m = *impl_;
  m.context.make_current();
  vtkChartXY* chart = m.chart;
  chart->ClearPlots();
  chart->SetTitle(plot.title);
  PlotFrame frame = axis_ranges(plot);
  add_curves(chart, plot);
  set_axes(chart, plot, frame);
  vtkAxis* x_axis = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y_axis = chart->GetAxis(vtkAxis::LEFT);

  // The chart at the top of the context: the plot's height plus one row per legend entry.
  int rows = 0;
  for (const Curve& c : plot.curves) rows += std::min(c.x.size(), c.y.size()) >= (plot.markers ? 1 : 2) ? 1 : 0;
  const int used = m.height + std::min(rows, kMaxLegendRows) * kLegendRowPixels + (rows > 0 ? kLegendPadding : 0);
  const int bottom = m.context_height - used;
  chart->SetSize(vtkRectf(0.0f, static_cast<float>(bottom), static_cast<float>(m.width), static_cast<float>(used)));

  // Draw and read the chart's rows of the back buffer (bottom-up, as vtkImageData stores them).
  m.window->Render();
  m.window->GetPixelData(0, bottom, m.width - 1, m.context_height - 1, 0, m.pixels, 0);
  vtkNew<vtkImageData> image;
  image->SetDimensions(m.width, used, 1);
  image->GetPointData()->SetScalars(m.pixels);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(png.string().c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0) {
    throw std::runtime_error("cannot write plot '" + png.string() + "'");
  }

  // Pixel positions of the axis ends (scene y counts from the context's bottom edge, the
  // image's rows from its top, the context's top).
  frame.left_px = x_axis->GetPoint1()[0];
  frame.right_px = x_axis->GetPoint2()[0];
  frame.bottom_px = m.context_height - y_axis->GetPoint1()[1];
  frame.top_px = m.context_height - y_axis->GetPoint2()[1];
  return frame;
}

}  // namespace limber::report
