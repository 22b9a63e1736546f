// The fixed camera's fit (camera_fit.h): every corner projects inside the window, the content
// touches the window on two opposite sides (no closer eye would fit), and a flat strip facing
// the camera is fitted at the closed-form distance.
#include "camera_fit.h"

#include <gtest/gtest.h>

#include <cmath>

namespace limber::render {
namespace {

constexpr double kAngle = 30.0;  // vertical view angle [deg]
constexpr double kAspect = 16.0 / 9.0;

// Normalised viewport coordinates of a ground point seen from `placement` (camera_fit.h's
// projection, the eye on the view axis).
Eigen::Vector2d project(const CameraPlacement& placement, const CameraAxes& axes, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = axes.of(p - placement.eye);
  const double t = std::tan(0.5 * kAngle * M_PI / 180.0);
  const double z = -q.z();
  return {0.5 + 0.5 * (placement.axis_at.x() + q.x() / (z * t * kAspect)),
          0.5 + 0.5 * (placement.axis_at.y() + q.y() / (z * t))};
}

TEST(CameraFit, EveryCornerInsideAndTwoSidesTouched) {
  // Two frames of an elongated motion (a stowed and a deployed array) seen obliquely.
  const CameraAxes axes = camera_axes(Eigen::Vector3d(1, -1, 1), Eigen::Vector3d::UnitZ());
  std::vector<Eigen::Vector3d> points;
  for (double x : {-0.5, 0.5}) {
    for (double y : {-0.3, 0.3}) {
      for (double z : {0.0, 1.0}) points.emplace_back(x, y, z);     // stowed
      for (double z : {0.0, 0.02}) points.emplace_back(x, 12 * y, z);  // deployed along y
    }
  }
  std::vector<CameraBox> boxes(2);
  for (std::size_t k = 0; k < points.size(); ++k) boxes[(k / 2) % 2].add(axes.of(points[k]));
  const ViewWindow window{0.02, 0.83, 0.09, 0.80};
  std::vector<Eigen::Vector3d> hull;
  for (const CameraBox& box : boxes) {
    for (const Eigen::Vector3d& p : box.corners()) hull.push_back(p);
  }
  const CameraPlacement placement = fit_camera(hull, axes, kAngle, kAspect, window);

  // The projected corners of the camera-axes boxes: inside to round-off (1e-9 of the extent is
  // the bisection's stopping width), and reaching both edges of the window in x or in y.
  double x0 = 1.0, x1 = 0.0, y0 = 1.0, y1 = 0.0;
  for (const CameraBox& box : boxes) {
    for (const Eigen::Vector3d& q : box.corners()) {
      const Eigen::Vector2d s = project(placement, axes, q.x() * axes.right + q.y() * axes.up + q.z() * axes.back);
      x0 = std::min(x0, s.x()), x1 = std::max(x1, s.x()), y0 = std::min(y0, s.y()), y1 = std::max(y1, s.y());
    }
  }
  constexpr double kTol = 1e-7;
  EXPECT_GE(x0, window.x0 - kTol);
  EXPECT_LE(x1, window.x1 + kTol);
  EXPECT_GE(y0, window.y0 - kTol);
  EXPECT_LE(y1, window.y1 + kTol);
  const bool spans_x = std::abs(x0 - window.x0) < 1e-6 && std::abs(x1 - window.x1) < 1e-6;
  const bool spans_y = std::abs(y0 - window.y0) < 1e-6 && std::abs(y1 - window.y1) < 1e-6;
  EXPECT_TRUE(spans_x || spans_y) << x0 << " " << x1 << " " << y0 << " " << y1;
  // The view axis is drawn at the window's centre; the focal point lies on it.
  EXPECT_NEAR(placement.axis_at.x(), window.x0 + window.x1 - 1.0, 1e-15);
  EXPECT_NEAR(placement.axis_at.y(), window.y0 + window.y1 - 1.0, 1e-15);
  const Eigen::Vector3d axis = (placement.eye - placement.focal).normalized();
  EXPECT_NEAR(axis.dot(axes.back), 1.0, 1e-12);
}

TEST(CameraFit, FlatStripAtTheClosedFormDistance) {
  // A strip 2w wide and thin, facing the camera, in the full frame: the eye is at
  // w / (tan(angle / 2) aspect) from it, centred on it.
  const CameraAxes axes = camera_axes(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
  const double w = 3.0;
  std::vector<CameraBox> boxes(1);
  boxes[0].add(axes.of(Eigen::Vector3d(1.0 - w, 2.0 - 0.01, 0.5)));
  boxes[0].add(axes.of(Eigen::Vector3d(1.0 + w, 2.0 + 0.01, 0.5)));
  const CameraPlacement placement = fit_camera(boxes[0].corners(), axes, kAngle, kAspect, ViewWindow{});
  const double distance = w / (std::tan(0.5 * kAngle * M_PI / 180.0) * kAspect);
  // The bisection stops within 1e-9 of the content's extent (2w).
  EXPECT_NEAR(placement.eye.z(), 0.5 + distance, 1e-8 * w);
  EXPECT_NEAR(placement.eye.x(), 1.0, 1e-8 * w);
  EXPECT_NEAR(placement.eye.y(), 2.0, 1e-8 * w);
}

}  // namespace
}  // namespace limber::render
