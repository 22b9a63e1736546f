#include "integrate/singular_test.h"

namespace limber::integrate {

bool is_singular(const Eigen::MatrixXd& a, const Eigen::PartialPivLU<Eigen::MatrixXd>& lu) {
  if (lu.rcond() > kSingularRcond) return false;
  // A zero row or column is singular at any scale.
  const Eigen::VectorXd row_max = a.cwiseAbs().rowwise().maxCoeff();
  if (!(row_max.minCoeff() > 0.0)) return true;
  const Eigen::MatrixXd rows_scaled = row_max.cwiseInverse().asDiagonal() * a;
  const Eigen::RowVectorXd column_max = rows_scaled.cwiseAbs().colwise().maxCoeff();
  if (!(column_max.minCoeff() > 0.0)) return true;
  const Eigen::MatrixXd scaled = rows_scaled * column_max.cwiseInverse().asDiagonal();
  return !(Eigen::PartialPivLU<Eigen::MatrixXd>(scaled).rcond() > kSingularRcond);
}

}  // namespace limber::integrate
