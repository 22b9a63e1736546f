// Sparse global stiffness and mass matrices of a component (Eigen sparse, column-major).
#pragma once

#include <vector>

#include <Eigen/SparseCore>

#include "fe/fe_model.h"

namespace limber::fe {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct StructuralMatrices {
  SparseMatrix stiffness;  // K, dof_count x dof_count, symmetric (both triangles stored)
  SparseMatrix mass;       // M, consistent, same pattern class
};

// Assembles K and M over all elements and point masses; fixed DOFs are NOT removed here.
StructuralMatrices assemble(const FeModel& model);

// Indices of the DOFs not held by FeModel::fixed_dofs, ascending.
std::vector<int> free_dofs(const FeModel& model);

// The submatrix A(free, free).
SparseMatrix restrict_to(const SparseMatrix& matrix, const std::vector<int>& dofs);

}  // namespace limber::fe
