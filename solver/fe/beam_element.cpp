#include "fe/beam_element.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <array>

#include "core/error.h"

namespace limber::fe {

namespace {

using Matrix4d = Eigen::Matrix4d;

// Bending matrices of one plane, DOFs (deflection 0, rotation 0, deflection 1, rotation 1)
// with rotation = +d(deflection)/dx. Przemieniecki 1968 (ch. 5 stiffness, ch. 11 translational
// and rotary consistent mass) with shear parameter phi; phi = 0 gives Euler-Bernoulli.
struct PlaneBending {
  Matrix4d stiffness;
  Matrix4d mass;
};

PlaneBending plane_bending(double ei, double rho_a, double rho_i, double length, double phi) {
  const double l = length;
  const double l2 = l * l;
  const double p = phi;
  const double p2 = phi * phi;
  PlaneBending out;

  // Stiffness with shear deformation.
  const double k = ei / ((1.0 + p) * l2 * l);
  // clang-format off
  out.stiffness << 12.0, 6.0 * l, -12.0, 6.0 * l,
                   6.0 * l, (4.0 + p) * l2, -6.0 * l, (2.0 - p) * l2,
                   -12.0, -6.0 * l, 12.0, -6.0 * l,
                   6.0 * l, (2.0 - p) * l2, -6.0 * l, (4.0 + p) * l2;
  // clang-format on
  out.stiffness *= k;

  // Translational inertia rho A.
  const double m11 = 13.0 / 35.0 + 7.0 / 10.0 * p + 1.0 / 3.0 * p2;
  const double m12 = (11.0 / 210.0 + 11.0 / 120.0 * p + 1.0 / 24.0 * p2) * l;
  const double m13 = 9.0 / 70.0 + 3.0 / 10.0 * p + 1.0 / 6.0 * p2;
  const double m14 = -(13.0 / 420.0 + 3.0 / 40.0 * p + 1.0 / 24.0 * p2) * l;
  const double m22 = (1.0 / 105.0 + 1.0 / 60.0 * p + 1.0 / 120.0 * p2) * l2;
  const double m24 = -(1.0 / 140.0 + 1.0 / 60.0 * p + 1.0 / 120.0 * p2) * l2;
  Matrix4d translational;
  // clang-format off
  translational << m11, m12, m13, m14,
                   m12, m22, -m14, m24,
                   m13, -m14, m11, -m12,
                   m14, m24, -m12, m22;
  // clang-format on
  translational *= rho_a * l / ((1.0 + p) * (1.0 + p));

  // Rotary inertia rho I of the section.
  const double r11 = 6.0 / 5.0;
  const double r12 = (1.0 / 10.0 - 1.0 / 2.0 * p) * l;
  const double r22 = (2.0 / 15.0 + 1.0 / 6.0 * p + 1.0 / 3.0 * p2) * l2;
  const double r24 = (-1.0 / 30.0 - 1.0 / 6.0 * p + 1.0 / 6.0 * p2) * l2;
  Matrix4d rotary;
  // clang-format off
  rotary << r11, r12, -r11, r12,
            r12, r22, -r12, r24,
            -r11, -r12, r11, -r12,
            r12, r24, -r12, r22;
  // clang-format on
  rotary *= rho_i / ((1.0 + p) * (1.0 + p) * l);

  out.mass = translational + rotary;
  return out;
}

// Scatters a 4x4 plane matrix into the 12x12 local matrix at `dofs`, flipping the sign of
// rows/columns with sign -1 (x-z plane: ry = -dw/dx).
void scatter(const Matrix4d& block, const std::array<int, 4>& dofs,
             const std::array<double, 4>& signs, Matrix12d& target) {
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      target(dofs[i], dofs[j]) += signs[i] * signs[j] * block(i, j);
    }
  }
}

// Two-DOF bar matrices: stiffness c [1 -1; -1 1], mass m/6 [2 1; 1 2].
void add_bar(int dof0, int dof1, double stiffness, double mass, BeamElementMatrices& out) {
  const std::array<int, 2> dofs{dof0, dof1};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      out.stiffness(dofs[i], dofs[j]) += (i == j ? stiffness : -stiffness);
      out.mass(dofs[i], dofs[j]) += (i == j ? 2.0 : 1.0) * mass / 6.0;
    }
  }
}

}  // namespace

Eigen::Matrix3d beam_local_axes(const Eigen::Vector3d& p_node0, const Eigen::Vector3d& p_node1,
                                const Eigen::Vector3d& orientation) {
  // Local x along the axis.
  const Eigen::Vector3d axis = p_node1 - p_node0;
  const double length = axis.norm();
  if (!(length > 0.0)) {
    throw InputError(
        fmt::format("beam: expected two distinct node positions, got length {}", length));
  }
  const Eigen::Vector3d x = axis / length;

  // Local z normal to the plane of the axis and the orientation vector.
  const double v_norm = orientation.norm();
  const Eigen::Vector3d z_raw = x.cross(orientation);
  if (!(v_norm > 0.0) || !(z_raw.norm() >= 1e-6 * v_norm)) {
    throw InputError(fmt::format(
        "beam: expected an orientation vector not parallel to the axis ({:.6g}, {:.6g}, {:.6g}), "
        "got ({:.6g}, {:.6g}, {:.6g})",
        x.x(), x.y(), x.z(), orientation.x(), orientation.y(), orientation.z()));
  }
  const Eigen::Vector3d z = z_raw.normalized();
  const Eigen::Vector3d y = z.cross(x);

  Eigen::Matrix3d r_lg;
  r_lg.row(0) = x.transpose();
  r_lg.row(1) = y.transpose();
  r_lg.row(2) = z.transpose();
  return r_lg;
}

BeamElementMatrices beam_local_matrices(double length, const BeamProperty& property) {
  LIMBER_DEMAND(length > 0.0);
  const Material& mat = property.material;
  const BeamSection& sec = property.section;
  const double e = mat.youngs_modulus;
  const double g = mat.shear_modulus();
  const double rho = mat.density;
  const double l = length;

  BeamElementMatrices out;
  out.stiffness.setZero();
  out.mass.setZero();

  // Axial (ux) and St-Venant torsion (rx) with polar mass moment rho (Iy + Iz).
  add_bar(0, 6, e * sec.area / l, rho * sec.area * l, out);
  add_bar(3, 9, g * sec.torsion_constant / l, rho * (sec.inertia_y + sec.inertia_z) * l, out);

  // Shear parameters (zero for Euler-Bernoulli): Phi = 12 E I / (k G A L^2).
  double phi_y = 0.0;  // x-y plane: shear along y, bending about z
  double phi_z = 0.0;  // x-z plane: shear along z, bending about y
  if (property.timoshenko) {
    phi_y = 12.0 * e * sec.inertia_z / (sec.shear_factor_y * g * sec.area * l * l);
    phi_z = 12.0 * e * sec.inertia_y / (sec.shear_factor_z * g * sec.area * l * l);
  }

  // Section rotary inertia of bending, unless switched off.
  const double rho_iy = property.rotary_inertia ? rho * sec.inertia_y : 0.0;
  const double rho_iz = property.rotary_inertia ? rho * sec.inertia_z : 0.0;

  // Bending in x-y: (v0, rz0, v1, rz1), rz = +dv/dx.
  const PlaneBending xy = plane_bending(e * sec.inertia_z, rho * sec.area, rho_iz, l, phi_y);
  scatter(xy.stiffness, {1, 5, 7, 11}, {1.0, 1.0, 1.0, 1.0}, out.stiffness);
  scatter(xy.mass, {1, 5, 7, 11}, {1.0, 1.0, 1.0, 1.0}, out.mass);

  // Bending in x-z: (w0, ry0, w1, ry1), ry = -dw/dx.
  const PlaneBending xz = plane_bending(e * sec.inertia_y, rho * sec.area, rho_iy, l, phi_z);
  scatter(xz.stiffness, {2, 4, 8, 10}, {1.0, -1.0, 1.0, -1.0}, out.stiffness);
  scatter(xz.mass, {2, 4, 8, 10}, {1.0, -1.0, 1.0, -1.0}, out.mass);
  return out;
}

BeamElementMatrices beam_element_matrices(const Eigen::Vector3d& p_node0,
                                          const Eigen::Vector3d& p_node1,
                                          const Eigen::Vector3d& orientation,
                                          const BeamProperty& property) {
  const Eigen::Matrix3d r_lg = beam_local_axes(p_node0, p_node1, orientation);
  const BeamElementMatrices local = beam_local_matrices((p_node1 - p_node0).norm(), property);

  // T = diag(R_LG, R_LG, R_LG, R_LG); global = T^T local T.
  Matrix12d t = Matrix12d::Zero();
  for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * b, 3 * b) = r_lg;
  BeamElementMatrices out;
  out.stiffness = t.transpose() * local.stiffness * t;
  out.mass = t.transpose() * local.mass * t;
  return out;
}

}  // namespace limber::fe
