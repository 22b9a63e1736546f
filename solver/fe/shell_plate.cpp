#include "fe/shell_plate.h"

#include <Eigen/LU>

namespace limber::fe {

namespace {

using Matrix312d = Eigen::Matrix<double, 3, 12>;
using Matrix212d = Eigen::Matrix<double, 2, 12>;
using Row12d = Eigen::Matrix<double, 1, 12>;

// Curvature rows, DOFs (w, θx, θy) per node.
Matrix312d bending_b(const QuadPoint& point) {
  Matrix312d b = Matrix312d::Zero();
  for (int k = 0; k < 4; ++k) {
    const double nx = point.dn_dxy(0, k);
    const double ny = point.dn_dxy(1, k);
    b(0, 3 * k + 2) = nx;
    b(1, 3 * k + 1) = -ny;
    b(2, 3 * k + 1) = -nx;
    b(2, 3 * k + 2) = ny;
  }
  return b;
}

// Covariant shear strain along natural direction `axis` (0: ξ, 1: η) of the bilinear
// field at (ξ, η): γ_axis = ∂w/∂axis + x,axis θy − y,axis θx.
Row12d covariant_shear_row(const QuadCoordinates& xy, int axis, double xi, double eta) {
  const QuadPoint point = quad_point(xy, xi, eta);
  const double x_axis = point.jacobian(axis, 0);
  const double y_axis = point.jacobian(axis, 1);
  Row12d row = Row12d::Zero();
  for (int k = 0; k < 4; ++k) {
    row(3 * k) = point.dn_dnat(axis, k);
    row(3 * k + 1) = -y_axis * point.n(k);
    row(3 * k + 2) = x_axis * point.n(k);
  }
  return row;
}

// Tying-point rows of the assumed covariant shear (Dvorkin & Bathe 1984).
struct TyingRows {
  Row12d xi_bottom, xi_top;    // γ_ξ at (0, −1), (0, 1)
  Row12d eta_left, eta_right;  // γ_η at (−1, 0), (1, 0)
};

TyingRows tying_rows(const QuadCoordinates& xy) {
  return {covariant_shear_row(xy, 0, 0.0, -1.0), covariant_shear_row(xy, 0, 0.0, 1.0),
          covariant_shear_row(xy, 1, -1.0, 0.0), covariant_shear_row(xy, 1, 1.0, 0.0)};
}

// Cartesian assumed shear rows at (ξ, η): (γxz, γyz) = J⁻¹ (γ_ξ, γ_η).
Matrix212d assumed_shear_b(const TyingRows& tying, const QuadPoint& point, double xi, double eta) {
  Matrix212d covariant;
  covariant.row(0) = 0.5 * (1.0 - eta) * tying.xi_bottom + 0.5 * (1.0 + eta) * tying.xi_top;
  covariant.row(1) = 0.5 * (1.0 - xi) * tying.eta_left + 0.5 * (1.0 + xi) * tying.eta_right;
  return point.jacobian.inverse() * covariant;
}

}  // namespace

Eigen::Matrix3d plate_bending_rigidity(const ShellProperty& property) {
  const double e = property.material.youngs_modulus;
  const double nu = property.material.poisson_ratio;
  const double t = property.thickness;
  Eigen::Matrix3d d;
  d << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  // E I with I = r T³/12; r multiplies first so that r = 1 rounds exactly as E T³/12.
  return e * property.bending_ratio * t * t * t / (12.0 * (1.0 - nu * nu)) * d;
}

Matrix12d plate_stiffness(const QuadCoordinates& xy, const ShellProperty& property) {
  const Eigen::Matrix3d d_bending = plate_bending_rigidity(property);
  const double d_shear =
      property.shear_ratio * property.material.shear_modulus() * property.thickness;
  const TyingRows tying = tying_rows(xy);
  Matrix12d k = Matrix12d::Zero();
  // Bending and assumed shear energy at the 2×2 Gauss points.
  for (const GaussPoint& gauss : kGauss2x2) {
    const QuadPoint point = quad_point(xy, gauss.xi, gauss.eta);
    const Matrix312d bb = bending_b(point);
    const Matrix212d bs = assumed_shear_b(tying, point, gauss.xi, gauss.eta);
    const double w = gauss.weight * point.det_j;
    k += w * (bb.transpose() * d_bending * bb + d_shear * bs.transpose() * bs);
  }
  return k;
}

Eigen::Vector3d plate_curvature(const QuadCoordinates& xy, const Vector12d& dofs, double xi,
                                double eta) {
  return bending_b(quad_point(xy, xi, eta)) * dofs;
}

Eigen::Vector2d plate_shear_strain(const QuadCoordinates& xy, const Vector12d& dofs, double xi,
                                   double eta) {
  return assumed_shear_b(tying_rows(xy), quad_point(xy, xi, eta), xi, eta) * dofs;
}

}  // namespace limber::fe
