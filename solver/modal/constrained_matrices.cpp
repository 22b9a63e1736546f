#include "modal/constrained_matrices.h"

#include <fmt/format.h>

#include "core/error.h"
#include "modal/dof_selection.h"

namespace limber::modal {

ConstrainedMatrices constrain(const fe::FeModel& model, const fe::StructuralMatrices& matrices,
                              const Eigen::MatrixXd& psi) {
  ConstrainedMatrices out;
  out.transformation = fe::constraint_transformation(model);
  const fe::ConstraintTransformation& t = out.transformation;
  const Eigen::SparseMatrix<double>& tt = t.transformation;
  const int n = model.dof_count();
  const Eigen::SparseMatrix<double> k_r = tt.transpose() * matrices.stiffness * tt;
  const Eigen::SparseMatrix<double> m_r = tt.transpose() * matrices.mass * tt;
  out.stiffness = fe::embed(k_r, t.independent_dofs, n);
  out.mass = fe::embed(m_r, t.independent_dofs, n);
  out.free_dofs = set_difference(fe::free_dofs(model), t.dependent_dofs);

  // Rigid motion must satisfy the constraints: Psi = T Psi(independent rows).
  const Eigen::MatrixXd psi_independent = gather_rows(psi, t.independent_dofs);
  const Eigen::MatrixXd violation = tt * psi_independent - psi;
  // Relative 1e-9: rigid elements satisfy it to round-off of the node positions' products.
  const double scale = psi.cwiseAbs().maxCoeff();
  if (violation.cwiseAbs().maxCoeff() > 1e-9 * scale) {
    Eigen::Index row = 0, col = 0;
    violation.cwiseAbs().maxCoeff(&row, &col);
    throw InputError(fmt::format(
        "multipoint constraints: expected equations that every rigid-body motion satisfies "
        "(as RBE2 and RBE3 do), got a violation of {:.3g} at DOF {} of node {} in rigid motion "
        "{} (the floating frame needs the body's rigid motion)",
        violation(row, col), row % fe::kDofsPerNode + 1,
        model.node_ids[static_cast<std::size_t>(row / fe::kDofsPerNode)], col + 1));
  }
  out.psi = scatter_rows(psi_independent, t.independent_dofs, n);
  return out;
}

Eigen::MatrixXd expand(const ConstrainedMatrices& constrained, const Eigen::MatrixXd& x) {
  const fe::ConstraintTransformation& t = constrained.transformation;
  return t.transformation * gather_rows(x, t.independent_dofs);
}

Eigen::MatrixXd reduce_loads(const ConstrainedMatrices& constrained, const Eigen::MatrixXd& f) {
  const fe::ConstraintTransformation& t = constrained.transformation;
  const Eigen::MatrixXd reduced = t.transformation.transpose() * f;
  return scatter_rows(reduced, t.independent_dofs, static_cast<int>(f.rows()));
}

}  // namespace limber::modal
