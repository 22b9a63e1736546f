// K and M of a component with its multipoint constraints (RBE2, RBE3) eliminated, for the
// modal reduction (fe/multipoint_constraints.h: u = T u_r, K_r = T^T K T, M_r = T^T M T).
//
// The reduced matrices are kept at full size n x n, embedded on the independent DOFs with
// zero rows and columns at the dependent ones, so every step of the reduction (normal modes,
// static modes, orthonormalisation) runs unchanged with the dependent DOFs left out of the
// free set; a full vector x (zero at dependent DOFs) stands for u = T x(independent DOFs),
// which `expand` returns. The rigid-body modes Psi (rigid_body_modes.h) satisfy RBE2 and RBE3
// exactly, so Psi = T Psi(independent rows) and the embedded Psi is Psi with its dependent
// rows zeroed.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fe/assembly.h"
#include "fe/fe_model.h"
#include "fe/multipoint_constraints.h"

namespace limber::modal {

struct ConstrainedMatrices {
  fe::ConstraintTransformation transformation;  // T and the (in)dependent DOFs
  Eigen::SparseMatrix<double> stiffness;        // T^T K T embedded, n x n
  Eigen::SparseMatrix<double> mass;             // T^T M T embedded, n x n
  Eigen::MatrixXd psi;                          // Psi with dependent rows zeroed, n x 6
  std::vector<int> free_dofs;                   // not fixed, not dependent, ascending
};

// Throws InputError when a rigid-body motion violates the constraints (an MPC equation that
// is not a rigid element's): the floating frame needs the rigid modes in the reduced space.
ConstrainedMatrices constrain(const fe::FeModel& model, const fe::StructuralMatrices& matrices,
                              const Eigen::MatrixXd& psi);

// u = T x(independent rows): full displacements of embedded vectors (n x k each).
Eigen::MatrixXd expand(const ConstrainedMatrices& constrained, const Eigen::MatrixXd& x);

// The embedded load of full loads f: T^T f on the independent rows (the work-equivalent load
// on u_r), zero at dependent rows.
Eigen::MatrixXd reduce_loads(const ConstrainedMatrices& constrained, const Eigen::MatrixXd& f);

}  // namespace limber::modal
