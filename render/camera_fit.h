// The fixed camera of an animation: along a given view direction, the eye nearest to the scene
// from which every frame's content projects inside a window of the frame (issue 28: the
// deployed array fills the frame). Fitting a bounding sphere instead, as limber did before,
// leaves an elongated motion at a third of the frame: the sphere holds the box's diagonal in
// every direction.
//
// Perspective projection, VTK's conventions: the view angle is vertical; a point at camera
// coordinates (r, u, d) (right, up, back = towards the eye) seen from the eye at (er, eu, ed)
// lands at x = cx + (r - er) / ((ed - d) tan(angle / 2) aspect),
// y = cy + (u - eu) / ((ed - d) tan(angle / 2)) in normalised device coordinates [-1, 1], where
// (cx, cy) is where the view axis appears (the centre of the fitted window).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace limber::render {

// Right-handed camera axes in ground: right = up x back; `back` points from the scene towards
// the eye.
struct CameraAxes {
  Eigen::Vector3d right, up, back;
  // Camera coordinates (right, up, back) of a ground point [m].
  Eigen::Vector3d of(const Eigen::Vector3d& p_W) const { return {right.dot(p_W), up.dot(p_W), back.dot(p_W)}; }
};

// Axes looking along -back with `up_hint` (not parallel to back) projected to the screen's up.
CameraAxes camera_axes(const Eigen::Vector3d& back, const Eigen::Vector3d& up_hint);

// An axis-aligned box [m] (in camera or in ground coordinates) about what one frame draws.
struct CameraBox {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-1e300);
  void add(const Eigen::Vector3d& p_C, double radius = 0.0) {
    lo = lo.cwiseMin((p_C.array() - radius).matrix());
    hi = hi.cwiseMax((p_C.array() + radius).matrix());
  }
  bool empty() const { return lo.x() > hi.x(); }
  // The 8 corners (none when empty).
  std::vector<Eigen::Vector3d> corners() const;
};

// Part of the frame the content must fit in, normalised viewport coordinates (0..1, y up);
// must hold the frame's centre.
struct ViewWindow {
  double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;
};

// The eye sits on the line through the content along the view direction (so a front view
// stays square to the front: no top face shows), and the image is shifted to the window's
// centre instead: the view axis appears at `axis_at` (normalised device coordinates,
// vtkCamera::SetWindowCenter(-axis_at) draws it there).
struct CameraPlacement {
  Eigen::Vector3d eye, focal;  // ground [m]; focal on the view axis at the content's mid depth
  Eigen::Vector2d axis_at = Eigen::Vector2d::Zero();  // the window's centre, device coordinates
  double eye_back = 0.0;       // the eye's camera coordinate along back: smaller is closer
  Eigen::Vector3d eye_C = Eigen::Vector3d::Zero();  // the eye in camera coordinates [m]
};

// Where a point at camera coordinates p_C (in front of the eye) appears with `placement`:
// normalised viewport coordinates (0..1, y up), the projection above.
Eigen::Vector2d viewport_point(const CameraPlacement& placement, const Eigen::Vector3d& p_C,
                               double view_angle_deg, double aspect);

// The point at camera depth `back` (its camera coordinate along back, in front of the eye) that
// appears at viewport point `v`: viewport_point's inverse on that plane.
Eigen::Vector3d point_at_viewport(const CameraPlacement& placement, const Eigen::Vector2d& v, double back,
                                  double view_angle_deg, double aspect);

// The eye nearest to the content (to 1e-9 of its extent) from which every point (camera
// coordinates, e.g. the corners of boxes holding each frame) projects inside `window`, centred
// in it where the content is narrower in one direction. Any set of points whose convex hull
// holds what is drawn gives a camera that shows it all; the tighter the hull, the larger the
// picture. view_angle_deg: vertical view angle; aspect: width / height. Precondition: points
// not empty, 0 < view_angle_deg < 180, aspect > 0.
CameraPlacement fit_camera(const std::vector<Eigen::Vector3d>& points_C, const CameraAxes& axes,
                           double view_angle_deg, double aspect, const ViewWindow& window);

}  // namespace limber::render
