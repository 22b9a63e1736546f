// Single quads for the shell element tests (test_shell_element.cpp, test_shell_section.cpp):
// corner sets in a tilted plane (no axis aligned with the global ones, offset from the origin).
#pragma once

#include <array>

#include <Eigen/Dense>

namespace limber::fe::testing {

using Corners = std::array<Eigen::Vector3d, 4>;

inline Eigen::Matrix3d skew(const Eigen::Vector3d& r) {
  Eigen::Matrix3d s;
  s << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return s;
}

// A rotation with no axis aligned to the global ones, and an offset.
inline Eigen::Matrix3d tilted_rotation() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()) *
          Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}
inline const Eigen::Vector3d kOffset(0.3, -1.2, 2.5);

// Corners of a quad given in its own plane (xy) with out-of-plane offsets z, placed tilted.
inline Corners placed(const std::array<Eigen::Vector2d, 4>& xy, const std::array<double, 4>& z = {}) {
  Corners corners;
  for (int k = 0; k < 4; ++k) {
    corners[k] = kOffset + tilted_rotation() * Eigen::Vector3d(xy[k].x(), xy[k].y(), z[k]);
  }
  return corners;
}

inline const std::array<Eigen::Vector2d, 4> kRectangle{
    {{-0.2, -0.15}, {0.2, -0.15}, {0.2, 0.15}, {-0.2, 0.15}}};
inline const std::array<Eigen::Vector2d, 4> kDistorted{
    {{0.0, 0.0}, {1.1, 0.1}, {1.3, 0.9}, {0.2, 0.7}}};
// Corner offsets ±0.01 m from the mean plane: warp ratio 0.01 / sqrt(0.795) = 0.011 < 0.05.
inline const std::array<double, 4> kSmallWarp{0.01, -0.01, 0.01, -0.01};

}  // namespace limber::fe::testing
