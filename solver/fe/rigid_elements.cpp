#include "fe/rigid_elements.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace limber::fe {

namespace {

// The 6x6 map from a rigid motion (u, theta) at a reference to the motion of a point at
// offset d from it: u + theta x d = u - d x theta, theta.
Eigen::Matrix<double, 6, 6> rigid_transfer(const Eigen::Vector3d& d) {
  Eigen::Matrix<double, 6, 6> s = Eigen::Matrix<double, 6, 6>::Identity();
  Eigen::Matrix3d d_cross;
  d_cross << 0.0, -d.z(), d.y(), d.z(), 0.0, -d.x(), -d.y(), d.x(), 0.0;
  s.topRightCorner<3, 3>() = -d_cross;
  return s;
}

}  // namespace

std::vector<MultipointConstraint> rigid_link_constraints(
    const std::vector<Eigen::Vector3d>& node_positions, int independent_node,
    const std::vector<int>& dependent_nodes, const std::vector<Dof>& dofs) {
  std::vector<MultipointConstraint> constraints;
  const Eigen::Vector3d& x_n = node_positions[static_cast<std::size_t>(independent_node)];
  for (int m : dependent_nodes) {
    const Eigen::Matrix<double, 6, 6> s = rigid_transfer(node_positions[static_cast<std::size_t>(m)] - x_n);
    for (Dof dof : dofs) {
      const int row = static_cast<int>(dof);
      MultipointConstraint c;
      c.dependent = FeModel::dof_index(m, dof);
      // Only the non-zero terms of the row.
      for (int k = 0; k < kDofsPerNode; ++k) {
        if (s(row, k) == 0.0) continue;
        c.independent.push_back(FeModel::dof_index(independent_node, static_cast<Dof>(k)));
        c.coefficients.push_back(s(row, k));
      }
      constraints.push_back(std::move(c));
    }
  }
  return constraints;
}

std::vector<MultipointConstraint> interpolation_constraints(
    const std::vector<Eigen::Vector3d>& node_positions, int reference_node,
    const std::vector<Dof>& reference_dofs, const std::vector<WeightedNodes>& groups,
    std::string& error) {
  const Eigen::Vector3d& x_ref = node_positions[static_cast<std::size_t>(reference_node)];
  // Mean distance of the independent nodes from the reference (rotational weight scale).
  double distance_sum = 0.0;
  int count = 0;
  for (const WeightedNodes& group : groups) {
    if (!(group.weight > 0.0)) {
      error = fmt::format("expected weights > 0, got {}", group.weight);
      return {};
    }
    for (int node : group.nodes) {
      if (node == reference_node) {
        error = "expected independent grids other than the reference grid, got the reference grid";
        return {};
      }
      distance_sum += (node_positions[static_cast<std::size_t>(node)] - x_ref).norm();
      ++count;
    }
  }
  const double mean_distance = count > 0 && distance_sum > 0.0 ? distance_sum / count : 1.0;

  // Normal equations A u_ref = B u_i over the listed independent DOFs.
  std::vector<int> columns;  // global DOFs of u_i
  std::vector<Eigen::Matrix<double, 6, 1>> b_columns;
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  for (const WeightedNodes& group : groups) {
    for (int node : group.nodes) {
      const Eigen::Matrix<double, 6, 6> s =
          rigid_transfer(node_positions[static_cast<std::size_t>(node)] - x_ref);
      for (Dof dof : group.dofs) {
        const int row = static_cast<int>(dof);
        const double w = row < 3 ? group.weight : group.weight * mean_distance * mean_distance;
        a += w * s.row(row).transpose() * s.row(row);
        columns.push_back(FeModel::dof_index(node, dof));
        b_columns.push_back(w * s.row(row).transpose());
      }
    }
  }
  // Rank test on A scaled to comparable units (rotations times the mean distance).
  Eigen::Matrix<double, 6, 1> scale;
  scale << 1.0, 1.0, 1.0, mean_distance, mean_distance, mean_distance;
  const Eigen::Matrix<double, 6, 6> a_scaled = scale.cwiseInverse().asDiagonal() * a * scale.cwiseInverse().asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(a_scaled);
  // 1e-10: far below any real spread of grids, far above the round-off of A (1e-16).
  if (!(eigen.eigenvalues()(0) > 1e-10 * eigen.eigenvalues()(5))) {
    error = "expected independent grids and components that fix all six rigid motions of the "
            "reference grid (e.g. three grids not on a line with components 123), got a set "
            "that leaves a rigid motion free";
    return {};
  }
  const Eigen::Matrix<double, 6, 6> a_inverse = a.inverse();

  // One constraint per reference DOF: the row of A^-1 B.
  std::vector<MultipointConstraint> constraints;
  for (Dof dof : reference_dofs) {
    MultipointConstraint c;
    c.dependent = FeModel::dof_index(reference_node, dof);
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const double coefficient = a_inverse.row(static_cast<int>(dof)).dot(b_columns[k]);
      if (coefficient == 0.0) continue;
      c.independent.push_back(columns[k]);
      c.coefficients.push_back(coefficient);
    }
    constraints.push_back(std::move(c));
  }
  return constraints;
}

}  // namespace limber::fe
