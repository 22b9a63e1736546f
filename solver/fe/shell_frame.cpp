#include "fe/shell_frame.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "core/error.h"

namespace limber::fe {

namespace {
// Smallest sine of the angle between the diagonals accepted before the area ratio tests.
constexpr double kMinDiagonalSine = 1e-8;
}  // namespace

ShellFrame shell_frame(const std::array<Eigen::Vector3d, 4>& corners) {
  ShellFrame frame;
  // Normal from the diagonals' cross product.
  const Eigen::Vector3d diagonal_13 = corners[2] - corners[0];
  const Eigen::Vector3d diagonal_24 = corners[3] - corners[1];
  const Eigen::Vector3d cross = diagonal_13.cross(diagonal_24);
  const double diagonal_product = diagonal_13.norm() * diagonal_24.norm();
  if (!(cross.norm() > kMinDiagonalSine * diagonal_product)) {
    throw InputError(fmt::format(
        "degenerate shell quad: expected two non-parallel diagonals of non-zero length, got "
        "lengths {:.6g} m and {:.6g} m with |d13 x d24| = {:.6g} m^2",
        diagonal_13.norm(), diagonal_24.norm(), cross.norm()));
  }
  const Eigen::Vector3d e3 = cross.normalized();
  frame.area = 0.5 * cross.norm();

  // Origin at the centroid; warp offsets of the corners from the mean plane.
  frame.centroid_W = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
  double max_offset = 0.0;
  for (int k = 0; k < 4; ++k) {
    frame.warp_offsets[k] = (corners[k] - frame.centroid_W).dot(e3);
    max_offset = std::max(max_offset, std::abs(frame.warp_offsets[k]));
  }
  const double warp_ratio = max_offset / std::sqrt(frame.area);
  if (warp_ratio > kMaxShellWarpRatio) {
    throw InputError(fmt::format(
        "warped shell quad: expected a warp ratio (corner distance from the mean plane / "
        "sqrt(area)) <= {}, got {:.6g}",
        kMaxShellWarpRatio, warp_ratio));
  }

  // In-plane axes: e1 along the mean ξ-direction projected on the plane.
  const Eigen::Vector3d xi_direction = corners[1] + corners[2] - corners[0] - corners[3];
  const Eigen::Vector3d e1 = (xi_direction - xi_direction.dot(e3) * e3).normalized();
  const Eigen::Vector3d e2 = e3.cross(e1);
  frame.rotation_WL.col(0) = e1;
  frame.rotation_WL.col(1) = e2;
  frame.rotation_WL.col(2) = e3;

  // Projected local coordinates.
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d r = corners[k] - frame.centroid_W;
    frame.xy[k] = Eigen::Vector2d(r.dot(e1), r.dot(e2));
  }

  // Convexity: every corner's edge cross product against the mean (= area).
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d edge_out = frame.xy[(k + 1) % 4] - frame.xy[k];
    const Eigen::Vector2d edge_in = frame.xy[(k + 3) % 4] - frame.xy[k];
    const double corner_ratio =
        (edge_out.x() * edge_in.y() - edge_out.y() * edge_in.x()) / frame.area;
    if (!(corner_ratio >= kMinShellCornerRatio)) {
      throw InputError(fmt::format(
          "non-convex or degenerate shell quad: expected every corner ratio (edge cross "
          "product / area) >= {}, got {:.6g} at corner {}",
          kMinShellCornerRatio, corner_ratio, k + 1));
    }
  }
  return frame;
}

}  // namespace limber::fe
