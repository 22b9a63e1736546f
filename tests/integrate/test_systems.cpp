#include "test_systems.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace limber::integrate::testing {

// Oscillator.
void Oscillator::kinematic_matrix(const Eigen::VectorXd&, Eigen::MatrixXd& N) const {
  N = Eigen::MatrixXd::Identity(1, 1);
}
void Oscillator::integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                                       Eigen::VectorXd& q_out) const {
  q_out = q + dv;
}
void Oscillator::coordinate_invariants(const Eigen::VectorXd&, Eigen::VectorXd& h,
                                       Eigen::MatrixXd& h_q) const {
  h.resize(0);
  h_q.resize(0, 1);
}
void Oscillator::mass_matrix(double, const Eigen::VectorXd&, Eigen::MatrixXd& M) {
  M = Eigen::MatrixXd::Constant(1, 1, m_);
}
void Oscillator::generalized_forces(double, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                                    Eigen::VectorXd& Q) {
  Q = -k_ * q;
}
void Oscillator::constraints(double, const Eigen::VectorXd&, Eigen::VectorXd& g) {
  g.resize(0);
}
void Oscillator::constraint_jacobian_q(double, const Eigen::VectorXd&,
                                       Eigen::MatrixXd& g_q) {
  g_q.resize(0, 1);
}
void Oscillator::constraint_jacobian_v(double, const Eigen::VectorXd&, Eigen::MatrixXd& G) {
  G.resize(0, 1);
}
void Oscillator::constraint_time_derivative(double, const Eigen::VectorXd&,
                                            Eigen::VectorXd& g_t) {
  g_t.resize(0);
}
void Oscillator::acceleration_rhs(double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                                  Eigen::VectorXd& gamma) {
  gamma.resize(0);
}

// Coupled oscillators.
void CoupledOscillators::kinematic_matrix(const Eigen::VectorXd&, Eigen::MatrixXd& N) const {
  N = Eigen::MatrixXd::Identity(2, 2);
}
void CoupledOscillators::integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                                               Eigen::VectorXd& q_out) const {
  q_out = q + dv;
}
void CoupledOscillators::coordinate_invariants(const Eigen::VectorXd&, Eigen::VectorXd& h,
                                               Eigen::MatrixXd& h_q) const {
  h.resize(0);
  h_q.resize(0, 2);
}
void CoupledOscillators::mass_matrix(double, const Eigen::VectorXd&, Eigen::MatrixXd& M) {
  M = Eigen::MatrixXd::Identity(2, 2);
}
void CoupledOscillators::generalized_forces(double, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                                            Eigen::VectorXd& Q) {
  Q = -k_ * q;
  Q(0) -= k_c_ * (q(0) - q(1));
  Q(1) -= k_c_ * (q(1) - q(0));
}
void CoupledOscillators::constraints(double, const Eigen::VectorXd&, Eigen::VectorXd& g) {
  g.resize(0);
}
void CoupledOscillators::constraint_jacobian_q(double, const Eigen::VectorXd&,
                                               Eigen::MatrixXd& g_q) {
  g_q.resize(0, 2);
}
void CoupledOscillators::constraint_jacobian_v(double, const Eigen::VectorXd&,
                                               Eigen::MatrixXd& G) {
  G.resize(0, 2);
}
void CoupledOscillators::constraint_time_derivative(double, const Eigen::VectorXd&,
                                                    Eigen::VectorXd& g_t) {
  g_t.resize(0);
}
void CoupledOscillators::acceleration_rhs(double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                                          Eigen::VectorXd& gamma) {
  gamma.resize(0);
}
bool CoupledOscillators::diagonal_stiffness_damping(Eigen::VectorXd& k, Eigen::VectorXd& c) const {
  k = Eigen::VectorXd::Constant(2, k_);
  c = Eigen::VectorXd::Zero(2);
  return true;
}

// Cartesian pendulum.
void CartesianPendulum::kinematic_matrix(const Eigen::VectorXd&, Eigen::MatrixXd& N) const {
  N = Eigen::MatrixXd::Identity(2, 2);
}
void CartesianPendulum::integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                                              Eigen::VectorXd& q_out) const {
  q_out = q + dv;
}
void CartesianPendulum::coordinate_invariants(const Eigen::VectorXd&, Eigen::VectorXd& h,
                                              Eigen::MatrixXd& h_q) const {
  h.resize(0);
  h_q.resize(0, 2);
}
void CartesianPendulum::mass_matrix(double, const Eigen::VectorXd&, Eigen::MatrixXd& M) {
  M = m_ * Eigen::MatrixXd::Identity(2, 2);
}
void CartesianPendulum::generalized_forces(double, const Eigen::VectorXd&,
                                           const Eigen::VectorXd& v, Eigen::VectorXd& Q) {
  Q = -c_ * v;
  Q(1) -= m_ * g0_;
}
void CartesianPendulum::constraints(double, const Eigen::VectorXd& q, Eigen::VectorXd& g) {
  g.resize(1);
  g(0) = 0.5 * (q.squaredNorm() - L_ * L_);
}
void CartesianPendulum::constraint_jacobian_q(double, const Eigen::VectorXd& q,
                                              Eigen::MatrixXd& g_q) {
  g_q = q.transpose();
}
void CartesianPendulum::constraint_jacobian_v(double, const Eigen::VectorXd& q,
                                              Eigen::MatrixXd& G) {
  G = q.transpose();
}
void CartesianPendulum::constraint_time_derivative(double, const Eigen::VectorXd&,
                                                   Eigen::VectorXd& g_t) {
  g_t = Eigen::VectorXd::Zero(1);
}
void CartesianPendulum::acceleration_rhs(double, const Eigen::VectorXd&, const Eigen::VectorXd& v,
                                         Eigen::VectorXd& gamma) {
  // d²g/dt² = |v|² + q·v̇ = 0.
  gamma = Eigen::VectorXd::Constant(1, -v.squaredNorm());
}
Eigen::VectorXd CartesianPendulum::position(double theta) const {
  return Eigen::Vector2d(L_ * std::sin(theta), -L_ * std::cos(theta));
}
Eigen::VectorXd CartesianPendulum::velocity(double theta, double theta_dot) const {
  return Eigen::Vector2d(L_ * std::cos(theta), L_ * std::sin(theta)) * theta_dot;
}
double CartesianPendulum::energy(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  return 0.5 * m_ * v.squaredNorm() + m_ * g0_ * q(1);
}
std::vector<Eigen::Vector2d> CartesianPendulum::reference(double theta0, double theta_dot0,
                                                          const std::vector<double>& times) const {
  const auto rate = [&](const Eigen::Vector2d& s) {
    return Eigen::Vector2d(s(1), -g0_ / L_ * std::sin(s(0)) - c_ / m_ * s(1));
  };
  constexpr double kMaxStep = 1e-4;
  std::vector<Eigen::Vector2d> out;
  Eigen::Vector2d s(theta0, theta_dot0);
  double t = 0.0;
  for (const double t_out : times) {
    // Classical RK4 with equal steps up to t_out.
    const int n = std::max(1, static_cast<int>(std::ceil((t_out - t) / kMaxStep)));
    const double h = (t_out - t) / n;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d k1 = rate(s);
      const Eigen::Vector2d k2 = rate(s + 0.5 * h * k1);
      const Eigen::Vector2d k3 = rate(s + 0.5 * h * k2);
      const Eigen::Vector2d k4 = rate(s + h * k3);
      s += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    t = t_out;
    out.push_back(s);
  }
  return out;
}

// Free rigid body.
namespace {
Eigen::Quaterniond quaternion(const Eigen::VectorXd& q) {
  return Eigen::Quaterniond(q(3), q(4), q(5), q(6));
}
}  // namespace

void FreeRigidBody::kinematic_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& N) const {
  // ṗ = ½ p ⊗ (0, ω) = ½ [−p_vᵀ; p_w I + [p_v]×] ω.
  N = Eigen::MatrixXd::Zero(7, 6);
  N.topLeftCorner(3, 3).setIdentity();
  const double w = q(3);
  const Eigen::Vector3d p_v = q.segment<3>(4);
  N.block<1, 3>(3, 3) = -0.5 * p_v.transpose();
  Eigen::Matrix3d cross;
  cross << 0, -p_v(2), p_v(1), p_v(2), 0, -p_v(0), -p_v(1), p_v(0), 0;
  N.block<3, 3>(4, 3) = 0.5 * (w * Eigen::Matrix3d::Identity() + cross);
}
void FreeRigidBody::integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                                          Eigen::VectorXd& q_out) const {
  // Translation adds; rotation composes with exp of the body-fixed increment.
  q_out.resize(7);
  q_out.head<3>() = q.head<3>() + dv.head<3>();
  const Eigen::Vector3d phi = dv.segment<3>(3);
  const double angle = phi.norm();
  const Eigen::Quaterniond increment =
      angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, phi / angle))
                  : Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond p = quaternion(q) * increment;
  q_out.segment<4>(3) << p.w(), p.x(), p.y(), p.z();
}
void FreeRigidBody::coordinate_invariants(const Eigen::VectorXd& q, Eigen::VectorXd& h,
                                          Eigen::MatrixXd& h_q) const {
  h = Eigen::VectorXd::Constant(1, 0.5 * (q.segment<4>(3).squaredNorm() - 1.0));
  h_q = Eigen::MatrixXd::Zero(1, 7);
  h_q.block<1, 4>(0, 3) = q.segment<4>(3).transpose();
}
void FreeRigidBody::mass_matrix(double, const Eigen::VectorXd&, Eigen::MatrixXd& M) {
  M = Eigen::MatrixXd::Zero(6, 6);
  M.topLeftCorner(3, 3) = m_ * Eigen::Matrix3d::Identity();
  M.bottomRightCorner(3, 3) = J_.asDiagonal();
}
void FreeRigidBody::generalized_forces(double, const Eigen::VectorXd&, const Eigen::VectorXd& v,
                                       Eigen::VectorXd& Q) {
  const Eigen::Vector3d w = v.segment<3>(3);
  Q = Eigen::VectorXd::Zero(6);
  Q.segment<3>(3) = -w.cross(J_.cwiseProduct(w));
}
void FreeRigidBody::constraints(double, const Eigen::VectorXd&, Eigen::VectorXd& g) {
  g.resize(0);
}
void FreeRigidBody::constraint_jacobian_q(double, const Eigen::VectorXd&,
                                          Eigen::MatrixXd& g_q) {
  g_q.resize(0, 7);
}
void FreeRigidBody::constraint_jacobian_v(double, const Eigen::VectorXd&,
                                          Eigen::MatrixXd& G) {
  G.resize(0, 6);
}
void FreeRigidBody::constraint_time_derivative(double, const Eigen::VectorXd&,
                                               Eigen::VectorXd& g_t) {
  g_t.resize(0);
}
void FreeRigidBody::acceleration_rhs(double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                                     Eigen::VectorXd& gamma) {
  gamma.resize(0);
}
Eigen::Vector3d FreeRigidBody::angular_momentum(const Eigen::VectorXd& q,
                                                const Eigen::VectorXd& v) const {
  return quaternion(q).toRotationMatrix() * J_.cwiseProduct(v.segment<3>(3));
}

// Heavy top.
namespace {
Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0, -a(2), a(1), a(2), 0, -a(0), -a(1), a(0), 0;
  return s;
}
// R(p) of HeavyTop, homogeneous quadratic in p.
Eigen::Matrix3d rotation(const Eigen::VectorXd& q) {
  const double w = q(3);
  const Eigen::Vector3d u = q.segment<3>(4);
  return (w * w - u.squaredNorm()) * Eigen::Matrix3d::Identity() + 2.0 * u * u.transpose() +
         2.0 * w * skew(u);
}
}  // namespace

void HeavyTop::generalized_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  Eigen::VectorXd& Q) {
  body_.generalized_forces(t, q, v, Q);
  Q(2) -= m_ * g0_;
}
void HeavyTop::constraints(double, const Eigen::VectorXd& q, Eigen::VectorXd& g) {
  g = q.head<3>() + rotation(q) * r_B_;
}
void HeavyTop::constraint_jacobian_q(double, const Eigen::VectorXd& q,
                                     Eigen::MatrixXd& g_q) {
  // ∂(R(p) r)/∂w = 2 (w r + u × r), ∂(R(p) r)/∂u = 2 (u·r I + u rᵀ − r uᵀ − w [r]×).
  const double w = q(3);
  const Eigen::Vector3d u = q.segment<3>(4);
  g_q = Eigen::MatrixXd::Zero(3, 7);
  g_q.leftCols(3).setIdentity();
  g_q.col(3) = 2.0 * (w * r_B_ + u.cross(r_B_));
  g_q.rightCols(3) = 2.0 * (u.dot(r_B_) * Eigen::Matrix3d::Identity() + u * r_B_.transpose() -
                            r_B_ * u.transpose() - w * skew(r_B_));
}
void HeavyTop::constraint_jacobian_v(double, const Eigen::VectorXd& q, Eigen::MatrixXd& G) {
  // d/dt (R r) = R (ω × r) = −R [r]× ω.
  G = Eigen::MatrixXd::Zero(3, 6);
  G.leftCols(3).setIdentity();
  G.rightCols(3) = -rotation(q) * skew(r_B_);
}
void HeavyTop::constraint_time_derivative(double, const Eigen::VectorXd&,
                                          Eigen::VectorXd& g_t) {
  g_t = Eigen::VectorXd::Zero(3);
}
void HeavyTop::acceleration_rhs(double, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                Eigen::VectorXd& gamma) {
  // d²/dt² (R r) = R (ω̇ × r + ω × (ω × r)): γ = −R (ω × (ω × r)).
  const Eigen::Vector3d w = v.segment<3>(3);
  gamma = -rotation(q) * w.cross(w.cross(r_B_));
}
double HeavyTop::energy(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  const Eigen::Vector3d w = v.segment<3>(3);
  return 0.5 * m_ * v.head<3>().squaredNorm() + 0.5 * w.dot(J_.cwiseProduct(w)) + m_ * g0_ * q(2);
}
double HeavyTop::vertical_momentum(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  const Eigen::Vector3d x = q.head<3>();
  return (m_ * x.cross(Eigen::Vector3d(v.head<3>())) + body_.angular_momentum(q, v))(2);
}

}  // namespace limber::integrate::testing
