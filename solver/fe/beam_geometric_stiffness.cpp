#include "fe/beam_geometric_stiffness.h"

#include <array>

#include "core/error.h"

namespace limber::fe {

Matrix12d beam_local_geometric_stiffness(double length, double axial_force, const BeamProperty& property) {
  LIMBER_DEMAND(length > 0.0);
  const double l = length;
  const double n = axial_force;
  Matrix12d k = Matrix12d::Zero();
  // One bending plane: N/L times the Hermite string matrix.
  Eigen::Matrix4d plane;
  // clang-format off
  plane << 6.0 / 5.0, l / 10.0,            -6.0 / 5.0, l / 10.0,
           l / 10.0,  2.0 * l * l / 15.0,  -l / 10.0,  -l * l / 30.0,
           -6.0 / 5.0, -l / 10.0,          6.0 / 5.0,  -l / 10.0,
           l / 10.0,  -l * l / 30.0,       -l / 10.0,  2.0 * l * l / 15.0;
  // clang-format on
  plane *= n / l;
  // x-y plane (v, θz = +dv/dx) and x-z plane (w, θy = −dw/dx).
  const std::array<int, 4> xy{1, 5, 7, 11}, xz{2, 4, 8, 10};
  const std::array<double, 4> xz_sign{1.0, -1.0, 1.0, -1.0};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      k(xy[i], xy[j]) += plane(i, j);
      k(xz[i], xz[j]) += xz_sign[i] * xz_sign[j] * plane(i, j);
    }
  }
  // Torsion: the axial stress acting on the twisted fibres, N Ip / (A L).
  const BeamSection& s = property.section;
  const double torsion = n * (s.inertia_y + s.inertia_z) / (s.area * l);
  k(3, 3) += torsion;
  k(9, 9) += torsion;
  k(3, 9) -= torsion;
  k(9, 3) -= torsion;
  return k;
}

Matrix12d beam_geometric_stiffness(const Eigen::Vector3d& p_node0, const Eigen::Vector3d& p_node1,
                                   const Eigen::Vector3d& orientation, const BeamProperty& property,
                                   double axial_force) {
  const Eigen::Matrix3d r_lg = beam_local_axes(p_node0, p_node1, orientation);
  const Matrix12d local = beam_local_geometric_stiffness((p_node1 - p_node0).norm(), axial_force, property);
  Matrix12d t = Matrix12d::Zero();
  for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * b, 3 * b) = r_lg;
  return t.transpose() * local * t;
}

double beam_axial_force(const Eigen::Vector3d& p_node0, const Eigen::Vector3d& p_node1,
                        const BeamProperty& property, const Vector12d& u_global) {
  const Eigen::Vector3d axis = p_node1 - p_node0;
  const double l = axis.norm();
  LIMBER_DEMAND(l > 0.0);
  const double stretch = axis.dot(u_global.segment<3>(6) - u_global.segment<3>(0)) / l;
  return property.material.youngs_modulus * property.section.area * stretch / l;
}

}  // namespace limber::fe
