#include "fe/shell_geometric_stiffness.h"

#include "fe/shell_frame.h"
#include "fe/shell_membrane.h"
#include "fe/shell_quad.h"

namespace limber::fe {

Matrix24d shell_geometric_stiffness(const std::array<Eigen::Vector3d, 4>& corners, const ShellProperty& property,
                                    const Vector24d& u_global) {
  const ShellFrame frame = shell_frame(corners);
  const Eigen::Matrix3d& R = frame.rotation_WL;
  // Local membrane DOFs (u, v, θz) of the corners.
  fe::Vector12d membrane;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d u = R.transpose() * u_global.segment<3>(6 * k);
    const Eigen::Vector3d theta = R.transpose() * u_global.segment<3>(6 * k + 3);
    membrane.segment<3>(3 * k) << u.x(), u.y(), theta.z();
  }
  const Eigen::Matrix3d D = membrane_elasticity(property);
  // ∫ ∇Nᵀ S ∇N dA on the corners' w, by the 2×2 rule.
  Eigen::Matrix4d k_w = Eigen::Matrix4d::Zero();
  for (const GaussPoint& g : kGauss2x2) {
    const Eigen::Vector3d n = D * membrane_strain(frame.xy, property, membrane, g.xi, g.eta);
    Eigen::Matrix2d s;
    s << n(0), n(2), n(2), n(1);
    const QuadPoint p = quad_point(frame.xy, g.xi, g.eta);
    k_w += p.dn_dxy.transpose() * s * p.dn_dxy * (p.det_j * g.weight);
  }
  // w_k = e3 · u_k: scatter onto the translational blocks.
  const Eigen::Vector3d e3 = R.col(2);
  const Eigen::Matrix3d e3e3 = e3 * e3.transpose();
  Matrix24d k = Matrix24d::Zero();
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) k.block<3, 3>(6 * a, 6 * b) = k_w(a, b) * e3e3;
  }
  return k;
}

}  // namespace limber::fe
