#include "bulkdata/connector_matrices.h"

#include "fe/fe_model.h"

namespace limber::bulkdata {

std::vector<int> node_dofs(int node) {
  std::vector<int> dofs;
  for (int k = 0; k < fe::kDofsPerNode; ++k) dofs.push_back(fe::FeModel::dof_index(node, static_cast<fe::Dof>(k)));
  return dofs;
}

std::vector<int> two_node_dofs(int a, int b) {
  std::vector<int> dofs = node_dofs(a);
  const std::vector<int> second = node_dofs(b);
  dofs.insert(dofs.end(), second.begin(), second.end());
  return dofs;
}

Block6 rotated_to_basic(const Block6& local, const Eigen::Matrix3d& axes) {
  Block6 q = Block6::Zero();
  q.topLeftCorner<3, 3>() = axes;
  q.bottomRightCorner<3, 3>() = axes;
  return q * local * q.transpose();
}

namespace {

// The two-node block [a11 x, a12 x; a12 x, a11 x].
Eigen::MatrixXd two_node_block(const Block6& x, double a11, double a12) {
  Eigen::MatrixXd m(12, 12);
  m << a11 * x, a12 * x, a12 * x, a11 * x;
  return m;
}

}  // namespace

Eigen::MatrixXd spring_between(const Block6& x) { return two_node_block(x, 1.0, -1.0); }

RodMatrices rod_matrices(const Eigen::Vector3d& axis, double axial_rigidity, double torsional_rigidity,
                         double mass_per_length, double polar_inertia_per_length) {
  const double length = axis.norm();
  const Eigen::Matrix3d eet = axis * axis.transpose() / (length * length);
  Block6 k = Block6::Zero();
  k.topLeftCorner<3, 3>() = axial_rigidity / length * eet;
  k.bottomRightCorner<3, 3>() = torsional_rigidity / length * eet;
  // Consistent two-node mass of linear interpolation: [2 1; 1 2] m L / 6.
  Block6 m = Block6::Zero();
  m.topLeftCorner<3, 3>() = mass_per_length * length / 6.0 * Eigen::Matrix3d::Identity();
  m.bottomRightCorner<3, 3>() = polar_inertia_per_length * length / 6.0 * eet;
  return {spring_between(k), two_node_block(m, 2.0, 1.0)};
}

}  // namespace limber::bulkdata
