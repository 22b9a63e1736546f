// Quaternion kinematics: A(p) against axis-angle closed forms, the exp map against the
// kinematic equation ṗ = ½ L(p)ᵀ ω', and L(p) identities (Nikravesh 1988, §6.3).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "multibody/rotation.h"

namespace limber::multibody {
namespace {

// Rounding of a few dozen flops on O(1) numbers: 1e-14 is ~100 ulp.
constexpr double kRounding = 1e-14;

TEST(Rotation, MatrixOfAxisAngleMatchesRodrigues) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
  const double angle = 0.7;
  const Eigen::Matrix3d K = skew(axis);
  const Eigen::Matrix3d rodrigues =
      Eigen::Matrix3d::Identity() + std::sin(angle) * K + (1 - std::cos(angle)) * K * K;
  EXPECT_LT((axis_angle_matrix(axis, angle) - rodrigues).norm(), kRounding);
}

TEST(Rotation, LMatrixIdentities) {
  const Eigen::Vector4d p = Eigen::Vector4d(0.3, -0.4, 0.5, 0.2).normalized();
  const Eigen::Matrix<double, 3, 4> L = l_matrix(p);
  EXPECT_LT((L * L.transpose() - Eigen::Matrix3d::Identity()).norm(), kRounding);
  EXPECT_LT((L * p).norm(), kRounding);
}

TEST(Rotation, ExpMapFollowsKinematicEquation) {
  // p(t) = p0 ⊗ exp(ω' t) solves ṗ = ½ L(p)ᵀ ω' for constant body rate ω'.
  const Eigen::Vector4d p0 = Eigen::Vector4d(0.9, 0.1, -0.3, 0.2).normalized();
  const Eigen::Vector3d w(0.4, -1.1, 2.0);
  const double t = 0.37, h = 1e-5;
  auto p_at = [&](double s) { return quaternion_product(p0, quaternion_exp(w * s)); };
  const Eigen::Vector4d p_dot_fd = (p_at(t + h) - p_at(t - h)) / (2 * h);
  const Eigen::Vector4d p_dot = 0.5 * l_matrix(p_at(t)).transpose() * w;
  // Central difference error ~ h² |p⃛| ~ 1e-10 · |ω|³/8 ≈ 1e-10.
  EXPECT_LT((p_dot_fd - p_dot).norm(), 1e-9);
  // And the angular velocity in ground is A ω': Ȧ = A ω̃'.
  const Eigen::Matrix3d A_dot_fd = (rotation_matrix(p_at(t + h)) - rotation_matrix(p_at(t - h))) / (2 * h);
  EXPECT_LT((A_dot_fd - rotation_matrix(p_at(t)) * skew(w)).norm(), 1e-9);
}

TEST(Rotation, QuaternionFromMatrixRoundTrips) {
  // Angles near 0, π/2 and π exercise every branch of Shepperd's method.
  for (double angle : {0.0, 0.3, std::numbers::pi / 2, 3.0, std::numbers::pi}) {
    for (const Eigen::Vector3d& axis :
         {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1),
          Eigen::Vector3d(1, 2, 3).normalized()}) {
      const Eigen::Matrix3d R = axis_angle_matrix(axis, angle);
      EXPECT_LT((rotation_matrix(quaternion_from_matrix(R)) - R).norm(), 1e-13);
    }
  }
}

TEST(Rotation, FrameFromAxesIsRightHanded) {
  const Eigen::Matrix3d R = frame_from_axes(Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(1, 1, 0));
  EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), kRounding);
  EXPECT_NEAR(R.determinant(), 1.0, kRounding);
  EXPECT_LT((R.col(2) - Eigen::Vector3d::UnitZ()).norm(), kRounding);
}

}  // namespace
}  // namespace limber::multibody
