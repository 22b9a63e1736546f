#include "fe/element_stress.h"

#include <algorithm>
#include <cmath>

#include "fe/beam_element.h"
#include "fe/shell_element.h"
#include "fe/shell_membrane.h"
#include "fe/shell_plate.h"

namespace limber::fe {

BeamResultantOperator beam_resultant_operator(const Eigen::Vector3d& p_node0,
                                              const Eigen::Vector3d& p_node1,
                                              const Eigen::Vector3d& orientation,
                                              const BeamProperty& property) {
  const Eigen::Matrix3d r_lg = beam_local_axes(p_node0, p_node1, orientation);
  const Matrix12d k_local = beam_local_matrices((p_node1 - p_node0).norm(), property).stiffness;
  Matrix12d t = Matrix12d::Zero();
  for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * b, 3 * b) = r_lg;
  // Nodal forces on the element in local axes; end 0 acts on the section's negative face.
  BeamResultantOperator op = k_local * t;
  op.topRows<6>() *= -1.0;
  return op;
}

double beam_extreme_fibre_stress(const Eigen::Matrix<double, kBeamResultants, 1>& r,
                                 const BeamSection& section) {
  double worst = 0.0;
  for (int end = 0; end < 2; ++end) {
    const double n = r(6 * end), my = r(6 * end + 4), mz = r(6 * end + 5);
    const double axial = std::abs(n) / section.area;
    // A circle's worst fibre lies along the resultant moment's normal.
    const double bending =
        section.circular
            ? std::hypot(my, mz) * section.fibre_z / section.inertia_y
            : std::abs(my) * section.fibre_z / section.inertia_y +
                  std::abs(mz) * section.fibre_y / section.inertia_z;
    worst = std::max(worst, axial + bending);
  }
  return worst;
}

ShellResultantOperator shell_resultant_operator(const std::array<Eigen::Vector3d, 4>& corners,
                                                const ShellProperty& property) {
  const ShellFrame frame = shell_frame(corners);
  const Matrix24d t = shell_global_to_local(frame);
  const Eigen::Matrix3d d_membrane = membrane_elasticity(property);
  const Eigen::Matrix3d d_bending = plate_bending_rigidity(property);
  // Columns of the local map: unit values of each local membrane and plate DOF.
  Eigen::Matrix<double, kShellResultants, 24> local = Eigen::Matrix<double, 6, 24>::Zero();
  for (int a = 0; a < 4; ++a) {
    for (int i = 0; i < 3; ++i) {
      Vector12d unit = Vector12d::Zero();
      unit(3 * a + i) = 1.0;
      local.block<3, 1>(0, 6 * a + kShellMembraneDofs[i]) =
          d_membrane * membrane_strain(frame.xy, property, unit, 0.0, 0.0);
      local.block<3, 1>(3, 6 * a + kShellPlateDofs[i]) =
          d_bending * plate_curvature(frame.xy, unit, 0.0, 0.0);
    }
  }
  return local * t;
}

double shell_fibre_distance(const ShellProperty& property) {
  return property.fibre_distance > 0.0 ? property.fibre_distance : 0.5 * property.thickness;
}

Eigen::Vector2d shell_von_mises(const Eigen::Matrix<double, kShellResultants, 1>& r,
                                const ShellProperty& property) {
  const double t = property.thickness;
  const double inertia = property.bending_ratio * t * t * t / 12.0;
  const double z = shell_fibre_distance(property);
  Eigen::Vector2d out;
  for (int side = 0; side < 2; ++side) {
    const double zs = side == 0 ? z : -z;
    const Eigen::Vector3d s = r.head<3>() / t + zs * r.tail<3>() / inertia;
    out(side) = std::sqrt(std::max(0.0, s(0) * s(0) + s(1) * s(1) - s(0) * s(1) + 3.0 * s(2) * s(2)));
  }
  return out;
}

}  // namespace limber::fe
