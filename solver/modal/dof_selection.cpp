#include "modal/dof_selection.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/error.h"

namespace limber::modal {

SparseMatrix submatrix(const SparseMatrix& a, const std::vector<int>& rows,
                       const std::vector<int>& cols) {
  // Map each global row to its position in `rows` (-1 when not selected).
  std::vector<int> row_position(static_cast<std::size_t>(a.rows()), -1);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    LIMBER_DEMAND(rows[i] >= 0 && rows[i] < a.rows());
    row_position[static_cast<std::size_t>(rows[i])] = static_cast<int>(i);
  }
  // Copy the selected columns entry by entry (column-major, rows stay sorted).
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t j = 0; j < cols.size(); ++j) {
    LIMBER_DEMAND(cols[j] >= 0 && cols[j] < a.cols());
    for (SparseMatrix::InnerIterator it(a, cols[j]); it; ++it) {
      const int i = row_position[static_cast<std::size_t>(it.row())];
      if (i >= 0) entries.emplace_back(i, static_cast<int>(j), it.value());
    }
  }
  SparseMatrix result(static_cast<Eigen::Index>(rows.size()),
                      static_cast<Eigen::Index>(cols.size()));
  result.setFromTriplets(entries.begin(), entries.end());
  return result;
}

void multiply_submatrix(const SparseMatrix& a, const std::vector<int>& dofs,
                        const std::vector<int>& positions, const double* x, double* y) {
  const std::size_t n = dofs.size();
  std::fill(y, y + n, 0.0);
  // Column by column: y += A(:, dofs[j]) x_j over the selected rows.
  for (std::size_t j = 0; j < n; ++j) {
    const double xj = x[j];
    for (SparseMatrix::InnerIterator it(a, dofs[j]); it; ++it) {
      const int i = positions[static_cast<std::size_t>(it.row())];
      if (i >= 0) y[i] += it.value() * xj;
    }
  }
}

double submatrix_norm_1(const SparseMatrix& a, const std::vector<int>& dofs,
                        const std::vector<int>& positions) {
  double norm = 0.0;
  for (int column : dofs) {
    double sum = 0.0;
    for (SparseMatrix::InnerIterator it(a, column); it; ++it) {
      if (positions[static_cast<std::size_t>(it.row())] >= 0) sum += std::abs(it.value());
    }
    norm = std::max(norm, sum);
  }
  return norm;
}

std::vector<int> dof_positions(const std::vector<int>& dofs, int n) {
  std::vector<int> positions(static_cast<std::size_t>(n), -1);
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    LIMBER_DEMAND(dofs[i] >= 0 && dofs[i] < n && (i == 0 || dofs[i - 1] < dofs[i]));
    positions[static_cast<std::size_t>(dofs[i])] = static_cast<int>(i);
  }
  return positions;
}

std::vector<int> set_difference(const std::vector<int>& all, const std::vector<int>& removed) {
  std::vector<int> result;
  std::set_difference(all.begin(), all.end(), removed.begin(), removed.end(),
                      std::back_inserter(result));
  return result;
}

Eigen::MatrixXd gather_rows(const Eigen::MatrixXd& x, const std::vector<int>& dofs) {
  Eigen::MatrixXd result(static_cast<Eigen::Index>(dofs.size()), x.cols());
  // No columns, no rows to copy (a row of an empty matrix is a null pointer plus an offset).
  if (x.cols() == 0) return result;
  for (std::size_t i = 0; i < dofs.size(); ++i) result.row(static_cast<Eigen::Index>(i)) = x.row(dofs[i]);
  return result;
}

Eigen::MatrixXd scatter_rows(const Eigen::MatrixXd& x_sub, const std::vector<int>& dofs, int n) {
  LIMBER_DEMAND(x_sub.rows() == static_cast<Eigen::Index>(dofs.size()));
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(n, x_sub.cols());
  // No columns (e.g. no rigid-body mode found): nothing to scatter.
  if (x_sub.cols() == 0) return result;
  for (std::size_t i = 0; i < dofs.size(); ++i) result.row(dofs[i]) = x_sub.row(static_cast<Eigen::Index>(i));
  return result;
}

}  // namespace limber::modal
