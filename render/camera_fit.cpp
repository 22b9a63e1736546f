#include "camera_fit.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace limber::render {
namespace {

// The interval of eye positions along one screen axis (c: r or u) that keeps every corner
// inside [a, b] (device coordinates) when the eye is at depth ed: c - b t z <= e <= c - a t z,
// z = ed - d, t the half-angle's tangent on that axis. Empty when lo > hi.
struct Interval {
  double lo = -1e300, hi = 1e300;
};

Interval eye_interval(const std::vector<Eigen::Vector3d>& points_C, int axis, double ed, double t,
                      double a, double b) {
  Interval e;
  for (const Eigen::Vector3d& p : points_C) {
    const double z = ed - p.z();
    e.lo = std::max(e.lo, p(axis) - b * t * z);
    e.hi = std::min(e.hi, p(axis) - a * t * z);
  }
  return e;
}

}  // namespace

CameraAxes camera_axes(const Eigen::Vector3d& back, const Eigen::Vector3d& up_hint) {
  CameraAxes axes;
  axes.back = back.normalized();
  axes.up = (up_hint - up_hint.dot(axes.back) * axes.back).normalized();
  axes.right = axes.up.cross(axes.back);
  return axes;
}

std::vector<Eigen::Vector3d> CameraBox::corners() const {
  std::vector<Eigen::Vector3d> corners;
  if (empty()) return corners;
  for (int c = 0; c < 8; ++c) {
    corners.emplace_back((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
  }
  return corners;
}

CameraPlacement fit_camera(const std::vector<Eigen::Vector3d>& points_C, const CameraAxes& axes,
                           double view_angle_deg, double aspect, const ViewWindow& window) {
  LIMBER_DEMAND(!points_C.empty());
  CameraBox all;
  for (const Eigen::Vector3d& p : points_C) all.add(p);
  const double ty = std::tan(0.5 * view_angle_deg * M_PI / 180.0);
  const double tx = ty * aspect;
  // The window about its centre, where the view axis is drawn.
  const Eigen::Vector2d centre(window.x0 + window.x1 - 1.0, window.y0 + window.y1 - 1.0);
  const double bx = window.x1 - window.x0, ax = -bx;
  const double by = window.y1 - window.y0, ay = -by;
  LIMBER_DEMAND(bx > 0.0 && by > 0.0);
  const double extent = std::max((all.hi - all.lo).norm(), 1e-9);

  // Both intervals widen as the eye backs away (a < 0 < b); bisect on the eye's depth between
  // the content's front (infeasible unless the content is a point) and a depth that fits.
  auto fits = [&](double ed) {
    const Interval x = eye_interval(points_C, 0, ed, tx, ax, bx);
    const Interval y = eye_interval(points_C, 1, ed, ty, ay, by);
    return x.lo <= x.hi && y.lo <= y.hi;
  };
  double near = all.hi.z();
  double far = all.hi.z() + extent;
  while (!fits(far)) far += 2.0 * (far - near);
  while (far - near > 1e-9 * extent) {
    const double mid = 0.5 * (near + far);
    (fits(mid) ? far : near) = mid;
  }
  const Interval x = eye_interval(points_C, 0, far, tx, ax, bx);
  const Interval y = eye_interval(points_C, 1, far, ty, ay, by);
  const Eigen::Vector3d eye_C(0.5 * (x.lo + x.hi), 0.5 * (y.lo + y.hi), far);

  // The focal point: on the view axis (through the eye along -back), at the content's mid depth.
  CameraPlacement placement;
  placement.eye = eye_C.x() * axes.right + eye_C.y() * axes.up + eye_C.z() * axes.back;
  placement.focal = placement.eye - (far - 0.5 * (all.lo.z() + all.hi.z())) * axes.back;
  placement.eye_back = far;
  placement.eye_C = eye_C;
  placement.axis_at = centre;
  return placement;
}

Eigen::Vector2d viewport_point(const CameraPlacement& placement, const Eigen::Vector3d& p_C,
                               double view_angle_deg, double aspect) {
  const double ty = std::tan(0.5 * view_angle_deg * M_PI / 180.0);
  const double z = placement.eye_C.z() - p_C.z();
  const Eigen::Vector2d ndc(placement.axis_at.x() + (p_C.x() - placement.eye_C.x()) / (z * ty * aspect),
                            placement.axis_at.y() + (p_C.y() - placement.eye_C.y()) / (z * ty));
  return 0.5 * (ndc + Eigen::Vector2d::Ones());
}

Eigen::Vector3d point_at_viewport(const CameraPlacement& placement, const Eigen::Vector2d& v, double back,
                                  double view_angle_deg, double aspect) {
  const double ty = std::tan(0.5 * view_angle_deg * M_PI / 180.0);
  const double z = placement.eye_C.z() - back;
  const Eigen::Vector2d ndc = 2.0 * v - Eigen::Vector2d::Ones() - placement.axis_at;
  return {placement.eye_C.x() + ndc.x() * z * ty * aspect, placement.eye_C.y() + ndc.y() * z * ty, back};
}

}  // namespace limber::render
