// A chart drawn offscreen: its PNG has the canvas size, the curve's colour where the data map
// to pixels through the reported axes, background away from it, and VTK logs nothing.
#include "plot.h"
#include "report_test_util.h"

#include <gtest/gtest.h>

#include <vtkOutputWindow.h>
#include <vtkStringOutputWindow.h>

#include <cmath>
#include <cstdlib>

namespace limber::report {
namespace {

constexpr int kWidth = 900;
constexpr int kHeight = 500;
// The line is 2.5 px wide and drawn without multisampling: its centre pixels carry the exact
// colour. A point is found within kSearch px of its mapped position (pixel-centre convention
// and rasterisation of a sloped line), in a colour within kColorTolerance per channel (the
// grid lines behind it are light grey and may blend at joins).
constexpr int kSearch = 3;
constexpr int kColorTolerance = 40;

bool near_color(const std::array<int, 3>& p, const std::array<unsigned char, 3>& c) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(p[k] - c[k]) > kColorTolerance) return false;
  }
  return true;
}

bool color_near_pixel(const testing::Png& png, const Eigen::Vector2d& at,
                      const std::array<unsigned char, 3>& color) {
  const int cx = static_cast<int>(std::lround(at.x()));
  const int cy = static_cast<int>(std::lround(at.y()));
  for (int y = cy - kSearch; y <= cy + kSearch; ++y) {
    for (int x = cx - kSearch; x <= cx + kSearch; ++x) {
      if (x >= 0 && y >= 0 && x < png.width && y < png.height &&
          near_color(png.pixel(x, y), color)) {
        return true;
      }
    }
  }
  return false;
}

TEST(NiceRange, RoundsOutwardsToOneTwoFiveSteps) {
  EXPECT_EQ(nice_range(-2.0, 4.0), (std::array<double, 2>{-2.0, 4.0}));
  const auto r = nice_range(0.013, 0.0871);  // step 0.02
  EXPECT_NEAR(r[0], 0.0, 1e-15);
  EXPECT_NEAR(r[1], 0.1, 1e-15);
  EXPECT_EQ(nice_range(5.0, 5.0), (std::array<double, 2>{4.0, 6.0}));
  EXPECT_EQ(nice_range(0.0, 0.0), (std::array<double, 2>{-1.0, 1.0}));
}

TEST(ChartCanvas, DrawsTheCurveWhereItsDataMapAndNothingElse) {
  unsetenv("DISPLAY");
  vtkNew<vtkStringOutputWindow> messages;
  vtkOutputWindow::SetInstance(messages);

  // y = 1 + 3 sin(2 pi x) on [0, 1]: y spans [-2, 4].
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(201, 0.0, 1.0);
  const Eigen::VectorXd y = (2.0 * M_PI * x).array().sin() * 3.0 + 1.0;
  PlotSpec spec{"test curve", "time [s]", "force [N]", {{"F", x, y}}, false};
  const auto dir = testing::fresh_directory("plot");
  PlotFrame frame;
  {
    ChartCanvas canvas(kWidth, kHeight);
    frame = canvas.draw(spec, dir / "curve.png");
  }
  vtkOutputWindow::SetInstance(nullptr);
  EXPECT_EQ(messages->GetOutput(), "") << "VTK logged while drawing";

  // Axes: the data's x span, the nice y range, a plot area inside the image.
  EXPECT_DOUBLE_EQ(frame.x_min, 0.0);
  EXPECT_DOUBLE_EQ(frame.x_max, 1.0);
  EXPECT_DOUBLE_EQ(frame.y_min, -2.0);
  EXPECT_DOUBLE_EQ(frame.y_max, 4.0);
  EXPECT_GT(frame.left_px, 0.0);
  EXPECT_LT(frame.right_px, kWidth);
  EXPECT_LT(frame.top_px, frame.bottom_px);
  EXPECT_GT(frame.right_px - frame.left_px, 0.5 * kWidth);

  const testing::Png png(dir / "curve.png");
  ASSERT_EQ(png.width, kWidth);
  // The plot, then its legend's one row below it.
  ASSERT_EQ(png.height, kHeight + kLegendRowPixels + kLegendPadding);

  // The curve's colour at every 10th sample's pixel.
  for (Eigen::Index k = 0; k < x.size(); k += 10) {
    EXPECT_TRUE(color_near_pixel(png, frame.to_pixel(x(k), y(k)), kCurveColors[0]))
        << "no curve pixel near sample " << k << " (x = " << x(k) << ", y = " << y(k) << ")";
  }
  // Far from the curve (x = 0.25 where y = 4; the curve is at -1.5 only near x = 0.69, 0.81).
  EXPECT_FALSE(color_near_pixel(png, frame.to_pixel(0.25, -1.5), kCurveColors[0]));
  const Eigen::Vector2d empty = frame.to_pixel(0.25, -1.5);
  EXPECT_EQ(png.pixel(static_cast<int>(empty.x()) + 5, static_cast<int>(empty.y()) + 5),
            (std::array<int, 3>{kPlotBackground[0], kPlotBackground[1], kPlotBackground[2]}));
}

// The canvas is reused for every plot of a report: a logarithmic plot before a linear one
// left VTK's axis limits positive, and the linear plot lost its negative half (every
// comparison plot of a report, drawn after the runs' log-scale violation plots, was cut at 0).
TEST(ChartCanvas, ALinearPlotAfterALogarithmicOneKeepsItsNegativeHalf) {
  unsetenv("DISPLAY");
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(201, 0.0, 1.0);
  const Eigen::VectorXd positive = (10.0 * x).array().exp();
  const Eigen::VectorXd y = (2.0 * M_PI * x).array().sin() * 3.0 + 1.0;  // spans [-2, 4]
  const auto dir = testing::fresh_directory("plot_after_log");
  PlotFrame frame;
  {
    ChartCanvas canvas(kWidth, kHeight);
    PlotSpec log_spec{"log", "time [s]", "violation [m]", {{"v", x, positive}}, true};
    canvas.draw(log_spec, dir / "log.png");
    frame = canvas.draw(PlotSpec{"linear", "time [s]", "force [N]", {{"F", x, y}}, false},
                        dir / "linear.png");
  }
  EXPECT_DOUBLE_EQ(frame.y_min, -2.0);
  const testing::Png png(dir / "linear.png");
  for (Eigen::Index k = 0; k < x.size(); k += 10) {
    EXPECT_TRUE(color_near_pixel(png, frame.to_pixel(x(k), y(k)), kCurveColors[0]))
        << "no curve pixel near sample " << k << " (x = " << x(k) << ", y = " << y(k) << ")";
  }
}

TEST(ChartCanvas, LogarithmicAxisSpansWholeDecades) {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(11, 0.0, 1.0);
  const Eigen::VectorXd y =  // 1e-10 ... 1e-6
      (x.array() * 4.0 - 10.0).unaryExpr([](double e) { return std::pow(10.0, e); });
  PlotSpec spec{"violation", "time [s]", "norm", {{"position", x, y}}, true};
  const auto dir = testing::fresh_directory("plot_log");
  ChartCanvas canvas(kWidth, kHeight);
  const PlotFrame frame = canvas.draw(spec, dir / "log.png");
  EXPECT_TRUE(frame.log_y);
  EXPECT_NEAR(std::log10(frame.y_min), -10.0, 1e-12);
  EXPECT_NEAR(std::log10(frame.y_max), -6.0, 1e-12);
  const testing::Png png(dir / "log.png");
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    EXPECT_TRUE(color_near_pixel(png, frame.to_pixel(x(k), y(k)), kCurveColors[0])) << k;
  }
}

// The work-precision plot of `limber sweep`: both axes logarithmic over whole decades, markers,
// and every point where y = 1e-3 x^-2 maps (a second-order method's error against cost).
TEST(ChartCanvas, LogLogAxesWithMarkers) {
  const Eigen::Vector4d x(0.1, 0.2, 0.4, 0.8);
  const Eigen::Vector4d y = 1e-3 * x.array().pow(-2.0);  // 0.1 ... 1.5625e-3
  PlotSpec spec{"work precision", "wall time [s]", "error", {{"galpha", x, y}}, true};
  spec.log_x = true;
  spec.markers = true;
  const auto dir = testing::fresh_directory("plot_loglog");
  ChartCanvas canvas(kWidth, kHeight);
  const PlotFrame frame = canvas.draw(spec, dir / "loglog.png");
  EXPECT_TRUE(frame.log_x);
  EXPECT_TRUE(frame.log_y);
  EXPECT_NEAR(std::log10(frame.x_min), -1.0, 1e-12);
  EXPECT_NEAR(std::log10(frame.x_max), 0.0, 1e-12);
  EXPECT_NEAR(std::log10(frame.y_min), -3.0, 1e-12);
  EXPECT_NEAR(std::log10(frame.y_max), -1.0, 1e-12);
  const testing::Png png(dir / "loglog.png");
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    EXPECT_TRUE(color_near_pixel(png, frame.to_pixel(x(k), y(k)), kCurveColors[0])) << k;
  }
  // Equal ratios are equal distances on both axes: x doubles between points.
  const double step_01 = frame.to_pixel(x(1), y(1)).x() - frame.to_pixel(x(0), y(0)).x();
  const double step_23 = frame.to_pixel(x(3), y(3)).x() - frame.to_pixel(x(2), y(2)).x();
  EXPECT_NEAR(step_01, step_23, 1e-9);
}

// The legend sits below the plot: a long run name neither narrows the plot area nor hides the
// curve, and the legend's line symbol shows under the x axis.
TEST(ChartCanvas, LegendBelowThePlotLeavesItsWidth) {
  unsetenv("DISPLAY");
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(201, 0.0, 1.0);
  const Eigen::VectorXd y = (2.0 * M_PI * x).array().sin();
  const std::string long_name(40, 'n');  // ~440 px at 20 px: half the plot's width
  PlotSpec short_label{"test curve", "time [s]", "force [N]", {{"F", x, y}}, false};
  PlotSpec long_label{"test curve", "time [s]", "force [N]", {{long_name, x, y}}, false};
  const auto dir = testing::fresh_directory("plot_legend");
  PlotFrame short_frame, long_frame;
  {
    ChartCanvas canvas(kWidth, kHeight);
    short_frame = canvas.draw(short_label, dir / "short.png");
    long_frame = canvas.draw(long_label, dir / "long.png");
  }
  // The same plot area to a pixel whatever the legend's width.
  EXPECT_NEAR(long_frame.right_px - long_frame.left_px, short_frame.right_px - short_frame.left_px, 1.0);
  EXPECT_GT(long_frame.right_px - long_frame.left_px, 0.8 * kWidth);
  // The legend's symbol: the curve's colour somewhere in the rows below the x axis's labels.
  const testing::Png png(dir / "long.png");
  bool symbol = false;
  for (int row = static_cast<int>(long_frame.bottom_px) + 50; row < png.height && !symbol; ++row) {
    for (int col = 0; col < png.width && !symbol; ++col) {
      symbol = near_color(png.pixel(col, row), kCurveColors[0]);
    }
  }
  EXPECT_TRUE(symbol) << "no legend symbol below the plot";
}

}  // namespace
}  // namespace limber::report
