// minimum_norm_solve against closed forms: exactly and nearly dependent rows.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "core/minimum_norm.h"

namespace limber {
namespace {

TEST(MinimumNormSolve, DependentRowsGiveTheMinimumNormSolution) {
  // x1 + x2 = 2 twice over: the solutions form a line, the shortest is (1, 1).
  const Eigen::MatrixXd A = (Eigen::MatrixXd(2, 2) << 1, 1, 2, 2).finished();
  const Eigen::VectorXd b = (Eigen::VectorXd(2) << 2, 4).finished();
  const Eigen::VectorXd x = minimum_norm_solve(A, b, 1e-6);
  EXPECT_NEAR(x(0), 1.0, 1e-14);
  EXPECT_NEAR(x(1), 1.0, 1e-14);
}

TEST(MinimumNormSolve, RowsDependentUpToRoundingCountAsDependent) {
  // Rows equal up to 1e-13 (like joint equations through a flexible body's mode shapes):
  // solved as independent, x2 = (b2 − b1) / 1e-13 = 1000 amplifies the 1e-10 mismatch;
  // below the relative threshold (1e-6) the system has rank 1 and x is the least-squares (1, 0)
  // up to the mismatch.
  const Eigen::MatrixXd A = (Eigen::MatrixXd(2, 2) << 1, 0, 1, 1e-13).finished();
  const Eigen::VectorXd b = (Eigen::VectorXd(2) << 1, 1 + 1e-10).finished();
  const Eigen::VectorXd x = minimum_norm_solve(A, b, 1e-6);
  EXPECT_NEAR(x(0), 1.0, 1e-9);
  EXPECT_LT(std::abs(x(1)), 1e-9);
}

TEST(MinimumNormSolve, OverdeterminedGivesLeastSquaresAndEmptyGivesZero) {
  // Fit of x to 1, 2, 3: the mean.
  const Eigen::MatrixXd A = Eigen::MatrixXd::Ones(3, 1);
  const Eigen::VectorXd b = (Eigen::VectorXd(3) << 1, 2, 3).finished();
  EXPECT_NEAR(minimum_norm_solve(A, b, 1e-6)(0), 2.0, 1e-14);
  // No equations: the shortest x is zero.
  const Eigen::VectorXd x = minimum_norm_solve(Eigen::MatrixXd(0, 4), Eigen::VectorXd(0), 1e-6);
  ASSERT_EQ(x.size(), 4);
  EXPECT_EQ(x.lpNorm<Eigen::Infinity>(), 0.0);
}

}  // namespace
}  // namespace limber
