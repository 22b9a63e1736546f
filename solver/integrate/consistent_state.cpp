#include "integrate/consistent_state.h"

#include <fmt/format.h>

#include <Eigen/Dense>

#include "core/minimum_norm.h"
#include "integrate/singular_test.h"

namespace limber::integrate {
namespace {

constexpr int kMaxProjectionIterations = 25;
constexpr double kProjectionTolerance = 1e-12;
// Relative singular value below which a projection direction counts as dependent (the
// redundancy analysis' threshold, multibody/redundancy.h).
constexpr double kRankThreshold = 1e-6;

Status failure(StatusCode code, double t, const std::string& why) {
  return {code, t, fmt::format("at t = {:.6g} s: {}", t, why)};
}

}  // namespace

Status project_initial_state(MechanicalSystem& system, double t, Eigen::VectorXd& q,
                             Eigen::VectorXd& v) {
  const int nq = system.nq();
  const int nv = system.nv();
  const int nc = system.nc();
  const int nh = system.nh();
  Eigen::VectorXd g(nc), h(nh), r(nc + nh), g_t(nc);
  Eigen::MatrixXd g_q(nc, nq), h_q(nh, nq), A(nc + nh, nq);

  // Positions: Gauss–Newton with minimum-norm steps on [g; h] = 0.
  bool converged = nc + nh == 0;
  for (int iteration = 0; !converged && iteration < kMaxProjectionIterations; ++iteration) {
    system.constraints(t, q, g);
    system.constraint_jacobian_q(t, q, g_q);
    system.coordinate_invariants(q, h, h_q);
    r << g, h;
    A << g_q, h_q;
    if (!r.allFinite() || !A.allFinite()) {
      return failure(StatusCode::kNaN, t, "the constraints are not finite at the initial state");
    }
    const Eigen::VectorXd dq = minimum_norm_solve(A, r, kRankThreshold);
    q -= dq;
    converged = dq.lpNorm<Eigen::Infinity>() <= kProjectionTolerance * (1.0 + q.lpNorm<Eigen::Infinity>());
  }
  if (!converged) {
    system.constraints(t, q, g);
    return failure(StatusCode::kConvergenceFailures, t,
                   fmt::format("the initial positions do not converge onto the constraints "
                               "in {} iterations (|g| = {:.3g})",
                               kMaxProjectionIterations, g.lpNorm<Eigen::Infinity>()));
  }
  if (nc == 0) return Status::success(t);

  // Velocities: M-orthogonal projection onto G v + g_t = 0.
  Eigen::MatrixXd M(nv, nv), G(nc, nv);
  system.mass_matrix(t, q, M);
  system.constraint_jacobian_v(t, q, G);
  system.constraint_time_derivative(t, q, g_t);
  const Eigen::LLT<Eigen::MatrixXd> mass(M);
  if (mass.info() != Eigen::Success) {
    return failure(StatusCode::kSingularJacobian, t, "the mass matrix is not positive definite");
  }
  const Eigen::MatrixXd Minv_Gt = mass.solve(G.transpose());
  const Eigen::MatrixXd S = G * Minv_Gt;
  const Eigen::PartialPivLU<Eigen::MatrixXd> schur(S);
  if (is_singular(S, schur)) {
    return failure(StatusCode::kSingularJacobian, t,
                   "G M⁻¹ Gᵀ is singular: the constraint equations are dependent");
  }
  v -= Minv_Gt * schur.solve(G * v + g_t);
  if (!v.allFinite()) {
    return failure(StatusCode::kNaN, t, "the projected initial velocities are not finite");
  }
  return Status::success(t);
}

Status solve_accelerations(MechanicalSystem& system, double t, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v, Eigen::VectorXd& vdot,
                           Eigen::VectorXd& lambda) {
  const int nv = system.nv();
  const int nc = system.nc();
  Eigen::MatrixXd M(nv, nv), G(nc, nv);
  Eigen::VectorXd Q(nv), gamma(nc);
  system.mass_matrix(t, q, M);
  system.generalized_forces(t, q, v, Q);
  system.constraint_jacobian_v(t, q, G);
  system.acceleration_rhs(t, q, v, gamma);

  // Saddle-point system [M Gᵀ; G 0] [v̇; λ] = [Q; γ].
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nv + nc, nv + nc);
  K.topLeftCorner(nv, nv) = M;
  K.topRightCorner(nv, nc) = G.transpose();
  K.bottomLeftCorner(nc, nv) = G;
  Eigen::VectorXd rhs(nv + nc);
  rhs << Q, gamma;
  if (!K.allFinite() || !rhs.allFinite()) {
    return failure(StatusCode::kNaN, t, "the mass matrix, forces or constraints are not finite");
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(K);
  if (is_singular(K, lu)) {
    return failure(StatusCode::kSingularJacobian, t,
                   "[M Gᵀ; G 0] is singular: dependent constraints or a singular mass matrix");
  }
  const Eigen::VectorXd x = lu.solve(rhs);
  vdot = x.head(nv);
  lambda = x.tail(nc);
  return Status::success(t);
}

}  // namespace limber::integrate
