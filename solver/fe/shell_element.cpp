// Flat 4-node shell: membrane (shell_membrane.h) + MITC4 plate (shell_plate.h) superposed in
// the local frame of the quad's mean plane (shell_frame.h), consistent mass, rotation to
// global axes.
//
// Mass per unit area: ρ T + NSM on (u, v, w) with the bilinear shape functions (consistent),
// rotary inertia ρ I = ρ (12I/T³) T³/12 on (θx, θy) (the faces' own for a sandwich; the
// non-structural mass sits on the mid-surface), and ρ T³/12 on the drilling rotation θz. The
// drilling inertia is not physical (it adds ρ T³ A / 12 to the moment of inertia about the
// normal, a relative error T² / (12 r²) for a homogeneous body of gyration radius r) but keeps
// M positive definite; it does not follow 12I/T³, so a sandwich's drilling modes stay as high
// as a homogeneous plate's. 2×2 Gauss integration is exact for these terms.
#include "fe/shell_element.h"

#include "core/error.h"
#include "fe/shell_frame.h"
#include "fe/shell_membrane.h"
#include "fe/shell_plate.h"

namespace limber::fe {

namespace {

// Adds a 12×12 matrix laid out as 4 nodes × 3 DOFs into the 24×24 local matrix.
void scatter(const Matrix12d& part, const std::array<int, 3>& dofs, Matrix24d& whole) {
  for (int a = 0; a < 4; ++a) {
    for (int i = 0; i < 3; ++i) {
      for (int b = 0; b < 4; ++b) {
        for (int j = 0; j < 3; ++j) {
          whole(6 * a + dofs[i], 6 * b + dofs[j]) += part(3 * a + i, 3 * b + j);
        }
      }
    }
  }
}

// Consistent mass in the local frame.
Matrix24d local_mass(const QuadCoordinates& xy, const ShellProperty& property) {
  const double t = property.thickness;
  const double rho = property.material.density;
  const double translational = rho * t + property.nonstructural_mass;
  // ρ I and ρ T³/12; the ratio multiplies first so that 12I/T³ = 1 rounds as ρ T³/12 does.
  const double rotary = rho * property.bending_ratio * t * t * t / 12.0;
  const double drilling = rho * t * t * t / 12.0;
  Matrix24d m = Matrix24d::Zero();
  for (const GaussPoint& gauss : kGauss2x2) {
    const QuadPoint point = quad_point(xy, gauss.xi, gauss.eta);
    const double w = gauss.weight * point.det_j;
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        const double nn = w * point.n(a) * point.n(b);
        for (int i = 0; i < 3; ++i) m(6 * a + i, 6 * b + i) += translational * nn;
        for (int i = 3; i < 5; ++i) m(6 * a + i, 6 * b + i) += rotary * nn;
        m(6 * a + 5, 6 * b + 5) += drilling * nn;
      }
    }
  }
  return m;
}

}  // namespace

Matrix24d shell_global_to_local(const ShellFrame& frame) {
  const Eigen::Matrix3d rotation_LW = frame.rotation_WL.transpose();
  const Eigen::Vector3d e3 = frame.rotation_WL.col(2);
  Matrix24d t = Matrix24d::Zero();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d offset = -frame.warp_offsets[k] * e3;
    Eigen::Matrix3d skew_offset;
    skew_offset << 0.0, -offset.z(), offset.y(), offset.z(), 0.0, -offset.x(), -offset.y(),
        offset.x(), 0.0;
    t.block<3, 3>(6 * k, 6 * k) = rotation_LW;
    t.block<3, 3>(6 * k, 6 * k + 3) = -rotation_LW * skew_offset;
    t.block<3, 3>(6 * k + 3, 6 * k + 3) = rotation_LW;
  }
  return t;
}

ShellElementMatrices shell_element_matrices(const std::array<Eigen::Vector3d, 4>& corners,
                                            const ShellProperty& property) {
  LIMBER_DEMAND(property.thickness > 0.0 && property.material.youngs_modulus > 0.0 &&
                property.bending_ratio > 0.0 && property.shear_ratio > 0.0 &&
                property.nonstructural_mass >= 0.0);
  // Local frame and shape checks (throws InputError).
  const ShellFrame frame = shell_frame(corners);

  // Local stiffness: membrane with drilling + MITC4 plate.
  Matrix24d k_local = Matrix24d::Zero();
  scatter(membrane_stiffness(frame.xy, property), kShellMembraneDofs, k_local);
  scatter(plate_stiffness(frame.xy, property), kShellPlateDofs, k_local);

  // Rotate (and offset) to global axes: K = Tᵀ K_L T, M = Tᵀ M_L T.
  const Matrix24d t = shell_global_to_local(frame);
  ShellElementMatrices matrices;
  matrices.stiffness = t.transpose() * k_local * t;
  matrices.mass = t.transpose() * local_mass(frame.xy, property) * t;
  // Symmetrise away the round-off of the triple products.
  matrices.stiffness = 0.5 * (matrices.stiffness + matrices.stiffness.transpose()).eval();
  matrices.mass = 0.5 * (matrices.mass + matrices.mass.transpose()).eval();
  return matrices;
}

}  // namespace limber::fe
