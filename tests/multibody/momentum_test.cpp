// The system momentum (momentum.h) of two free rigid bodies against the textbook sums
// P = Σ m v_c and L = Σ (r_c × m v_c + R I_c ω_B), worked out by hand below.
#include <numbers>

#include <gtest/gtest.h>

#include "multibody/momentum.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

TEST(SystemMomentum, TwoFreeRigidBodiesMatchTheSumsWorkedByHand) {
  ModelBuilder builder;
  // Body a: m = 2 kg, centre c = (0.1, 0, 0) in its frame, I_c = diag(1, 2, 3), at r = (1, 2, 3),
  // turned 90° about z, ṙ = (0.5, 0, 0), ω_B = (0, 0, 2).
  const Eigen::Matrix3d R = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  RigidBodySpec a = testing::body_spec("a", 2.0, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 3), R,
                                       Eigen::Vector3d(0.1, 0, 0));
  a.initial_velocity_W = Eigen::Vector3d(0.5, 0, 0);
  a.initial_angular_velocity_B = Eigen::Vector3d(0, 0, 2);
  // Body b: m = 1 kg, centre at its origin (0, 0, 0), I_c = I, ṙ = (0, 0, −1), ω_B = (1, 0, 0).
  RigidBodySpec b = testing::body_spec("b", 1.0, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d::Zero());
  b.initial_velocity_W = Eigen::Vector3d(0, 0, -1);
  b.initial_angular_velocity_B = Eigen::Vector3d(1, 0, 0);
  builder.add_rigid_body(a);
  builder.add_rigid_body(b);
  const Model model = builder.build();
  const Eigen::Matrix<double, 6, 1> h = system_momentum(model, initial_state(model));
  // a: ω_B × c = (0, 0.2, 0), turned: (−0.2, 0, 0); v_c = (0.3, 0, 0), P_a = (0.6, 0, 0);
  //    r_c = r + R c = (1, 2.1, 3); r_c × P_a = (0, 1.8, −1.26); R I_c ω_B = (0, 0, 6).
  // b: P_b = (0, 0, −1); r_c × P_b = 0; I ω_B = (1, 0, 0).
  Eigen::Matrix<double, 6, 1> expected;
  expected << 0.6, 0, -1, 1, 1.8, 4.74;
  // Rounding of a few products of O(1) numbers (the rotation's cos(π/2) ≈ 6e-17 included).
  EXPECT_LT((h - expected).cwiseAbs().maxCoeff(), 1e-12) << h.transpose();
}

}  // namespace
}  // namespace limber::multibody
