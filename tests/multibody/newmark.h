// A small Newmark integrator for the full FE model, M ü + K u = f(t) with constant sparse
// M, K: the reference of the reduced-versus-full cross-check. Average acceleration
// (β = ¼, γ = ½; Newmark, J. Eng. Mech. Div. ASCE 85, 1959): unconditionally stable,
// second order, no numerical damping, period error (ωh)²/12.
#pragma once

#include <functional>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "core/error.h"

namespace limber::multibody::testing {

using SparseMatrix = Eigen::SparseMatrix<double>;

// From u = u̇ = 0 at t = 0, `steps` steps of size h; on_step(t, u) after each step.
inline void newmark(const SparseMatrix& M, const SparseMatrix& K, double h, int steps,
                    const std::function<Eigen::VectorXd(double)>& force,
                    const std::function<void(double, const Eigen::VectorXd&)>& on_step) {
  constexpr double beta = 0.25, gamma = 0.5;
  const Eigen::Index n = M.rows();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n);
  // Initial acceleration from M a = f(0).
  Eigen::SimplicialLDLT<SparseMatrix> mass(M);
  LIMBER_DEMAND(mass.info() == Eigen::Success);
  Eigen::VectorXd a = mass.solve(force(0.0));
  // Effective stiffness K + M / (β h²), factorised once.
  const SparseMatrix effective = K + M / (beta * h * h);
  Eigen::SimplicialLDLT<SparseMatrix> solver(effective);
  LIMBER_DEMAND(solver.info() == Eigen::Success);
  for (int k = 1; k <= steps; ++k) {
    const double t = k * h;
    // Predictors, then u_{n+1} from the effective system, then a and v.
    const Eigen::VectorXd u_star = u + h * v + (0.5 - beta) * h * h * a;
    const Eigen::VectorXd v_star = v + (1.0 - gamma) * h * a;
    u = solver.solve(force(t) + M * u_star / (beta * h * h));
    a = (u - u_star) / (beta * h * h);
    v = v_star + gamma * h * a;
    on_step(t, u);
  }
}

}  // namespace limber::multibody::testing
