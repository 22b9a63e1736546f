#include "integrate/ggl_equations.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

namespace limber::integrate {

namespace {

// block += scale · A, A sparse (its nonzeros only).
void add_sparse(double scale, const Eigen::SparseMatrix<double>& A, Eigen::Block<Eigen::Map<Eigen::MatrixXd>> block) {
  for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) block(it.row(), it.col()) += scale * it.value();
  }
}

}  // namespace

GglLayout GglLayout::of(const MechanicalSystem& system, int nz) {
  GglLayout l;
  l.nq = system.nq();
  l.nv = system.nv();
  l.nc = system.nc();
  l.nh = system.nh();
  l.nz = nz;
  l.iv = l.nq;
  l.ilambda = l.iv + l.nv;
  l.imu = l.ilambda + l.nc;
  l.iz = l.imu + l.nc + l.nh;
  l.n = l.iz + l.nz;
  return l;
}

GglEquations::GglEquations(MechanicalSystem& system, const Quadrature& quadrature)
    : system_(system), quadrature_(quadrature), layout_(GglLayout::of(system, quadrature.size)),
      sparse_(system.sparse()) {
  h_.resize(layout_.nh);
  f_.resize(layout_.nz);
  N_.resize(layout_.nq, layout_.nv);
  h_q_.resize(layout_.nh, layout_.nq);
  D_.resize(layout_.nq, layout_.nq);
  // Systems without a diagonal stiffness and damping get a structured matrix without them.
  if (!system.diagonal_stiffness_damping(stiffness_, damping_)) {
    stiffness_.setZero(layout_.nv);
    damping_.setZero(layout_.nv);
  }
}

void GglEquations::unpack(const double* y, const double* yp) {
  const GglLayout& l = layout_;
  q_ = Eigen::Map<const Eigen::VectorXd>(y, l.nq);
  v_ = Eigen::Map<const Eigen::VectorXd>(y + l.iv, l.nv);
  lambda_ = Eigen::Map<const Eigen::VectorXd>(y + l.ilambda, l.nc);
  mu_g_ = Eigen::Map<const Eigen::VectorXd>(y + l.imu, l.nc);
  mu_h_ = Eigen::Map<const Eigen::VectorXd>(y + l.imu + l.nc, l.nh);
  vdot_ = Eigen::Map<const Eigen::VectorXd>(yp + l.iv, l.nv);
}

bool GglEquations::residual(double t, const double* y, const double* yp, double* r_data) {
  const GglLayout& l = layout_;
  unpack(y, yp);
  Eigen::Map<Eigen::VectorXd> r(r_data, l.n);
  Eigen::Map<const Eigen::VectorXd> qdot(yp, l.nq);
  system_.kinematic_matrix(q_, N_);
  system_.evaluate(t, q_, v_, true, eval_);
  system_.coordinate_invariants(q_, h_, h_q_);

  // Kinematics with the GGL stabilising term, dynamics, velocity and position constraints.
  r.head(l.nq).noalias() = qdot - N_ * v_;
  r.head(l.nq).noalias() += eval_.g_q.transpose() * mu_g_;
  r.head(l.nq).noalias() += h_q_.transpose() * mu_h_;
  if (sparse_) {
    r.segment(l.iv, l.nv).noalias() = eval_.M_sparse * vdot_;
  } else {
    r.segment(l.iv, l.nv).noalias() = eval_.M * vdot_;
  }
  r.segment(l.iv, l.nv) -= eval_.Q;
  r.segment(l.iv, l.nv).noalias() += eval_.G.transpose() * lambda_;
  r.segment(l.ilambda, l.nc).noalias() = eval_.G * v_ + eval_.g_t;
  r.segment(l.imu, l.nc) = eval_.g;
  r.segment(l.imu + l.nc, l.nh) = h_;
  // Quadratures.
  if (l.nz > 0) {
    quadrature_.integrand(t, q_, v_, vdot_, lambda_, f_);
    r.segment(l.iz, l.nz) = Eigen::Map<const Eigen::VectorXd>(yp + l.iz, l.nz) - f_;
  }
  return r.allFinite();
}

bool GglEquations::newton_matrix(double t, double c_j, const double* y, const double* yp, double* J_data,
                                 bool refresh_difference) {
  const GglLayout& l = layout_;
  unpack(y, yp);
  Eigen::Map<Eigen::MatrixXd> J(J_data, l.n, l.n);
  system_.kinematic_matrix(q_, N_);
  system_.evaluate(t, q_, v_, true, eval_);
  system_.coordinate_invariants(q_, h_, h_q_);
  // D = ∂(N v)/∂q by forward differences of N (no model evaluation).
  const double root_epsilon = std::sqrt(std::numeric_limits<double>::epsilon());
  qdot_.noalias() = N_ * v_;
  q_perturbed_ = q_;
  for (int j = 0; j < l.nq; ++j) {
    const double increment = root_epsilon * std::max(1.0, std::abs(q_(j)));
    q_perturbed_(j) = q_(j) + increment;
    system_.kinematic_matrix(q_perturbed_, N_perturbed_);
    D_.col(j).noalias() = N_perturbed_ * v_;
    D_.col(j) = (D_.col(j) - qdot_) / increment;
    q_perturbed_(j) = q_(j);
  }
  // ∂g/∂q a step ε along the motion (t + ε, q + ε q̇).
  const double epsilon = root_epsilon * std::max(1.0, q_.lpNorm<Eigen::Infinity>()) /
                         std::max(1.0, qdot_.lpNorm<Eigen::Infinity>());
  q_perturbed_.noalias() = q_ + epsilon * qdot_;
  system_.constraint_jacobian_q(t + epsilon, q_perturbed_, g_q_along_);
  N_pinv_.noalias() = (N_.transpose() * N_).ldlt().solve(N_.transpose());
  J.setZero();
  // Kinematic rows.
  J.topLeftCorner(l.nq, l.nq) = -D_;
  J.topLeftCorner(l.nq, l.nq).diagonal().array() += c_j;
  J.block(0, l.iv, l.nq, l.nv) = -N_;
  J.block(0, l.imu, l.nq, l.nc) = eval_.g_q.transpose();
  J.block(0, l.imu + l.nc, l.nq, l.nh) = h_q_.transpose();
  // Dynamics rows.
  J.block(l.iv, 0, l.nv, l.nq).noalias() = stiffness_.asDiagonal() * N_pinv_;
  if (sparse_) {
    add_sparse(c_j, eval_.M_sparse, J.block(l.iv, l.iv, l.nv, l.nv));
  } else {
    J.block(l.iv, l.iv, l.nv, l.nv) = c_j * eval_.M;
  }
  J.block(l.iv, l.iv, l.nv, l.nv).diagonal() += damping_;
  // The internal forces that couple velocities (a nonlinear body's beams), at (t, q).
  if (system_.coupled_stiffness(t, q_, coupled_)) J.block(l.iv, 0, l.nv, l.nq).noalias() += coupled_ * N_pinv_;
  if (system_.coupled_damping(t, q_, coupled_)) add_sparse(1.0, coupled_, J.block(l.iv, l.iv, l.nv, l.nv));
  // What the structured blocks miss (force elements, constraint forces), kept from the last
  // difference; c_j M is exact and stays out of it.
  if (!sparse_ && refresh_difference) take_difference(t, c_j, J);
  if (!sparse_ && has_difference_) {
    J.block(l.iv, 0, l.nv, l.nq) += difference_q_;
    J.block(l.iv, l.iv, l.nv, l.nv) += difference_v_;
  }
  J.block(l.iv, l.ilambda, l.nv, l.nc) = eval_.G.transpose();
  // Velocity constraints.
  J.block(l.ilambda, 0, l.nc, l.nq) = (g_q_along_ - eval_.g_q) / epsilon;
  J.block(l.ilambda, 0, l.nc, l.nq).noalias() += eval_.g_q * D_;
  J.block(l.ilambda, l.iv, l.nc, l.nv) = eval_.G;
  // Position constraints, invariants, integrals.
  J.block(l.imu, 0, l.nc, l.nq) = eval_.g_q;
  J.block(l.imu + l.nc, 0, l.nh, l.nq) = h_q_;
  J.block(l.iz, l.iz, l.nz, l.nz).diagonal().setConstant(c_j);
  return J.allFinite();
}

void GglEquations::dynamics_rows(const SystemEvaluation& e, const Eigen::VectorXd& Q, Eigen::VectorXd& out) const {
  out.noalias() = e.M * vdot_;
  out -= Q;
  out.noalias() += e.G.transpose() * lambda_;
}

void GglEquations::take_difference(double t, double c_j, const Eigen::Map<Eigen::MatrixXd>& J) {
  const GglLayout& l = layout_;
  const double root_epsilon = std::sqrt(std::numeric_limits<double>::epsilon());
  dynamics_rows(eval_, eval_.Q, dynamics_);
  // Columns for q: a full evaluation each (M, Q and G move with q).
  difference_q_.resize(l.nv, l.nq);
  q_perturbed_ = q_;
  for (int j = 0; j < l.nq; ++j) {
    const double increment = root_epsilon * std::max(1.0, std::abs(q_(j)));
    q_perturbed_(j) = q_(j) + increment;
    system_.evaluate(t, q_perturbed_, v_, false, probe_);
    dynamics_rows(probe_, probe_.Q, dynamics_perturbed_);
    difference_q_.col(j) = (dynamics_perturbed_ - dynamics_) / increment;
    q_perturbed_(j) = q_(j);
  }
  // Columns for v: only Q moves.
  difference_v_.resize(l.nv, l.nv);
  v_perturbed_ = v_;
  for (int j = 0; j < l.nv; ++j) {
    const double increment = root_epsilon * std::max(1.0, std::abs(v_(j)));
    v_perturbed_(j) = v_(j) + increment;
    system_.generalized_forces(t, q_, v_perturbed_, Q_perturbed_);
    difference_v_.col(j) = (eval_.Q - Q_perturbed_) / increment;
    v_perturbed_(j) = v_(j);
  }
  difference_evaluations_ += l.nq + l.nv;
  // Keep what the structured blocks (already in J) do not hold.
  difference_q_ -= J.block(l.iv, 0, l.nv, l.nq);
  difference_v_ -= J.block(l.iv, l.iv, l.nv, l.nv);
  difference_v_.noalias() += c_j * eval_.M;
  has_difference_ = difference_q_.allFinite() && difference_v_.allFinite();
}

}  // namespace limber::integrate
