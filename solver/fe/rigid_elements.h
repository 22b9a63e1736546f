// Rigid and interpolation elements as linear multipoint constraints (fe_model.h,
// MultipointConstraint), linearised about the undeformed positions (small displacements and
// rotations, as the rest of the FE model). Definitions: MSC Nastran Quick Reference Guide,
// bulk data entries RBE2 ("rigid body element, form 2") and RBE3 ("defines the motion at a
// reference grid point as the weighted average of the motions at a set of other grid points");
// docs/bulk-data.md, "Rigid elements".
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "fe/fe_model.h"

namespace limber::fe {

// RBE2: each dependent node m follows the independent node n rigidly in `dofs`:
//   u_m = u_n + theta_n x (x_m - x_n),   theta_m = theta_n   (the rows `dofs` of it).
// Positions in metres; one constraint per (dependent node, DOF), in that order.
std::vector<MultipointConstraint> rigid_link_constraints(
    const std::vector<Eigen::Vector3d>& node_positions, int independent_node,
    const std::vector<int>& dependent_nodes, const std::vector<Dof>& dofs);

// One weight group of an RBE3: nodes whose `dofs` enter the average with `weight`.
struct WeightedNodes {
  double weight = 1.0;
  std::vector<Dof> dofs;
  std::vector<int> nodes;
};

// RBE3: the reference node's motion u_ref (6) is the weighted least-squares fit of a rigid
// motion to the listed DOFs of the independent nodes:
//   minimise sum_i (S_i u_ref - u_i)^T W_i (S_i u_ref - u_i),
//   S_i = [I  -[d_i]x; 0  I] (rows: node i's listed DOFs), d_i = x_i - x_ref,
//   W_i = weight on translations, weight L^2 on rotations (L: mean distance of the independent
//         nodes from the reference, 1 m if all coincide with it, so that both are in N/m units),
//   u_ref = A^-1 sum_i S_i^T W_i u_i,   A = sum_i S_i^T W_i S_i,
// and the `reference_dofs` rows of it are the dependent DOFs. A rigid motion of the
// independent nodes (u_i = S_i u) gives u_ref = u exactly, so the element adds no stiffness.
// Returns nothing and sets `error` when A is singular (the listed DOFs do not fix all six
// rigid motions, e.g. grids on a line with components 123 only), when a weight is not > 0, or
// when the reference node is also independent.
std::vector<MultipointConstraint> interpolation_constraints(
    const std::vector<Eigen::Vector3d>& node_positions, int reference_node,
    const std::vector<Dof>& reference_dofs, const std::vector<WeightedNodes>& groups,
    std::string& error);

}  // namespace limber::fe
