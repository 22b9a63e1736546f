// Mass matrix, quadratic-velocity forces and force elements against closed forms,
// conservation laws and finite differences of the energies.
#include <gtest/gtest.h>

#include "multibody/assembly.h"
#include "multibody/body.h"
#include "multibody/dynamics.h"
#include "multibody/multibody_system.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;

// A spinning, translating body whose origin is away from its centre of mass.
Model free_body(const Eigen::Vector3d& gravity) {
  ModelBuilder builder;
  builder.set_gravity(gravity);
  RigidBodySpec spec = body_spec("b", 3.0, Eigen::Vector3d(0.2, 0.5, 0.6), Eigen::Vector3d(0.1, 0.2, 0.3),
                                 axis_angle_matrix(Eigen::Vector3d(1, 1, 0), 0.5), Eigen::Vector3d(0.3, -0.2, 0.1));
  spec.inertia_com_B(0, 1) = spec.inertia_com_B(1, 0) = 0.05;
  spec.initial_velocity_W = Eigen::Vector3d(0.5, -0.3, 0.2);
  spec.initial_angular_velocity_B = Eigen::Vector3d(1.0, 4.0, -2.5);  // near the unstable middle axis
  builder.add_rigid_body(spec);
  return builder.build();
}

TEST(Dynamics, CentreOfMassFallsWithGravity) {
  // Newton: a_c = g whatever the spin, and Euler: J_c ω̇' = −ω' × J_c ω'.
  const Eigen::Vector3d g(0, 0, -9.81);
  const Model model = free_body(g);
  Workspace ws(model);
  const State state = initial_state(model);
  Eigen::VectorXd v_dot, lambda;
  solve_accelerations(model, state, full_partition(model), ws, v_dot, lambda);
  const Body& b = model.bodies[1];
  const Eigen::Matrix3d A = rotation_matrix(state.q.segment<4>(3));
  const Eigen::Vector3d w = state.v.segment<3>(3), w_dot = v_dot.segment<3>(3);
  const Eigen::Vector3d a_c = v_dot.head<3>() + A * w_dot.cross(b.com_B) + A * w.cross(w.cross(b.com_B));
  // Rounding of a 6 x 6 solve with entries O(1-10): 1e-12.
  EXPECT_LT((a_c - g).norm(), 1e-12);
  EXPECT_LT((b.inertia_com_B * w_dot + w.cross(b.inertia_com_B * w)).norm(), 1e-12);
}

TEST(Dynamics, TorqueFreeBodyConservesEnergyAndMomentum) {
  // Classical RK4 on q' = N v, v' = M⁻¹ Q for 1 s at h = 1e-3 (global error ~ h⁴ ω⁵ ~ 1e-9).
  const Model model = free_body(Eigen::Vector3d::Zero());
  MultibodySystem system(model, full_partition(model));
  Workspace ws(model);
  State state = initial_state(model);
  const Body& b = model.bodies[1];
  auto momentum = [&](const State& s) {
    // H about the ground origin: m r_c × v_c + A J_c ω'.
    const Eigen::Matrix3d A = rotation_matrix(s.q.segment<4>(3));
    const Eigen::Vector3d w = s.v.segment<3>(3);
    const Eigen::Vector3d r_c = s.q.head<3>() + A * b.com_B, v_c = s.v.head<3>() + A * w.cross(b.com_B);
    return Eigen::Vector3d(b.mass * r_c.cross(v_c) + A * b.inertia_com_B * w);
  };
  auto rate = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& q_dot, Eigen::VectorXd& v_dot) {
    Eigen::MatrixXd N, M;
    Eigen::VectorXd Q;
    system.kinematic_matrix(q, N);
    system.mass_matrix(0.0, q, M);
    system.generalized_forces(0.0, q, v, Q);
    q_dot = N * v;
    v_dot = M.llt().solve(Q);
  };
  const double T0 = energies(model, state, ws).kinetic;
  const Eigen::Vector3d H0 = momentum(state);
  const double h = 1e-3;
  for (int step = 0; step < 1000; ++step) {
    Eigen::VectorXd k1q, k1v, k2q, k2v, k3q, k3v, k4q, k4v;
    rate(state.q, state.v, k1q, k1v);
    rate(state.q + 0.5 * h * k1q, state.v + 0.5 * h * k1v, k2q, k2v);
    rate(state.q + 0.5 * h * k2q, state.v + 0.5 * h * k2v, k3q, k3v);
    rate(state.q + h * k3q, state.v + h * k3v, k4q, k4v);
    state.q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
    state.v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  // A wrong quadratic-velocity term changes T and H at O(1) relative within a second.
  EXPECT_NEAR(energies(model, state, ws).kinetic / T0, 1.0, 1e-8);
  EXPECT_LT((momentum(state) - H0).norm() / H0.norm(), 1e-8);
}

// Two bodies linked by an RSDA and a TSDA (optionally with actuators: the RSDA's a
// function of its angle, the TSDA's of time) and a point load on b2, gravity off.
Model spring_model(double k_rot, double c_rot, double k_lin, double c_lin, bool actuated = false) {
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("b1", 2.0, Eigen::Vector3d(0.1, 0.2, 0.25), Eigen::Vector3d(0.3, -0.2, 0.5),
                                   axis_angle_matrix(Eigen::Vector3d(1, 2, 3), 0.4)));
  builder.add_rigid_body(body_spec("b2", 1.5, Eigen::Vector3d(0.3, 0.2, 0.15), Eigen::Vector3d(-0.4, 0.6, 0.1),
                                   axis_angle_matrix(Eigen::Vector3d(-2, 1, 0.5), 1.1)));
  builder.add_marker("m1", "b1", Eigen::Vector3d(0.2, 0.1, -0.3), axis_angle_matrix(Eigen::Vector3d(0, 1, 1), 0.3));
  builder.add_marker("m2", "b2", Eigen::Vector3d(-0.1, 0.4, 0.2), axis_angle_matrix(Eigen::Vector3d(1, 0, 1), -0.7));
  const TimeFunction none = TimeFunction::constant(0.0);
  builder.add_rsda({"rsda", "m1", "m2", k_rot, c_rot, 0.4,
                    actuated ? TimeFunction::table({-3, 3}, {-5, 7}, TableInterpolation::kLinear) : none, true});
  builder.add_tsda({"tsda", "m1", "m2", k_lin, c_lin, 0.5, actuated ? TimeFunction::constant_speed(1.0, 2.0) : none});
  if (actuated) {
    builder.add_point_load({"load", "m2", Eigen::Vector3d(1, -2, 3), Eigen::Vector3d(0.5, 0.1, -0.2),
                            TimeFunction::constant(1.5), LoadFrame::kMarker});
  }
  return builder.build();
}

TEST(Dynamics, SpringForcesAreMinusGradientOfSpringEnergy) {
  // Q_spring = −∂V/∂v (virtual work along q ⊕ h e_k), a check of the RSDA angle rate
  // vector and of the TSDA direction; central differences: error ~ 1e-10 (see the
  // constraint tests), tolerance 1e-7 on forces of O(100).
  const Model model = spring_model(30.0, 0.0, 200.0, 0.0);
  Workspace ws(model);
  State state = initial_state(model);
  state.v.setZero();
  generalized_forces(model, state, ws);
  const Eigen::VectorXd Q = ws.Q;
  const double h = 1e-6;
  for (int k = 0; k < model.nv; ++k) {
    State plus = state, minus = state;
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(model.nv, k) * h;
    for (int b = 1; b <= 2; ++b) {
      integrate_body_coordinates(model, b, state.q, e, plus.q);
      integrate_body_coordinates(model, b, state.q, -e, minus.q);
    }
    const double dV = (energies(model, plus, ws).spring - energies(model, minus, ws).spring) / (2 * h);
    EXPECT_NEAR(Q(k), -dV, 1e-7) << "direction " << k;
  }
  EXPECT_GT(Q.norm(), 1.0);
}

TEST(Dynamics, DamperPowerEqualsDissipation) {
  // With k = 0 and no actuators, the generalized forces minus the inertial ones do
  // power Qᵀv = −(c θ̇² + c l̇²): rounding only (1e-12 relative).
  const Model model = spring_model(0.0, 3.0, 0.0, 7.0);
  const Model inert = spring_model(0.0, 0.0, 0.0, 0.0);
  Workspace ws(model), ws_inert(inert);
  State state = initial_state(model);
  state.v = Eigen::VectorXd::LinSpaced(model.nv, -1.0, 2.0);
  PowerTerms powers;
  generalized_forces(model, state, ws, &powers);
  generalized_forces(inert, state, ws_inert);
  const double power = (ws.Q - ws_inert.Q).dot(state.v);
  EXPECT_GT(powers.dissipation, 0.1);
  EXPECT_NEAR(power, -powers.dissipation, 1e-12 * powers.dissipation);
}

TEST(Dynamics, ActuatorAndLoadPowersMatchGeneralizedForces) {
  // Qᵀv of the force elements = −dissipation + actuator power + load power (virtual work
  // with the exact marker Jacobians): rounding only.
  const Model model = spring_model(0.0, 3.0, 0.0, 7.0, true);
  const Model inert = spring_model(0.0, 0.0, 0.0, 0.0, false);
  Workspace ws(model), ws_inert(inert);
  State state = initial_state(model);
  state.t = 0.3;
  state.v = Eigen::VectorXd::LinSpaced(model.nv, 2.0, -1.0);
  PowerTerms powers;
  generalized_forces(model, state, ws, &powers);
  generalized_forces(inert, state, ws_inert);
  const double power = (ws.Q - ws_inert.Q).dot(state.v);
  EXPECT_GT(std::abs(powers.actuators), 0.1);
  EXPECT_GT(std::abs(powers.loads), 0.1);
  EXPECT_NEAR(power, -powers.dissipation + powers.actuators + powers.loads, 1e-12 * (1 + std::abs(power)));
}

}  // namespace
}  // namespace limber::multibody
