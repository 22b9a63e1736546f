// KLU's sparse LU (integrate/sparse_lu.h) against Eigen's dense LU, and generalized-α on the
// sparse path against the dense one.
#include "integrate/sparse_lu.h"

#include <cmath>

#include <gtest/gtest.h>

#include "integrate/generalized_alpha.h"
#include "integrate/simulate.h"
#include "test_systems.h"

namespace limber::integrate {
namespace {

// A saddle-point matrix shaped like generalized-α's iteration matrix of a chain of bodies:
// tridiagonal 3 x 3 blocks (mass plus neighbour coupling), two constraint rows, a zero block.
Eigen::SparseMatrix<double> chain_saddle_point(int blocks, double coupling) {
  const int n = 3 * blocks, m = n + 2;
  std::vector<Eigen::Triplet<double>> entries;
  for (int b = 0; b < blocks; ++b) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double value = (i == j ? 4.0 + 0.1 * b : 0.3 * std::sin(i + 2.0 * j + b));
        entries.emplace_back(3 * b + i, 3 * b + j, value);
        if (b + 1 < blocks) {
          entries.emplace_back(3 * b + i, 3 * (b + 1) + j, -coupling + 0.01 * i);
          entries.emplace_back(3 * (b + 1) + j, 3 * b + i, -coupling - 0.02 * j);
        }
      }
    }
  }
  // Constraints on the first and the last body, and their transposes.
  for (const auto& [row, column, value] : {std::tuple{n, 0, 1.0}, std::tuple{n, 1, -0.5},
                                           std::tuple{n + 1, n - 1, 2.0}, std::tuple{n + 1, n - 3, 0.7}}) {
    entries.emplace_back(row, column, value);
    entries.emplace_back(column, row, value);
  }
  Eigen::SparseMatrix<double> A(m, m);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

TEST(SparseLu, SolvesASaddlePointSystemAsTheDenseLuDoes) {
  // 30 blocks (92 unknowns), moderate conditioning: both solutions agree to a few hundred ε
  // relative (backward-stable LUs on a matrix of condition ~1e2; bound 1e-12 leaves margin).
  const Eigen::SparseMatrix<double> A = chain_saddle_point(30, 1.0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  SparseLu lu;
  ASSERT_TRUE(lu.factorize(A));
  EXPECT_GT(lu.rcond(), 1e-6);
  const Eigen::VectorXd x = lu.solve(b);
  const Eigen::VectorXd x_dense = Eigen::MatrixXd(A).partialPivLu().solve(b);
  EXPECT_LT((x - x_dense).norm(), 1e-12 * x_dense.norm());
  // The same pattern with other values reuses the ordering and still solves exactly.
  const Eigen::SparseMatrix<double> B = chain_saddle_point(30, 1.5);
  ASSERT_TRUE(lu.factorize(B));
  EXPECT_LT((B * lu.solve(b) - b).norm(), 1e-12 * b.norm());
}

TEST(SparseLu, AZeroColumnIsSingular) {
  // A column without entries: KLU meets a zero pivot and says so.
  Eigen::SparseMatrix<double> A = chain_saddle_point(4, 1.0);
  A.prune([](int, int column, double) { return column != 5; });
  A.makeCompressed();
  SparseLu lu;
  EXPECT_FALSE(lu.factorize(A));
}

// The heavy top as a sparse system: the same equations, M handed over as a sparse matrix, so
// that generalized-α takes its sparse path (KLU) on it.
class SparseHeavyTop final : public testing::ForwardingSystem {
 public:
  using ForwardingSystem::ForwardingSystem;
  bool sparse() const override { return true; }
  void evaluate(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, bool with_g_q,
                SystemEvaluation& out) override {
    base_.evaluate(t, q, v, with_g_q, out);
    out.M_sparse = out.M.sparseView();
    out.M.resize(0, 0);
  }
};

TEST(GeneralizedAlphaSparse, FollowsTheDensePathToTheNewtonTolerance) {
  // The heavy top (a quaternion and three constraint rows) for 0.5 s at h = 1 ms on both paths.
  // They differ only in the linear solver, so in the Newton iterates by the round-off of the
  // solves, and in where Newton stops: within its tolerance (1e-8 of ‖ξ‖, ξ ≈ 0.05 per step).
  // Over 500 steps such differences add up to at most ~500 × 5e-10 = 2.5e-7 in q; same step
  // counts and Newton iterations (within one per ten steps) say the paths behave alike.
  using testing::HeavyTop;
  HeavyTop top(2.0, Eigen::Vector3d(0.02, 0.02, 0.01), Eigen::Vector3d(0.0, 0.0, -0.1), 9.81);
  SparseHeavyTop sparse_top(top);
  InitialState start;
  start.q.resize(7);
  start.q << 0.0, 0.0, 0.0, std::cos(0.15), std::sin(0.15), 0.0, 0.0;
  start.v = Eigen::VectorXd::Zero(6);
  start.v(5) = 50.0;
  const IntegratorOptions options = IntegratorOptions::generalized_alpha(1e-3, 0.8);
  Eigen::VectorXd q_dense, q_sparse;
  const auto dense = simulate(top, options, start, {0.0, 0.5}, [&](const Sample& s) { q_dense = s.q; });
  const auto sparse = simulate(sparse_top, options, start, {0.0, 0.5}, [&](const Sample& s) { q_sparse = s.q; });
  ASSERT_TRUE(dense.status.ok()) << dense.status.message;
  ASSERT_TRUE(sparse.status.ok()) << sparse.status.message;
  EXPECT_LT((q_dense - q_sparse).lpNorm<Eigen::Infinity>(), 2.5e-7);
  EXPECT_EQ(dense.statistics.steps, sparse.statistics.steps);
  EXPECT_NEAR(dense.statistics.newton_iterations, sparse.statistics.newton_iterations, 0.1 * dense.statistics.steps);
}

}  // namespace
}  // namespace limber::integrate
