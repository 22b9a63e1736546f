// Index bookkeeping between the full FE DOF vector (n = 6 x nodes) and subsets of it
// (free DOFs, held DOFs, the "v" and "c" sets of constraint modes).
// DOF lists are ascending, unique global indices in [0, n).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace limber::modal {

using SparseMatrix = Eigen::SparseMatrix<double>;

// A(rows, cols) as a sparse matrix of size rows.size() x cols.size().
// Precondition: rows and cols ascending, in range.
SparseMatrix submatrix(const SparseMatrix& a, const std::vector<int>& rows,
                       const std::vector<int>& cols);

// y = A(dofs, dofs) x without forming the submatrix: x, y of size dofs.size(); `positions`
// from dof_positions(dofs, A.rows()). Allocates nothing (used inside Lanczos iterations).
void multiply_submatrix(const SparseMatrix& a, const std::vector<int>& dofs,
                        const std::vector<int>& positions, const double* x, double* y);

// Largest absolute column sum of A(dofs, dofs) (the 1-norm), without forming it.
double submatrix_norm_1(const SparseMatrix& a, const std::vector<int>& dofs,
                        const std::vector<int>& positions);

// Position of each of the n global DOFs in `dofs`, or -1 when it is not there.
std::vector<int> dof_positions(const std::vector<int>& dofs, int n);

// The entries of `all` that are not in `removed` (both ascending).
std::vector<int> set_difference(const std::vector<int>& all, const std::vector<int>& removed);

// Rows `dofs` of x (x has n rows; result has dofs.size() rows).
Eigen::MatrixXd gather_rows(const Eigen::MatrixXd& x, const std::vector<int>& dofs);

// An n-row matrix that is zero except rows `dofs`, which take the rows of x_sub.
Eigen::MatrixXd scatter_rows(const Eigen::MatrixXd& x_sub, const std::vector<int>& dofs, int n);

}  // namespace limber::modal
