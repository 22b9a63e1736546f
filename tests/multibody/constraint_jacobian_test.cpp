// Constraint Jacobians and acceleration right-hand sides of every joint type and driver
// against central finite differences, at generic (not assembled) configurations so the
// derivatives are checked off the constraint manifold too; on rigid bodies and on the FE
// nodes of a deformed flexible body.
#include <gtest/gtest.h>

#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/multibody_system.h"
#include "flexible_test_models.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;

// Central differences with step h: truncation ~ h² |g'''| ≈ 1e-12 for O(1) derivatives,
// rounding ~ 1e-16 / h = 1e-10; a 1e-8 bound is 100x above both and far below any
// error in a derivative term (O(1)).
constexpr double kStep = 1e-6;
constexpr double kFdTolerance = 1e-8;

// Two moving bodies in generic poses joined by `type`, plus a driver when asked;
// body b1 is also jointed to ground by the same type with ground as marker i.
Model two_body_model(JointType type, bool rotation_driver, bool translation_driver) {
  ModelBuilder builder;
  const Eigen::Matrix3d R1 = axis_angle_matrix(Eigen::Vector3d(1, 2, 3), 0.4);
  const Eigen::Matrix3d R2 = axis_angle_matrix(Eigen::Vector3d(-2, 1, 0.5), 1.1);
  builder.add_rigid_body(body_spec("b1", 2.0, Eigen::Vector3d(0.1, 0.2, 0.25), Eigen::Vector3d(0.3, -0.2, 0.5), R1,
                                   Eigen::Vector3d(0.05, 0.0, -0.1)));
  builder.add_rigid_body(body_spec("b2", 1.5, Eigen::Vector3d(0.3, 0.2, 0.15), Eigen::Vector3d(-0.4, 0.6, 0.1), R2));
  // Markers at arbitrary places, slightly misaligned (the model is not assembled).
  builder.add_marker("m1", "b1", Eigen::Vector3d(0.2, 0.1, -0.3), axis_angle_matrix(Eigen::Vector3d(0, 1, 1), 0.3));
  builder.add_marker("m2", "b2", Eigen::Vector3d(-0.1, 0.4, 0.2), axis_angle_matrix(Eigen::Vector3d(1, 0, 1), -0.7));
  builder.add_marker("g", "ground", Eigen::Vector3d(0.1, 0.2, 0.3), axis_angle_matrix(Eigen::Vector3d(1, 1, 0), 0.2));
  builder.add_marker("m3", "b1", Eigen::Vector3d(0.0, -0.2, 0.1), axis_angle_matrix(Eigen::Vector3d(0, 0, 1), 0.5));
  builder.add_joint("J", type, "m1", "m2");
  builder.add_joint("K", type, "g", "m3");
  if (rotation_driver) {
    builder.add_driver("DR", "J", DriverCoordinate::kRotation,
                       TimeFunction::ramp(0.2, 3.0, 2.0, RampShape::kQuintic));
  }
  if (translation_driver) {
    builder.add_driver("DT", "J", DriverCoordinate::kTranslation,
                       TimeFunction::table({0, 1, 2, 3}, {0.1, 0.3, 0.2, 0.5}, TableInterpolation::kCubic));
  }
  return builder.build();
}

// As two_body_model with b1 a flexible space frame (4 free-free modes, deformed: elastic
// rotations up to ~0.1 rad) whose markers sit on its tip node and on an inner node.
Model flexible_two_body_model(JointType type, bool rotation_driver, bool translation_driver) {
  ModelBuilder builder;
  const fe::FeModel frame = testing::space_frame(3);
  FlexibleBodySpec spec = testing::flexible_spec("b1", frame, testing::normal_modes(frame, 4), ModalDamping::ratio(0.0));
  spec.initial_pose.position = Eigen::Vector3d(0.3, -0.2, 0.5);
  spec.initial_pose.orientation = quaternion_from_matrix(axis_angle_matrix(Eigen::Vector3d(1, 2, 3), 0.4));
  spec.initial_modal_coordinates = Eigen::Vector4d(0.02, -0.015, 0.01, 0.012);
  builder.add_flexible_body(spec);
  builder.add_rigid_body(body_spec("b2", 1.5, Eigen::Vector3d(0.3, 0.2, 0.15), Eigen::Vector3d(-0.4, 0.6, 0.1),
                                   axis_angle_matrix(Eigen::Vector3d(-2, 1, 0.5), 1.1)));
  builder.add_node_marker("m1", "b1", frame.node_count() - 1, axis_angle_matrix(Eigen::Vector3d(0, 1, 1), 0.3));
  builder.add_marker("m2", "b2", Eigen::Vector3d(-0.1, 0.4, 0.2), axis_angle_matrix(Eigen::Vector3d(1, 0, 1), -0.7));
  builder.add_marker("g", "ground", Eigen::Vector3d(0.1, 0.2, 0.3), axis_angle_matrix(Eigen::Vector3d(1, 1, 0), 0.2));
  builder.add_node_marker("m3", "b1", 4, axis_angle_matrix(Eigen::Vector3d(0, 0, 1), 0.5));
  builder.add_joint("J", type, "m1", "m2");
  builder.add_joint("K", type, "g", "m3");
  if (rotation_driver) {
    builder.add_driver("DR", "J", DriverCoordinate::kRotation, TimeFunction::ramp(0.2, 3.0, 2.0, RampShape::kQuintic));
  }
  if (translation_driver) {
    builder.add_driver("DT", "J", DriverCoordinate::kTranslation,
                       TimeFunction::table({0, 1, 2, 3}, {0.1, 0.3, 0.2, 0.5}, TableInterpolation::kCubic));
  }
  return builder.build();
}

State generic_state(const Model& model) {
  State state = initial_state(model);
  state.t = 0.7;
  state.v = Eigen::VectorXd::LinSpaced(model.nv, -1.3, 1.7);
  state.v(3) = 2.1;
  return state;
}

// q ⊕ dv over all bodies.
Eigen::VectorXd perturb(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& dv) {
  Eigen::VectorXd out = q;
  for (size_t b = 0; b < model.bodies.size(); ++b) integrate_body_coordinates(model, b, q, dv, out);
  return out;
}

void check_model(const Model& model) {
  Workspace ws(model);
  const State state = generic_state(model);
  evaluate_constraints(model, state, Stage::kVelocity, ws);
  const Eigen::MatrixXd G = ws.G;
  const Eigen::VectorXd gamma = ws.gamma, g_t = ws.g_t;
  const Eigen::VectorXd g0 = ws.g;
  ASSERT_GT(g0.cwiseAbs().maxCoeff(), 1e-2);  // really off the manifold
  auto g_at = [&](const Eigen::VectorXd& q, double t) {
    State s = state;
    s.q = q;
    s.t = t;
    evaluate_constraints(model, s, Stage::kPosition, ws);
    return std::make_pair(Eigen::VectorXd(ws.g), Eigen::MatrixXd(ws.G));
  };
  // G against differences of g along each velocity direction (q ⊕ ±h e_k).
  for (int k = 0; k < model.nv; ++k) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(model.nv, k) * kStep;
    const Eigen::VectorXd fd =
        (g_at(perturb(model, state.q, e), state.t).first - g_at(perturb(model, state.q, -e), state.t).first) /
        (2 * kStep);
    EXPECT_LT((fd - G.col(k)).cwiseAbs().maxCoeff(), kFdTolerance) << "velocity direction " << k;
  }
  // g_t against differences in time.
  const Eigen::VectorXd gt_fd = (g_at(state.q, state.t + kStep).first - g_at(state.q, state.t - kStep).first) / (2 * kStep);
  EXPECT_LT((gt_fd - g_t).cwiseAbs().maxCoeff(), kFdTolerance);
  // γ = −(d/dt G) v − ∂g_t/∂t along the motion q ⊕ s v with v constant.
  const Eigen::VectorXd Gv_fd = (g_at(perturb(model, state.q, kStep * state.v), state.t).second * state.v -
                                 g_at(perturb(model, state.q, -kStep * state.v), state.t).second * state.v) /
                                (2 * kStep);
  State s_plus = state, s_minus = state;
  s_plus.t += kStep;
  s_minus.t -= kStep;
  evaluate_constraints(model, s_plus, Stage::kPosition, ws);
  const Eigen::VectorXd gt_plus = ws.g_t;
  evaluate_constraints(model, s_minus, Stage::kPosition, ws);
  const Eigen::VectorXd gtt_fd = (gt_plus - ws.g_t) / (2 * kStep);
  // γ involves second derivatives: differences of G v lose one more digit (tolerance 1e-7).
  EXPECT_LT((-Gv_fd - gtt_fd - gamma).cwiseAbs().maxCoeff(), 1e-7);
  // ∂g/∂q of the integrator interface against differences of the raw coordinates.
  MultibodySystem system(model, full_partition(model));
  Eigen::MatrixXd g_q, N;
  system.constraint_jacobian_q(state.t, state.q, g_q);
  for (int k = 0; k < model.nq; ++k) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(model.nq, k) * kStep;
    const Eigen::VectorXd fd = (g_at(state.q + e, state.t).first - g_at(state.q - e, state.t).first) / (2 * kStep);
    EXPECT_LT((fd - g_q.col(k)).cwiseAbs().maxCoeff(), kFdTolerance) << "coordinate " << k;
  }
  // And G = ∂g/∂q N exactly (unit quaternions: L Lᵀ = I), to rounding.
  system.kinematic_matrix(state.q, N);
  EXPECT_LT((g_q * N - G).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(ConstraintJacobian, Revolute) { check_model(two_body_model(JointType::kRevolute, true, false)); }
TEST(ConstraintJacobian, Translational) { check_model(two_body_model(JointType::kTranslational, false, true)); }
TEST(ConstraintJacobian, Spherical) { check_model(two_body_model(JointType::kSpherical, false, false)); }
TEST(ConstraintJacobian, Bracket) { check_model(two_body_model(JointType::kBracket, false, false)); }
TEST(ConstraintJacobian, Universal) { check_model(two_body_model(JointType::kUniversal, false, false)); }
TEST(ConstraintJacobian, CylindricalWithBothDrivers) {
  check_model(two_body_model(JointType::kCylindrical, true, true));
}

TEST(ConstraintJacobian, FlexibleNodeMarkersEveryJointType) {
  // Same bounds as the rigid models: the node kinematics (exp of the elastic rotation and
  // its left Jacobian) must be exact, not first-order in η.
  for (JointType type : {JointType::kRevolute, JointType::kTranslational, JointType::kSpherical,
                         JointType::kBracket, JointType::kUniversal}) {
    SCOPED_TRACE(to_string(type));
    check_model(flexible_two_body_model(type, false, false));
  }
  check_model(flexible_two_body_model(JointType::kCylindrical, true, true));
}

TEST(ConstraintJacobian, EquationNamesAndCounts) {
  // Haug 1989 Table 9.x counts: revolute 5, translational 5, spherical 3, bracket 6,
  // universal 4, cylindrical 4.
  const std::pair<JointType, int> expected[] = {
      {JointType::kRevolute, 5}, {JointType::kTranslational, 5}, {JointType::kSpherical, 3},
      {JointType::kBracket, 6},  {JointType::kUniversal, 4},     {JointType::kCylindrical, 4}};
  for (const auto& [type, rows] : expected) {
    const Model model = two_body_model(type, false, false);
    EXPECT_EQ(model.joints[0].rows, rows) << to_string(type);
  }
  const Model revolute = two_body_model(JointType::kRevolute, true, false);
  EXPECT_EQ(revolute.equations[4].name, "J.rot_y");
  EXPECT_EQ(revolute.equations[10].name, "DR");
}

}  // namespace
}  // namespace limber::multibody
