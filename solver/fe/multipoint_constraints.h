// Elimination of linear multipoint constraints (fe_model.h, MultipointConstraint) by the
// master-slave transformation (Cook, Malkus, Plesha & Witt, "Concepts and Applications of
// Finite Element Analysis", 4th ed., 2002, §9.2 "Transformation of constraint equations"):
//   u = T u_r,   u_r = the independent DOFs,   K_r = T^T K T,   M_r = T^T M T,
// T's row of an independent DOF is a unit row; a dependent DOF's row holds its coefficients,
// with chains (an independent DOF that is dependent elsewhere) substituted through.
// Rigid motions that satisfy the constraints (RBE2, RBE3) lie in the range of T, so the reduced
// model keeps them; the full displacement of any reduced vector is T u_r.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/SparseCore>

#include "fe/fe_model.h"

namespace limber::fe {

struct ConstraintTransformation {
  Eigen::SparseMatrix<double> transformation;  // T, n x n_r
  std::vector<int> independent_dofs;           // the n_r DOFs of u_r, ascending
  std::vector<int> dependent_dofs;             // ascending
};

// The indices of constraints that form a cycle (a dependent DOF that depends on itself
// through a chain), in chain order; nothing when the constraints are acyclic.
// Precondition (DEMAND): each DOF is dependent in at most one constraint.
std::optional<std::vector<int>> constraint_cycle(const FeModel& model);

// T for the model's constraints (the identity's columns when there are none).
// Preconditions (DEMAND): no cycle, DOFs in range, each DOF dependent at most once.
ConstraintTransformation constraint_transformation(const FeModel& model);

// The embedding of the reduced matrix A_r (n_r x n_r, order of independent_dofs) in an n x n
// matrix: rows and columns of the independent DOFs, zero at the dependent ones.
Eigen::SparseMatrix<double> embed(const Eigen::SparseMatrix<double>& reduced,
                                  const std::vector<int>& independent_dofs, int n);

}  // namespace limber::fe
