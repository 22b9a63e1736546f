// Sparse global stiffness and mass matrices of a component (Eigen sparse, column-major).
//
// Global DOF of (node n, Dof d) is FeModel::dof_index(n, d) = 6 n + d. Beam matrices come
// from beam_element_matrices (beam_element.h), shell matrices from shell_element_matrices
// (shell_element.h), point masses add m to the translational and their inertia tensor
// to the rotational diagonal block of their node; DOF matrices (FeModel::dof_stiffnesses,
// dof_masses) add their entries to K or M. Multipoint constraints are not applied here
// (fe/multipoint_constraints.h).
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "fe/fe_model.h"

namespace limber::fe {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct StructuralMatrices {
  SparseMatrix stiffness;  // K, dof_count x dof_count, symmetric (both triangles stored)
  SparseMatrix mass;       // M, consistent, same sparsity pattern as K
};

// Assembles K and M over all elements and point masses; fixed DOFs are NOT removed here.
// The pattern is built once from node adjacency (full 6x6 blocks for every pair of nodes
// sharing an element, sorted row indices, compressed) and element matrices are added in
// place: memory is the final matrices only, no triplet list.
// Throws InputError (naming the element) when a shell is too warped for the flat element.
StructuralMatrices assemble(const FeModel& model);

// Indices of the DOFs not held by FeModel::fixed_dofs, ascending.
std::vector<int> free_dofs(const FeModel& model);

// The submatrix A(dofs, dofs), rows and columns in the order of `dofs`.
// Precondition (LIMBER_DEMAND): indices are distinct and within the matrix.
SparseMatrix restrict_to(const SparseMatrix& matrix, const std::vector<int>& dofs);

}  // namespace limber::fe
