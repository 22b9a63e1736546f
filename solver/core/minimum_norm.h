// The minimum-norm least-squares solution x = A⁺ b of a possibly rank-deficient system, as
// used for redundant constraint equations (assembly steps, reactions).
#pragma once

#include <Eigen/Core>

namespace limber {

// x minimising ‖x‖ among the minimisers of ‖A x − b‖, singular values σ ≤ relative_threshold
// · σ_max taken as zero (Golub & Van Loan, Matrix Computations, §5.5.4), from the
// eigen-decomposition of AᵀA. Not Eigen 3.4's CompleteOrthogonalDecomposition: its solve
// reads uninitialised memory when A is rank deficient (valgrind on the flexible
// slider-crank's reactions), and its default threshold, near machine precision, counts rows
// that are dependent up to rounding (σ ~ 1e-12 σ_max) as independent.
// Preconditions (DEMAND): b.size() == A.rows(); relative_threshold ≥ 1e-7, since the cut is
// applied to σ², whose rounding is ~1e-16 σ_max².
Eigen::VectorXd minimum_norm_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                   double relative_threshold);

}  // namespace limber
