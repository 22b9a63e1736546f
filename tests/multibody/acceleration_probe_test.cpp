// Acceleration probes (multibody/acceleration_probe.h) at given states against closed forms:
// a point of a spinning rigid body (centripetal and tangential), and an FE node of a flexible
// rod in free vibration in one mode (ü = −ω_i² u). The flexible node along a run is checked
// against finite differences of its velocity in tests/run/acceleration_probe_run_test.cpp.
#include "multibody/acceleration_probe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexible_test_models.h"
#include "multibody/rotation.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

// A rigid body turned 90° about ground x (body z along ground −y), at r, spinning about its z
// at Ω with angular acceleration α, its origin accelerating at r̈; the point p_B = (ρ, 0, 0)
// sits at ρ x_W from the axis: centripetal −Ω² ρ x_W, tangential α z_B × ρ x_W = α ρ z_W.
TEST(AccelerationProbe, PointOfASpinningRigidBody) {
  ModelBuilder builder;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  builder.add_rigid_body(testing::body_spec("wheel", 2.0, Eigen::Vector3d(1, 1, 2), Eigen::Vector3d(1, 2, 3), R));
  const double rho = 0.3, Omega = 40.0, alpha = 7.0;
  builder.add_acceleration_probe({"rim", "", "wheel", Eigen::Vector3d(rho, 0, 0), -1});
  const Model model = builder.build();
  ASSERT_EQ(model.acceleration_probes.size(), 1u);
  Eigen::VectorXd q(7), v(6), v_dot(6);
  q << 1, 2, 3, quaternion_from_matrix(R);
  v << 0.5, 0, 0, 0, 0, Omega;
  v_dot << 0.1, -0.2, 0.3, 0, 0, alpha;
  FrameKinematics frame;
  const PointMotion motion = probe_motion(model, model.acceleration_probes[0], q, v, v_dot, frame);
  // Exact up to the rotation's round-off (1e-15 of Ω² ρ = 480 m/s²).
  EXPECT_TRUE(motion.p_W.isApprox(Eigen::Vector3d(1 + rho, 2, 3), 1e-14));
  // ṙ + A (ω × p_B) = (0.5, 0, 0) + Ω ρ A y_B, A y_B = z_W.
  EXPECT_TRUE(motion.v_W.isApprox(Eigen::Vector3d(0.5, 0, Omega * rho), 1e-14)) << motion.v_W.transpose();
  const Eigen::Vector3d expected = Eigen::Vector3d(0.1, -0.2, 0.3) + Eigen::Vector3d(-Omega * Omega * rho, 0, alpha * rho);
  EXPECT_LT((motion.a_W - expected).norm(), 1e-12 * Omega * Omega * rho) << motion.a_W.transpose();
}

// A free-free steel rod (1 m, 10 beams, 3 modes) at rest in ground, vibrating in mode i alone:
// η = η0 e_i, η̈ = −ω_i² η; a node's acceleration is −ω_i² times its displacement from the
// undeformed position (both through the probe: p_W at η and at 0).
TEST(AccelerationProbe, NodeOfAFlexibleRodInFreeVibration) {
  const fe::FeModel rod = testing::straight_rod(1.0, 10);
  ModelBuilder builder;
  builder.add_flexible_body(testing::flexible_spec("rod", rod, testing::normal_modes(rod, 3), ModalDamping::ratio(0.0)));
  AccelerationProbeSpec tip{"tip", "", "rod", Eigen::Vector3d::Zero(), 10};
  builder.add_acceleration_probe(tip);
  const Model model = builder.build();
  const FlexibleBody& flexible = *model.bodies[1].flexible;
  for (int i = 0; i < flexible.mode_count(); ++i) {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq), v = Eigen::VectorXd::Zero(model.nv), v_dot = v;
    q(3) = 1.0;  // identity quaternion
    FrameKinematics frame;
    const Eigen::Vector3d undeformed = probe_motion(model, model.acceleration_probes[0], q, v, v_dot, frame).p_W;
    const double eta0 = 1e-3, omega2 = flexible.stiffness(i);
    q(7 + i) = eta0;
    v_dot(6 + i) = -omega2 * eta0;
    const PointMotion motion = probe_motion(model, model.acceleration_probes[0], q, v, v_dot, frame);
    const Eigen::Vector3d expected = -omega2 * (motion.p_W - undeformed);
    // Round-off of the difference of positions (1e-16 m on 1 m) times ω_i² against the value.
    EXPECT_LT((motion.a_W - expected).norm(), 1e-9 * expected.norm()) << "mode " << i;
    EXPECT_GT(expected.norm(), 0.0);
  }
}

TEST(AccelerationProbe, BuilderRefusesBadPoints) {
  const fe::FeModel rod = testing::straight_rod(1.0, 4);
  ModelBuilder builder;
  builder.add_rigid_body(testing::body_spec("box", 1.0, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d::Zero()));
  builder.add_flexible_body(testing::flexible_spec("rod", rod, testing::normal_modes(rod, 2), ModalDamping::ratio(0.0)));
  builder.add_marker("m", "ground", Eigen::Vector3d::Zero());
  EXPECT_THROW(builder.add_acceleration_probe({"a", "", "nobody", Eigen::Vector3d::Zero(), -1}), InputError);
  EXPECT_THROW(builder.add_acceleration_probe({"a", "", "ground", Eigen::Vector3d::Zero(), -1}), InputError);
  EXPECT_THROW(builder.add_acceleration_probe({"a", "m", "", Eigen::Vector3d::Zero(), -1}), InputError);  // on ground
  EXPECT_THROW(builder.add_acceleration_probe({"a", "", "box", Eigen::Vector3d::Zero(), 2}), InputError);
  EXPECT_THROW(builder.add_acceleration_probe({"a", "", "rod", Eigen::Vector3d::Zero(), 5}), InputError);  // 5 nodes
  EXPECT_THROW(builder.add_acceleration_probe({"a", "", "rod", Eigen::Vector3d::Zero(), -1}), InputError);
  builder.add_acceleration_probe({"a", "", "rod", Eigen::Vector3d::Zero(), 4});
  EXPECT_THROW(builder.add_acceleration_probe({"a", "", "box", Eigen::Vector3d::Zero(), -1}), InputError);  // duplicate
}

}  // namespace
}  // namespace limber::multibody
