// ARPACK shift-invert eigen-solver against closed forms (spring-mass chains) and a dense
// solver, plus its failure statuses.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "modal/sparse_eigensolver.h"
#include "modal_test_support.h"

namespace limber::modal {
namespace {

using testing::spring_chain;

// Mass-normalisation of every returned vector.
void expect_mass_normalised(const Eigen::SparseMatrix<double>& m, const Eigen::MatrixXd& v) {
  for (Eigen::Index j = 0; j < v.cols(); ++j) {
    // phi^T M phi is rescaled to 1 explicitly: only round-off remains.
    EXPECT_NEAR(v.col(j).dot(m * v.col(j)), 1.0, 1e-13);
  }
}

TEST(SparseEigensolver, GroundedChainMatchesClosedForm) {
  // Fixed-free chain of n unit masses and unit springs:
  //   lambda_j = 4 sin^2((2j - 1) pi / (2 (2n + 1))), j = 1..n.
  const int n = 60;
  const auto chain = spring_chain(std::vector<double>(n, 1.0), std::vector<double>(n, 1.0), true);
  const EigenSolution solution = solve_lowest_eigenpairs(chain.stiffness, chain.mass, 8);
  ASSERT_EQ(solution.status, ModalStatus::kOk) << solution.message;
  ASSERT_EQ(solution.eigenvalues.size(), 8);
  for (int j = 1; j <= 8; ++j) {
    const double exact = 4.0 * std::pow(std::sin((2 * j - 1) * std::numbers::pi / (2.0 * (2 * n + 1))), 2);
    // Condition lambda_max / lambda_1 ~ 2e4 and machine-precision ARPACK tolerance: the
    // eigenvalues are good to ~1e-12; 1e-10 leaves a margin of 100.
    EXPECT_NEAR(solution.eigenvalues[j - 1] / exact, 1.0, 1e-10) << "mode " << j;
  }
  expect_mass_normalised(chain.mass, solution.vectors);
  // Backward stable: a few machine epsilons (2.2e-16); 1e-14 allows some growth with n.
  EXPECT_LT(solution.max_backward_error, 1e-14);
}

TEST(SparseEigensolver, FreeChainFindsTheRigidModeThroughANegativeShift) {
  // Free-free chain: lambda_j = 4 sin^2(j pi / (2n)), j = 0..n-1, lambda_0 = 0 (rigid).
  const int n = 60;
  const auto chain = spring_chain(std::vector<double>(n - 1, 1.0), std::vector<double>(n, 1.0), false);
  const EigenSolution solution = solve_lowest_eigenpairs(chain.stiffness, chain.mass, 6);
  ASSERT_EQ(solution.status, ModalStatus::kOk) << solution.message;
  EXPECT_LT(solution.shift, 0.0);
  // Rigid mode: zero up to round-off of K (entries 1, lambda_max = 4).
  EXPECT_LT(std::abs(solution.eigenvalues[0]), 1e-12);
  // Its shape is the uniform translation 1/sqrt(n) (sign free).
  EXPECT_NEAR(std::abs(solution.vectors.col(0).sum()), std::sqrt(static_cast<double>(n)), 1e-10);
  for (int j = 1; j < 6; ++j) {
    const double exact = 4.0 * std::pow(std::sin(j * std::numbers::pi / (2.0 * n)), 2);
    // As above: condition ~ 1.5e3, 1e-10 is a wide margin over round-off.
    EXPECT_NEAR(solution.eigenvalues[j] / exact, 1.0, 1e-10) << "mode " << j;
  }
  expect_mass_normalised(chain.mass, solution.vectors);
}

TEST(SparseEigensolver, ArpackMatchesDenseSolverOnIrregularChain) {
  // 200 masses and springs drawn in [0.5, 2]: no closed form, dense solver as reference.
  const int n = 200;
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> draw(0.5, 2.0);
  std::vector<double> springs(n);
  std::vector<double> masses(n);
  for (double& k : springs) k = draw(generator);
  for (double& m : masses) m = draw(generator);
  const auto chain = spring_chain(springs, masses, true);
  const EigenSolution solution = solve_lowest_eigenpairs(chain.stiffness, chain.mass, 12);
  ASSERT_EQ(solution.status, ModalStatus::kOk) << solution.message;
  const Eigen::VectorXd dense = testing::dense_eigenvalues(chain.stiffness, chain.mass);
  for (int j = 0; j < 12; ++j) {
    // Both solvers are backward stable; condition lambda_max / lambda_1 ~ 1e5 bounds the
    // relative difference by ~1e-11.
    EXPECT_NEAR(solution.eigenvalues[j] / dense[j], 1.0, 1e-10) << "mode " << j;
  }
}

TEST(SparseEigensolver, ArpackMatchesDenseSolverOnClampedBeam) {
  // Clamped steel rod, 30 elements (174 free DOFs): bending, axial and torsion mixed.
  const fe::FeModel model = testing::rod_model(30, true, {0});
  const fe::StructuralMatrices matrices = fe::assemble(model);
  const std::vector<int> dofs = fe::free_dofs(model);
  const auto k = fe::restrict_to(matrices.stiffness, dofs);
  const auto m = fe::restrict_to(matrices.mass, dofs);
  const EigenSolution solution = solve_lowest_eigenpairs(k, m, 10);
  ASSERT_EQ(solution.status, ModalStatus::kOk) << solution.message;
  const Eigen::VectorXd dense = testing::dense_eigenvalues(k, m);
  const double lambda_max = dense[dense.size() - 1];
  for (int j = 0; j < 10; ++j) {
    // Both solvers are backward stable: each eigenvalue is exact for matrices perturbed by
    // ~eps ||K||, so they may differ by ~eps lambda_max / lambda_j relative (1e-8 for the
    // first bending mode: lambda_max / lambda_1 ~ 1e8 with the axial DOFs). Bound: 100 x that.
    const double tolerance = 100.0 * 2.2e-16 * lambda_max / dense[j];
    EXPECT_NEAR(solution.eigenvalues[j] / dense[j], 1.0, tolerance) << "mode " << j;
  }
  EXPECT_LT(solution.max_backward_error, 1e-14);
}

TEST(SparseEigensolver, ShiftAboveAnEigenvalueReportsSingularFactorisation) {
  // sigma = 1 lies inside the spectrum (0, 4): K - sigma M is indefinite, LLT must fail.
  const int n = 60;
  const auto chain = spring_chain(std::vector<double>(n, 1.0), std::vector<double>(n, 1.0), true);
  EigenSolverOptions options;
  options.shift = 1.0;
  const EigenSolution solution = solve_lowest_eigenpairs(chain.stiffness, chain.mass, 4, options);
  EXPECT_EQ(solution.status, ModalStatus::kSingular);
  EXPECT_NE(solution.message.find("not positive definite"), std::string::npos);
  EXPECT_EQ(solution.eigenvalues.size(), 0);
}

TEST(SparseEigensolver, TooFewRestartsReportsNotConverged) {
  // A long chain with a tiny Lanczos basis cannot converge in one restart.
  const int n = 2000;
  const auto chain = spring_chain(std::vector<double>(n, 1.0), std::vector<double>(n, 1.0), true);
  EigenSolverOptions options;
  options.max_iterations = 1;
  options.basis_size = 12;
  options.shift = -1.0;
  const EigenSolution solution = solve_lowest_eigenpairs(chain.stiffness, chain.mass, 10, options);
  EXPECT_EQ(solution.status, ModalStatus::kNotConverged);
  EXPECT_EQ(solution.arpack_info, 1);
  EXPECT_NE(solution.message.find("info = 1"), std::string::npos) << solution.message;
}

}  // namespace
}  // namespace limber::modal
