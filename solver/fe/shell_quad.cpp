#include "fe/shell_quad.h"

#include <Eigen/LU>

#include "core/error.h"

namespace limber::fe {

QuadPoint quad_point(const QuadCoordinates& xy, double xi, double eta) {
  QuadPoint point;
  // Shape functions and natural derivatives.
  for (int k = 0; k < 4; ++k) {
    const double a = 1.0 + kCornerXi[k] * xi;
    const double b = 1.0 + kCornerEta[k] * eta;
    point.n(k) = 0.25 * a * b;
    point.dn_dnat(0, k) = 0.25 * kCornerXi[k] * b;
    point.dn_dnat(1, k) = 0.25 * kCornerEta[k] * a;
  }
  // Jacobian of the map (ξ, η) -> (x, y).
  point.jacobian.setZero();
  for (int k = 0; k < 4; ++k) point.jacobian += point.dn_dnat.col(k) * xy[k].transpose();
  point.det_j = point.jacobian.determinant();
  LIMBER_DEMAND(point.det_j > 0.0);
  // Cartesian derivatives: [N,x; N,y] = J^-1 [N,ξ; N,η].
  point.dn_dxy = point.jacobian.inverse() * point.dn_dnat;
  return point;
}

}  // namespace limber::fe
