// The structured Newton matrix of IDA's GGL equations (integrate/ggl_equations.h) against the
// closed-form derivatives of two small systems: its kept difference of the dynamics rows must
// hold a coupling spring the diagonal stiffness leaves out, and the constraint force's and the
// damper's derivatives, and keep them until refreshed.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include "integrate/ggl_equations.h"
#include "test_systems.h"

namespace limber::integrate {
namespace {

using testing::CartesianPendulum;
using testing::CoupledOscillators;

// Column-major J (n x n) from GglEquations::newton_matrix at (t, y, y').
Eigen::MatrixXd newton_matrix(GglEquations& equations, double c_j, const Eigen::VectorXd& y,
                              const Eigen::VectorXd& yp, bool refresh) {
  const int n = equations.layout().n;
  Eigen::MatrixXd J(n, n);
  EXPECT_TRUE(equations.newton_matrix(0.0, c_j, y.data(), yp.data(), J.data(), refresh));
  return J;
}

// Forward differences of forces linear in q and v are exact but for round-off: ε |Q| / δ with
// δ = √ε, i.e. ~1e-8 of the forces' scale (here k |q| ~ 1e3).
constexpr double kDifferenceTolerance = 1e-5;

TEST(GglEquations, KeptDifferenceHoldsTheCouplingSpringUntilRefreshed) {
  const double k = 1e3, k_c = 4e3, c_j = 1e4;
  CoupledOscillators system(k, k_c);
  const Quadrature none;
  GglEquations equations(system, none);
  Eigen::VectorXd y(4), yp = Eigen::VectorXd::Zero(4);
  y << 0.3, -0.2, 1.0, 0.5;  // q, v
  // K = [[k + k_c, −k_c], [−k_c, k + k_c]] (−∂Q/∂q), M = I.
  Eigen::Matrix2d K;
  K << k + k_c, -k_c, -k_c, k + k_c;

  // Without a difference: the diagonal k only (the coupling is what a structured matrix misses).
  const Eigen::MatrixXd plain = newton_matrix(equations, c_j, y, yp, false);
  EXPECT_NEAR((plain.block(2, 0, 2, 2) - k * Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-12);
  // Refreshed: the whole K; the v rows' c_j M and the q rows untouched.
  const Eigen::MatrixXd fresh = newton_matrix(equations, c_j, y, yp, true);
  EXPECT_NEAR((fresh.block(2, 0, 2, 2) - K).norm(), 0.0, kDifferenceTolerance * K.norm());
  EXPECT_NEAR((fresh.block(2, 2, 2, 2) - c_j * Eigen::Matrix2d::Identity()).norm(), 0.0,
              kDifferenceTolerance * c_j);
  EXPECT_NEAR((fresh.topRows(2) - plain.topRows(2)).norm(), 0.0, 1e-12);
  // Kept at another state and c_j without a refresh (the springs are linear: still exact).
  y << -0.1, 0.4, -2.0, 0.0;
  const Eigen::MatrixXd kept = newton_matrix(equations, 2.0 * c_j, y, yp, false);
  EXPECT_NEAR((kept.block(2, 0, 2, 2) - K).norm(), 0.0, kDifferenceTolerance * K.norm());
  EXPECT_NEAR((kept.block(2, 2, 2, 2) - 2.0 * c_j * Eigen::Matrix2d::Identity()).norm(), 0.0,
              kDifferenceTolerance * c_j);
  EXPECT_EQ(equations.difference_evaluations(), 4);  // nq + nv, once
}

TEST(GglEquations, KeptDifferenceHoldsTheConstraintForceAndTheDamper) {
  const double m = 2.0, L = 1.5, g0 = 9.81, c = 0.7, c_j = 1e3;
  CartesianPendulum system(m, L, g0, c);
  const Quadrature none;
  GglEquations equations(system, none);
  const GglLayout& l = equations.layout();
  ASSERT_EQ(l.n, 6);  // q (2), v (2), λ (1), μ (1)
  // On the circle at θ = 0.4 rad, moving, with λ = 30 N/m and some v'.
  const double theta = 0.4, lambda = 30.0;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(l.n), yp = Eigen::VectorXd::Zero(l.n);
  y.head(2) << L * std::sin(theta), -L * std::cos(theta);
  y.segment(l.iv, 2) << 1.2 * std::cos(theta), 1.2 * std::sin(theta);
  y(l.ilambda) = lambda;
  yp.segment(l.iv, 2) << -3.0, 1.0;
  // Dynamics rows m v' + G(q)ᵀλ − Q(v) with G = qᵀ and Q = (0, −m g0) − c v:
  // ∂/∂q = λ I (the constraint force), ∂/∂v = c_j m I + c I (the damper).
  const Eigen::MatrixXd plain = newton_matrix(equations, c_j, y, yp, false);
  EXPECT_NEAR(plain.block(l.iv, 0, 2, 2).norm(), 0.0, 1e-12);  // no stiffness offered
  EXPECT_NEAR((plain.block(l.iv, l.iv, 2, 2) - c_j * m * Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-9);
  const Eigen::MatrixXd fresh = newton_matrix(equations, c_j, y, yp, true);
  EXPECT_NEAR((fresh.block(l.iv, 0, 2, 2) - lambda * Eigen::Matrix2d::Identity()).norm(), 0.0,
              kDifferenceTolerance * lambda);
  EXPECT_NEAR((fresh.block(l.iv, l.iv, 2, 2) - (c_j * m + c) * Eigen::Matrix2d::Identity()).norm(), 0.0,
              kDifferenceTolerance * c_j * m);
  // The rest of the matrix is the structured one's.
  EXPECT_NEAR((fresh.topRows(l.iv) - plain.topRows(l.iv)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((fresh.bottomRows(l.n - l.ilambda) - plain.bottomRows(l.n - l.ilambda)).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace limber::integrate
