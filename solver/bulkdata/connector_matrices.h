// The stiffness and mass blocks of the deck's connector elements (CROD/CONROD, CBUSH, CONM1) on
// a node's six DOFs, in basic axes. deck_to_fe.cpp resolves the cards (grids, properties,
// systems) and adds these blocks to the FE model.
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace limber::bulkdata {

using Block6 = Eigen::Matrix<double, 6, 6>;

// The six DOFs of `node` (FE DOF indices).
std::vector<int> node_dofs(int node);

// The twelve DOFs of two nodes, node-major.
std::vector<int> two_node_dofs(int a, int b);

// A 6x6 block on a node's translations and rotations, given along `axes` (columns: the local
// directions in basic), rotated to basic.
Block6 rotated_to_basic(const Block6& local, const Eigen::Matrix3d& axes);

// The 12x12 two-node block [x -x; -x x] of a spring between two nodes.
Eigen::MatrixXd spring_between(const Block6& x);

struct RodMatrices {
  Eigen::MatrixXd stiffness;  // 12x12 on two_node_dofs(a, b)
  Eigen::MatrixXd mass;
};

// A rod along `axis` (from its first grid to its second, length > 0): axial EA/L and torsional
// GJ/L along the axis; consistent mass m' L (linear interpolation) on all translations and
// ρJ L on the axial rotation, m' the mass per length and ρJ the polar inertia per length.
RodMatrices rod_matrices(const Eigen::Vector3d& axis, double axial_rigidity, double torsional_rigidity,
                         double mass_per_length, double polar_inertia_per_length);

}  // namespace limber::bulkdata
