// Pendulums at an instant: accelerations and joint reactions against Newton-Euler
// closed forms (compound pendulum at rest; mass pendulum swinging: rod tension
// m (g cos θ + L θ̇²)).
#include <cmath>

#include <gtest/gtest.h>

#include "multibody/assembly.h"
#include "multibody/dynamics.h"
#include "multibody/multibody_system.h"
#include "multibody/reactions.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;

constexpr double kG = 9.81;

// A body hanging from a ground revolute at the origin (axis ground y), its centre of mass
// at distance `arm` from the pivot at angle θ from the downward vertical, moving at θ̇.
// Body frame at the centre of mass, x along the arm (pivot → CoM).
struct Pendulum {
  Model model;
  State state;
};

Pendulum make_pendulum(double mass, double arm, double inertia, double theta, double theta_dot) {
  ModelBuilder builder;
  builder.set_gravity(Eigen::Vector3d(0, 0, -kG));
  const Eigen::Vector3d e(std::sin(theta), 0, -std::cos(theta));
  Eigen::Matrix3d R;
  R << e, Eigen::Vector3d::UnitY(), e.cross(Eigen::Vector3d::UnitY());
  RigidBodySpec spec = body_spec("bob", mass, Eigen::Vector3d(1e-3 * inertia, inertia, inertia), arm * e, R);
  // θ̇ about ground y: ṙ = ω × r, ω' = Rᵀ ω.
  const Eigen::Vector3d w = -theta_dot * Eigen::Vector3d::UnitY();  // θ grows from −z towards +x: −y
  spec.initial_velocity_W = w.cross(arm * e);
  spec.initial_angular_velocity_B = R.transpose() * w;
  builder.add_rigid_body(spec);
  const Eigen::Matrix3d R_axis = frame_from_axes(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
  builder.add_marker_at("pivot.ground", "ground", Eigen::Vector3d::Zero(), R_axis);
  builder.add_marker_at("pivot.bob", "bob", Eigen::Vector3d::Zero(), R_axis);
  builder.add_joint("pivot", JointType::kRevolute, "pivot.ground", "pivot.bob");
  Pendulum p{builder.build(), {}};
  p.state = initial_state(p.model);
  return p;
}

TEST(Pendulum, CompoundPendulumAtRest) {
  // Uniform rod m, L from its end: θ̈ = −(3g / 2L) sin θ; pivot force on the rod along the
  // rod −m g cos θ (tension), across it m g sin θ / 4; no reaction torque.
  const double m = 2.0, L = 1.2, theta = 0.6;
  Pendulum p = make_pendulum(m, L / 2, m * L * L / 12, theta, 0.0);
  Workspace ws(p.model);
  ASSERT_EQ(assemble_positions(p.model, p.state, ws).status, AssemblyStatus::kOk);
  const ConstraintPartition partition = analyse_redundancy(p.model, p.state, ws);
  EXPECT_TRUE(partition.redundant.empty());
  Eigen::VectorXd v_dot, lambda;
  solve_accelerations(p.model, p.state, partition, ws, v_dot, lambda);
  // Angular acceleration about ground y is −θ̈ (θ turns about −y); ω' = (0, ·, 0) in body axes.
  const Eigen::Vector3d e(std::sin(theta), 0, -std::cos(theta)), t(std::cos(theta), 0, std::sin(theta));
  const double theta_ddot = -1.5 * kG / L * std::sin(theta);
  // Rounding of a 11 x 11 KKT solve on O(10) numbers: 1e-12.
  EXPECT_NEAR(v_dot(4), -theta_ddot, 1e-12);  // body y = ground y
  EXPECT_NEAR(v_dot.head<3>().dot(t), theta_ddot * L / 2, 1e-12);
  const Reactions r = compute_reactions(p.model, p.state, v_dot, partition, ws);
  const JointReaction& pivot = r.joints[0];
  EXPECT_NEAR(pivot.force_j_W.dot(e), -m * kG * std::cos(theta), 1e-11);
  EXPECT_NEAR(pivot.force_j_W.dot(t), m * kG * std::sin(theta) / 4, 1e-11);
  EXPECT_NEAR(pivot.force_j_W.y(), 0.0, 1e-11);
  EXPECT_LT(pivot.torque_j_W.norm(), 1e-11);
  // Ground side: equal and opposite; joint-frame components are the same vector rotated.
  EXPECT_LT((pivot.force_i_W + pivot.force_j_W).norm(), 1e-14);
  const Eigen::Matrix3d R_axis = frame_from_axes(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
  EXPECT_LT((R_axis * pivot.force_i_I - pivot.force_i_W).norm(), 1e-12);
  EXPECT_FALSE(pivot.indeterminate);
}

TEST(Pendulum, SwingingMassRodTension) {
  // Radial Newton for any central inertia: tension m (g cos θ + L θ̇²); tangential:
  // θ̈ = −m g L sin θ / (J + m L²).
  const double m = 0.7, L = 0.9, J = 1e-4, theta = -1.1, theta_dot = 2.3;
  Pendulum p = make_pendulum(m, L, J, theta, theta_dot);
  Workspace ws(p.model);
  ASSERT_EQ(assemble_positions(p.model, p.state, ws).status, AssemblyStatus::kOk);
  // The initial velocity is already consistent: the projection must not change it.
  const Eigen::VectorXd v0 = p.state.v;
  EXPECT_LT(assemble_velocities(p.model, p.state, ws), 1e-13);
  EXPECT_LT((p.state.v - v0).norm(), 1e-13);
  const ConstraintPartition partition = analyse_redundancy(p.model, p.state, ws);
  Eigen::VectorXd v_dot, lambda;
  solve_accelerations(p.model, p.state, partition, ws, v_dot, lambda);
  EXPECT_NEAR(-v_dot(4), -m * kG * L * std::sin(theta) / (J + m * L * L), 1e-11);
  const Reactions r = compute_reactions(p.model, p.state, v_dot, partition, ws);
  const Eigen::Vector3d e(std::sin(theta), 0, -std::cos(theta));
  const double tension = m * (kG * std::cos(theta) + L * theta_dot * theta_dot);
  EXPECT_NEAR(-r.joints[0].force_j_W.dot(e), tension, 1e-11 * tension);
}

TEST(Pendulum, LargeAmplitudePeriodByRk4MatchesEllipticIntegral) {
  // Compound pendulum released at rest from θ0 = 1 rad: T = 4 sqrt(I_p / (m g d)) K(sin θ0/2)
  // (I_p about the pivot, d pivot-to-CoM). Integrated here without solver/integrate, by
  // classical RK4 (h = 1 ms) on the index-1 form q' = N v, v' from the KKT system, which
  // checks M, Q, G and γ together. Zero crossings of θ by linear interpolation (θ'' = 0
  // there). RK4 phase error ~ (ωh)⁴ / 120 per radian ≈ 1e-12; constraint drift ~1e-9.
  const double m = 1.0, d = 0.5, J = 2e-3, theta0 = 1.0;
  Pendulum p = make_pendulum(m, d, J, theta0, 0.0);
  Workspace ws(p.model);
  ASSERT_EQ(assemble_positions(p.model, p.state, ws).status, AssemblyStatus::kOk);
  const ConstraintPartition partition = analyse_redundancy(p.model, p.state, ws);
  MultibodySystem system(p.model, partition);
  const double period =
      4.0 * std::sqrt((J + m * d * d) / (m * kG * d)) * std::comp_ellint_1(std::sin(theta0 / 2));
  auto rate = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& q_dot,
                  Eigen::VectorXd& v_dot) {
    Eigen::MatrixXd N;
    Eigen::VectorXd lambda;
    system.kinematic_matrix(q, N);
    q_dot = N * v;
    solve_accelerations(p.model, State{0.0, q, v}, partition, ws, v_dot, lambda);
  };
  auto angle = [&](const Eigen::VectorXd& q) { return std::atan2(q(0), -q(2)); };
  const EnergyTerms e_start = energies(p.model, p.state, ws);
  const double h = 1e-3;
  std::vector<double> crossings;
  Eigen::VectorXd q = p.state.q, v = p.state.v;
  for (int step = 0; step < 2000 && crossings.size() < 3; ++step) {
    Eigen::VectorXd k1q, k1v, k2q, k2v, k3q, k3v, k4q, k4v;
    rate(q, v, k1q, k1v);
    rate(q + 0.5 * h * k1q, v + 0.5 * h * k1v, k2q, k2v);
    rate(q + 0.5 * h * k2q, v + 0.5 * h * k2v, k3q, k3v);
    rate(q + h * k3q, v + h * k3v, k4q, k4v);
    const Eigen::VectorXd q_next = q + h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
    const double a0 = angle(q), a1 = angle(q_next);
    if (a0 * a1 < 0.0) crossings.push_back((step + a0 / (a0 - a1)) * h);
    q = q_next;
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  ASSERT_EQ(crossings.size(), 3u);
  // Crossings are half a period apart; linear interpolation error ~ h² |θ'''| / 8 ~ 1e-6 s.
  EXPECT_NEAR(crossings[2] - crossings[0], period, 2e-6);
  const EnergyTerms e_end = energies(p.model, State{0.0, q, v}, ws);
  EXPECT_NEAR(e_end.kinetic + e_end.gravity, e_start.kinetic + e_start.gravity, 1e-8 * m * kG * d);
}

}  // namespace
}  // namespace limber::multibody
