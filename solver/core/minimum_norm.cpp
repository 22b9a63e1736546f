#include "core/minimum_norm.h"

#include <Eigen/Eigenvalues>

#include "core/error.h"

namespace limber {

Eigen::VectorXd minimum_norm_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                   double relative_threshold) {
  LIMBER_DEMAND(b.size() == A.rows());
  LIMBER_DEMAND(relative_threshold >= 1e-7);
  if (A.size() == 0) return Eigen::VectorXd::Zero(A.cols());
  // A⁺ b = (AᵀA)⁺ Aᵀ b from the eigen-decomposition of the Gram matrix: its eigenvalues are
  // the σ², cut at (relative_threshold σ_max)². A few times cheaper than a Jacobi SVD at the
  // sizes of joint Jacobians (reactions are solved at every sample); the squared condition
  // costs accuracy only for σ near the cut, far below what the rank decision keeps.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> gram(A.transpose() * A);
  const Eigen::VectorXd& sigma2 = gram.eigenvalues();
  const double cut = relative_threshold * relative_threshold * sigma2.maxCoeff();
  const Eigen::VectorXd projected = gram.eigenvectors().transpose() * (A.transpose() * b);
  Eigen::VectorXd scaled = Eigen::VectorXd::Zero(sigma2.size());
  for (Eigen::Index k = 0; k < sigma2.size(); ++k) {
    if (sigma2(k) > cut) scaled(k) = projected(k) / sigma2(k);
  }
  return gram.eigenvectors() * scaled;
}

}  // namespace limber
