// Small MechanicalSystems with known solutions, for the integrator tests and benchmark.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/mechanical_system.h"

namespace limber::integrate::testing {

// Mass m on x'' = −k x (nq = nv = 1, no constraints): x = x0 cos ωt, ω = √(k/m).
class Oscillator final : public MechanicalSystem {
 public:
  Oscillator(double mass, double stiffness) : m_(mass), k_(stiffness) {}
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  int nc() const override { return 0; }
  int nh() const override { return 0; }
  void kinematic_matrix(const Eigen::VectorXd&, Eigen::MatrixXd& N) const override;
  void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                             Eigen::VectorXd& q_out) const override;
  void coordinate_invariants(const Eigen::VectorXd&, Eigen::VectorXd& h,
                             Eigen::MatrixXd& h_q) const override;
  void mass_matrix(double, const Eigen::VectorXd&, Eigen::MatrixXd& M) override;
  void generalized_forces(double, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                          Eigen::VectorXd& Q) override;
  void constraints(double, const Eigen::VectorXd&, Eigen::VectorXd& g) override;
  void constraint_jacobian_q(double, const Eigen::VectorXd&, Eigen::MatrixXd& g_q) override;
  void constraint_jacobian_v(double, const Eigen::VectorXd&, Eigen::MatrixXd& G) override;
  void constraint_time_derivative(double, const Eigen::VectorXd&,
                                  Eigen::VectorXd& g_t) override;
  void acceleration_rhs(double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                        Eigen::VectorXd& gamma) override;

 private:
  double m_, k_;
};

// Two unit masses on springs k to ground, joined by a spring k_c: x'' = −K x with
// K = [[k + k_c, −k_c], [−k_c, k + k_c]]; x1 + x2 moves as one oscillator of ω² = k, x1 − x2 as
// one of ω² = k + 2 k_c. It offers k alone as its diagonal stiffness, as a modal body offers
// its modes' ω² but not a force element between two of its coordinates, so a structured
// iteration matrix misses k_c.
class CoupledOscillators final : public MechanicalSystem {
 public:
  CoupledOscillators(double stiffness, double coupling) : k_(stiffness), k_c_(coupling) {}
  int nq() const override { return 2; }
  int nv() const override { return 2; }
  int nc() const override { return 0; }
  int nh() const override { return 0; }
  void kinematic_matrix(const Eigen::VectorXd&, Eigen::MatrixXd& N) const override;
  void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                             Eigen::VectorXd& q_out) const override;
  void coordinate_invariants(const Eigen::VectorXd&, Eigen::VectorXd& h,
                             Eigen::MatrixXd& h_q) const override;
  void mass_matrix(double, const Eigen::VectorXd&, Eigen::MatrixXd& M) override;
  void generalized_forces(double, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                          Eigen::VectorXd& Q) override;
  void constraints(double, const Eigen::VectorXd&, Eigen::VectorXd& g) override;
  void constraint_jacobian_q(double, const Eigen::VectorXd&, Eigen::MatrixXd& g_q) override;
  void constraint_jacobian_v(double, const Eigen::VectorXd&, Eigen::MatrixXd& G) override;
  void constraint_time_derivative(double, const Eigen::VectorXd&,
                                  Eigen::VectorXd& g_t) override;
  void acceleration_rhs(double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                        Eigen::VectorXd& gamma) override;
  bool diagonal_stiffness_damping(Eigen::VectorXd& k, Eigen::VectorXd& c) const override;

 private:
  double k_, k_c_;
};

// Planar pendulum in Cartesian coordinates: point mass m at q = (x, y) [m], pivot at the origin,
// gravity −g0 ŷ, viscous damping force −c v; one constraint g = ½(x² + y² − L²) = 0 with
// λ = rod tension / L [N/m]. θ is measured from the downward vertical: (x, y) = L (sin θ, −cos θ).
class CartesianPendulum final : public MechanicalSystem {
 public:
  CartesianPendulum(double mass, double length, double gravity, double damping = 0.0)
      : m_(mass), L_(length), g0_(gravity), c_(damping) {}
  int nq() const override { return 2; }
  int nv() const override { return 2; }
  int nc() const override { return 1; }
  int nh() const override { return 0; }
  void kinematic_matrix(const Eigen::VectorXd&, Eigen::MatrixXd& N) const override;
  void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                             Eigen::VectorXd& q_out) const override;
  void coordinate_invariants(const Eigen::VectorXd&, Eigen::VectorXd& h,
                             Eigen::MatrixXd& h_q) const override;
  void mass_matrix(double, const Eigen::VectorXd&, Eigen::MatrixXd& M) override;
  void generalized_forces(double, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                          Eigen::VectorXd& Q) override;
  void constraints(double, const Eigen::VectorXd& q, Eigen::VectorXd& g) override;
  void constraint_jacobian_q(double, const Eigen::VectorXd& q,
                             Eigen::MatrixXd& g_q) override;
  void constraint_jacobian_v(double, const Eigen::VectorXd& q, Eigen::MatrixXd& G) override;
  void constraint_time_derivative(double, const Eigen::VectorXd&,
                                  Eigen::VectorXd& g_t) override;
  void acceleration_rhs(double, const Eigen::VectorXd&, const Eigen::VectorXd& v,
                        Eigen::VectorXd& gamma) override;

  // State at angle θ [rad] and rate θ̇ [rad/s].
  Eigen::VectorXd position(double theta) const;
  Eigen::VectorXd velocity(double theta, double theta_dot) const;
  // Kinetic plus gravity energy [J] (zero of gravity at the pivot).
  double energy(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  double damping() const { return c_; }

  // θ(t), θ̇(t) at `times` from θ'' = −(g0/L) sin θ − (c/m) θ̇ by classical RK4 with steps
  // ≤ 1e-4 s (global error ~1e-14 rad over a few seconds): the reference second method.
  std::vector<Eigen::Vector2d> reference(double theta0, double theta_dot0,
                                         const std::vector<double>& times) const;

 private:
  double m_, L_, g0_, c_;
};

// Torque-free rigid body: q = [position (3), unit quaternion (w, x, y, z)], v = [velocity of the
// centre of mass in the world (3), angular velocity in the body (3)]; inertia diag(J) about the
// centre of mass; h = ½(|p|² − 1). Euler's equations J ω̇ + ω × J ω = 0.
class FreeRigidBody final : public MechanicalSystem {
 public:
  FreeRigidBody(double mass, const Eigen::Vector3d& principal_inertia)
      : m_(mass), J_(principal_inertia) {}
  int nq() const override { return 7; }
  int nv() const override { return 6; }
  int nc() const override { return 0; }
  int nh() const override { return 1; }
  void kinematic_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& N) const override;
  void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                             Eigen::VectorXd& q_out) const override;
  void coordinate_invariants(const Eigen::VectorXd& q, Eigen::VectorXd& h,
                             Eigen::MatrixXd& h_q) const override;
  void mass_matrix(double, const Eigen::VectorXd&, Eigen::MatrixXd& M) override;
  void generalized_forces(double, const Eigen::VectorXd&, const Eigen::VectorXd& v,
                          Eigen::VectorXd& Q) override;
  void constraints(double, const Eigen::VectorXd&, Eigen::VectorXd& g) override;
  void constraint_jacobian_q(double, const Eigen::VectorXd&, Eigen::MatrixXd& g_q) override;
  void constraint_jacobian_v(double, const Eigen::VectorXd&, Eigen::MatrixXd& G) override;
  void constraint_time_derivative(double, const Eigen::VectorXd&,
                                  Eigen::VectorXd& g_t) override;
  void acceleration_rhs(double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                        Eigen::VectorXd& gamma) override;

  // Angular momentum about the centre of mass in the world frame, R(p) J ω [kg m²/s].
  Eigen::Vector3d angular_momentum(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;

 private:
  double m_;
  Eigen::Vector3d J_;
};

// A rigid body hanging from a spherical joint at the world origin (the heavy top): the body of
// FreeRigidBody, gravity −g0 ẑ, and g = x + R(p) r_B = 0 (3 equations), r_B the joint point
// from the centre of mass in the body. R(p) = (w² − u·u) I + 2 u uᵀ + 2 w [u]× (a rotation for
// unit p). Conserved: energy and the vertical angular momentum about the joint.
class HeavyTop final : public MechanicalSystem {
 public:
  HeavyTop(double mass, const Eigen::Vector3d& principal_inertia, const Eigen::Vector3d& r_B,
           double gravity)
      : body_(mass, principal_inertia), m_(mass), J_(principal_inertia), r_B_(r_B), g0_(gravity) {}
  int nq() const override { return 7; }
  int nv() const override { return 6; }
  int nc() const override { return 3; }
  int nh() const override { return 1; }
  void kinematic_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& N) const override {
    body_.kinematic_matrix(q, N);
  }
  void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                             Eigen::VectorXd& q_out) const override {
    body_.integrate_coordinates(q, dv, q_out);
  }
  void coordinate_invariants(const Eigen::VectorXd& q, Eigen::VectorXd& h,
                             Eigen::MatrixXd& h_q) const override {
    body_.coordinate_invariants(q, h, h_q);
  }
  void mass_matrix(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& M) override {
    body_.mass_matrix(t, q, M);
  }
  void generalized_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                          Eigen::VectorXd& Q) override;
  void constraints(double, const Eigen::VectorXd& q, Eigen::VectorXd& g) override;
  void constraint_jacobian_q(double, const Eigen::VectorXd& q, Eigen::MatrixXd& g_q) override;
  void constraint_jacobian_v(double, const Eigen::VectorXd& q, Eigen::MatrixXd& G) override;
  void constraint_time_derivative(double, const Eigen::VectorXd&,
                                  Eigen::VectorXd& g_t) override;
  void acceleration_rhs(double, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                        Eigen::VectorXd& gamma) override;

  double energy(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  // Vertical component of the angular momentum about the joint (the world origin) [kg m²/s].
  double vertical_momentum(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;

 private:
  FreeRigidBody body_;
  double m_;
  Eigen::Vector3d J_, r_B_;
  double g0_;
};

// Forwards every call to another system; tests override single members to break it.
class ForwardingSystem : public MechanicalSystem {
 public:
  explicit ForwardingSystem(MechanicalSystem& base) : base_(base) {}
  int nq() const override { return base_.nq(); }
  int nv() const override { return base_.nv(); }
  int nc() const override { return base_.nc(); }
  int nh() const override { return base_.nh(); }
  void kinematic_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& N) const override {
    base_.kinematic_matrix(q, N);
  }
  void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                             Eigen::VectorXd& q_out) const override {
    base_.integrate_coordinates(q, dv, q_out);
  }
  void coordinate_invariants(const Eigen::VectorXd& q, Eigen::VectorXd& h,
                             Eigen::MatrixXd& h_q) const override {
    base_.coordinate_invariants(q, h, h_q);
  }
  void mass_matrix(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& M) override {
    base_.mass_matrix(t, q, M);
  }
  void generalized_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                          Eigen::VectorXd& Q) override {
    base_.generalized_forces(t, q, v, Q);
  }
  void constraints(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g) override {
    base_.constraints(t, q, g);
  }
  void constraint_jacobian_q(double t, const Eigen::VectorXd& q,
                             Eigen::MatrixXd& g_q) override {
    base_.constraint_jacobian_q(t, q, g_q);
  }
  void constraint_jacobian_v(double t, const Eigen::VectorXd& q,
                             Eigen::MatrixXd& G) override {
    base_.constraint_jacobian_v(t, q, G);
  }
  void constraint_time_derivative(double t, const Eigen::VectorXd& q,
                                  Eigen::VectorXd& g_t) override {
    base_.constraint_time_derivative(t, q, g_t);
  }
  void acceleration_rhs(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                        Eigen::VectorXd& gamma) override {
    base_.acceleration_rhs(t, q, v, gamma);
  }

 protected:
  MechanicalSystem& base_;
};

}  // namespace limber::integrate::testing
