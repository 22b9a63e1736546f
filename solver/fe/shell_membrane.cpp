#include "fe/shell_membrane.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace limber::fe {

namespace {

using Matrix312d = Eigen::Matrix<double, 3, 12>;
using Matrix34d = Eigen::Matrix<double, 3, 4>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

// Strain rows of the bilinear field and drilling row g (θz − ω = g · d) of the compatible
// DOFs (u, v, θz) per node.
struct CompatibleRows {
  Matrix312d strain = Matrix312d::Zero();
  Vector12d drilling = Vector12d::Zero();
};
CompatibleRows compatible_rows(const QuadPoint& point) {
  CompatibleRows rows;
  for (int k = 0; k < 4; ++k) {
    const double nx = point.dn_dxy(0, k);
    const double ny = point.dn_dxy(1, k);
    rows.strain(0, 3 * k) = nx;
    rows.strain(1, 3 * k + 1) = ny;
    rows.strain(2, 3 * k) = ny;
    rows.strain(2, 3 * k + 1) = nx;
    rows.drilling(3 * k) = 0.5 * ny;
    rows.drilling(3 * k + 1) = -0.5 * nx;
    rows.drilling(3 * k + 2) = point.n(k);
  }
  return rows;
}

// The same rows for the incompatible modes, parameters (a1x, a2x, a1y, a2y) with
// u += a1x (1 − ξ²) + a2x (1 − η²), v likewise; derivatives from the centre Jacobian, scaled by
// det J0 / det J (Taylor, Beresford & Wilson 1976), so that they integrate to zero.
struct IncompatibleRows {
  Matrix34d strain = Matrix34d::Zero();
  Eigen::Vector4d drilling = Eigen::Vector4d::Zero();
};
IncompatibleRows incompatible_rows(const QuadPoint& point, const QuadPoint& centre, double xi,
                                   double eta) {
  const Eigen::Matrix2d inverse_j0 = centre.jacobian.inverse();
  const double scale = centre.det_j / point.det_j;
  const Eigen::Vector2d d_mode1 = scale * inverse_j0 * Eigen::Vector2d(-2.0 * xi, 0.0);
  const Eigen::Vector2d d_mode2 = scale * inverse_j0 * Eigen::Vector2d(0.0, -2.0 * eta);
  IncompatibleRows rows;
  rows.strain(0, 0) = d_mode1.x();
  rows.strain(0, 1) = d_mode2.x();
  rows.strain(1, 2) = d_mode1.y();
  rows.strain(1, 3) = d_mode2.y();
  rows.strain(2, 0) = d_mode1.y();
  rows.strain(2, 1) = d_mode2.y();
  rows.strain(2, 2) = d_mode1.x();
  rows.strain(2, 3) = d_mode2.x();
  rows.drilling << 0.5 * d_mode1.y(), 0.5 * d_mode2.y(), -0.5 * d_mode1.x(), -0.5 * d_mode2.x();
  return rows;
}

// Blocks of the membrane + drilling stiffness before condensation of the incompatible modes.
struct MembraneBlocks {
  Matrix12d kcc = Matrix12d::Zero();
  Eigen::Matrix<double, 12, 4> kci = Eigen::Matrix<double, 12, 4>::Zero();
  Eigen::Matrix4d kii = Eigen::Matrix4d::Zero();
};

MembraneBlocks membrane_blocks(const QuadCoordinates& xy, const ShellProperty& property) {
  const Eigen::Matrix3d d = membrane_elasticity(property);
  const double penalty = kDrillingPenalty * property.material.shear_modulus() * property.thickness;
  const QuadPoint centre = quad_point(xy, 0.0, 0.0);
  MembraneBlocks blocks;
  // Plane-stress energy ∫ εᵀ D ε and drilling penalty α G t ∫ (θz − ω)², 2×2 Gauss.
  for (const GaussPoint& gauss : kGauss2x2) {
    const QuadPoint point = quad_point(xy, gauss.xi, gauss.eta);
    const CompatibleRows c = compatible_rows(point);
    const IncompatibleRows i = incompatible_rows(point, centre, gauss.xi, gauss.eta);
    const double w = gauss.weight * point.det_j;
    blocks.kcc +=
        w * (c.strain.transpose() * d * c.strain + penalty * c.drilling * c.drilling.transpose());
    blocks.kci +=
        w * (c.strain.transpose() * d * i.strain + penalty * c.drilling * i.drilling.transpose());
    blocks.kii +=
        w * (i.strain.transpose() * d * i.strain + penalty * i.drilling * i.drilling.transpose());
  }
  return blocks;
}

}  // namespace

Eigen::Matrix3d membrane_elasticity(const ShellProperty& property) {
  const double e = property.material.youngs_modulus;
  const double nu = property.material.poisson_ratio;
  Eigen::Matrix3d d;
  d << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  return e * property.thickness / (1.0 - nu * nu) * d;
}

Matrix12d membrane_stiffness(const QuadCoordinates& xy, const ShellProperty& property) {
  // Static condensation of the incompatible modes: Kcc − Kci Kii⁻¹ Kic.
  const MembraneBlocks blocks = membrane_blocks(xy, property);
  return blocks.kcc - blocks.kci * blocks.kii.ldlt().solve(blocks.kci.transpose());
}

Eigen::Vector3d membrane_strain(const QuadCoordinates& xy, const ShellProperty& property,
                                const Vector12d& dofs, double xi, double eta) {
  // Incompatible-mode amplitudes from the condensation: a = −Kii⁻¹ Kic d.
  const MembraneBlocks blocks = membrane_blocks(xy, property);
  const Eigen::Vector4d a = -blocks.kii.ldlt().solve(blocks.kci.transpose() * dofs);
  // Strain of both fields at the point.
  const QuadPoint centre = quad_point(xy, 0.0, 0.0);
  const QuadPoint point = quad_point(xy, xi, eta);
  return compatible_rows(point).strain * dofs +
         incompatible_rows(point, centre, xi, eta).strain * a;
}

}  // namespace limber::fe
