// Line plots drawn offscreen with VTK's chart classes (vtkChartXY in a vtkContextView) in
// render's headless EGL context, written as PNG. One ChartCanvas owns one OpenGL context: use it
// from the thread that created it.
#pragma once

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace limber::report {

// How a curve's line is drawn: solid by default; a curve lying on an earlier one of its plot
// is dashed or dotted (curve_styles.h) so that both stay visible.
enum class LineStyle { kSolid, kDashed, kDotted, kDashDot };

// One curve: y(x) drawn as a line; x and y have the same length.
struct Curve {
  std::string label;  // legend entry
  Eigen::VectorXd x;
  Eigen::VectorXd y;
  int color = -1;     // index into kCurveColors; -1: the curve's place in its plot
  LineStyle style = LineStyle::kSolid;
  // Extra line width [pixels] over the plot's default (2.5 px in the PNG, 1.5 px in the chart):
  // comparisons draw earlier runs wider, so a later run drawn over them leaves them visible.
  float extra_width = 0.0f;

  Curve() = default;
  Curve(std::string label_, Eigen::VectorXd x_, Eigen::VectorXd y_, int color_ = -1)
      : label(std::move(label_)), x(std::move(x_)), y(std::move(y_)), color(color_) {}
};

struct PlotSpec {
  std::string title;
  std::string x_label;  // with units, e.g. "time [s]"
  std::string y_label;  // with units, e.g. "force [N]"
  std::vector<Curve> curves;
  bool log_y = false;   // logarithmic y axis; needs every y > 0 (else drawn linear)
  bool log_x = false;   // logarithmic x axis; needs every x > 0 (else drawn linear)
  bool markers = false; // a circle at every point (work-precision curves of few points)
};

// Where the plot area landed in the PNG: data ranges and their pixel positions, so a data point
// can be located in the image (rows counted from the top).
struct PlotFrame {
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // axis ranges (data units; log_y: values)
  double left_px = 0, right_px = 0;                    // columns of x_min and x_max
  double bottom_px = 0, top_px = 0;                    // rows of y_min and y_max
  bool log_y = false;
  bool log_x = false;

  // Pixel (column, row from the top) of the data point (x, y).
  Eigen::Vector2d to_pixel(double x, double y) const;
};

// Line colours in curve order (RGB 0..255), repeated past the end (curve_color picks): the
// colour-blind-safe palette of Okabe & Ito ("Color Universal Design", 2008) — blue, vermillion,
// bluish green, orange, reddish purple, sky blue, black — with grey for its yellow, which does
// not show on white paper.
inline constexpr std::array<std::array<unsigned char, 3>, 8> kCurveColors{{
    {0, 114, 178}, {213, 94, 0}, {0, 158, 115}, {230, 159, 0},
    {204, 121, 167}, {86, 180, 233}, {0, 0, 0}, {128, 128, 128}}};
// The colour of curve `index` of a plot: its own when set, else by its place.
inline const std::array<unsigned char, 3>& curve_color(const Curve& curve, std::size_t index) {
  const std::size_t k = curve.color >= 0 ? static_cast<std::size_t>(curve.color) : index;
  return kCurveColors[k % kCurveColors.size()];
}
// The page colour behind the chart (white, as printed).
inline constexpr std::array<unsigned char, 3> kPlotBackground{255, 255, 255};

// The legend sits below the plot (a long run name must not narrow the plot), one row per
// curve: each PNG is `height` plus this per legend row, up to kMaxLegendRows rows (a plot of
// more curves lets its legend take plot height instead).
inline constexpr int kLegendRowPixels = 26;
inline constexpr int kMaxLegendRows = 12;
// Below a legend's rows: VTK's padding around a legend outside the plot (10 + 5 pixels).
inline constexpr int kLegendPadding = 15;

class ChartCanvas {
 public:
  // Creates the EGL context and a chart view width pixels wide whose plots are `height` pixels
  // high above their legend (each PNG: height + the legend's rows, see kLegendRowPixels).
  // Throws std::runtime_error when no offscreen OpenGL 3.2 context can be created.
  ChartCanvas(int width, int height);
  ~ChartCanvas();
  ChartCanvas(const ChartCanvas&) = delete;
  ChartCanvas& operator=(const ChartCanvas&) = delete;

  // Draws `plot` and writes it to `png`. Axis ranges are padded "nice" bounds of the data;
  // a plot without points gets the unit square. Throws std::runtime_error when the file
  // cannot be written.
  PlotFrame draw(const PlotSpec& plot, const std::filesystem::path& png);

  int width() const;
  int height() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Rounds [lo, hi] outwards to multiples of a 1-2-5 step giving about `ticks` intervals;
// an empty or degenerate range is widened around its value.
std::array<double, 2> nice_range(double lo, double hi, int ticks = 6);

}  // namespace limber::report
