#include "core/minimum_norm.h"

#include <Eigen/SVD>

#include "core/error.h"

namespace limber {

Eigen::VectorXd minimum_norm_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                   double relative_threshold) {
  LIMBER_DEMAND(b.size() == A.rows());
  if (A.size() == 0) return Eigen::VectorXd::Zero(A.cols());
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(relative_threshold);
  return svd.solve(b);
}

}  // namespace limber
