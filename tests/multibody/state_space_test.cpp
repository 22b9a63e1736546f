// The state-space model of a linearized mechanism (multibody/state_space.h) against hand
// models: a damped spring–mass on a slider (A's eigenvalues the roots of m s² + c s + k, the
// static gain −C A⁻¹ B the compliance 1/k, the acceleration's feedthrough 1/m), a body hinged
// to ground on a torsion spring driven by the RSDA's actuator torque and by a marker torque
// (±iω, gain 1/k), and a free-floating hinged pair (±iω of the relative rotation, twelve zero
// eigenvalues of the six rigid modes).
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include "multibody/assembly.h"
#include "multibody/linearization.h"
#include "multibody/redundancy.h"
#include "multibody/state_space.h"
#include "linear_test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;
using testing::marker_index;

// The assembled start's state-space model with `inputs` and `outputs`.
StateSpace linear_model(const Model& model, const std::vector<LinearInput>& inputs,
                        const std::vector<LinearOutput>& outputs) {
  State point = initial_state(model);
  Workspace ws(model);
  EXPECT_EQ(assemble_positions(model, point, ws).status, AssemblyStatus::kOk);
  const ConstraintPartition partition = analyse_redundancy(model, point, ws);
  TangentMatrices tangent;
  std::string message;
  EXPECT_EQ(tangent_matrices(model, partition, point, tangent, message), LinearizationStatus::kOk) << message;
  return state_space(model, point, tangent, null_space_basis(tangent.G, model.nv), inputs, outputs);
}

// A's eigenvalues, by increasing magnitude.
std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd& A) {
  const Eigen::VectorXcd s = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  std::vector<std::complex<double>> sorted(s.data(), s.data() + s.size());
  std::sort(sorted.begin(), sorted.end(), [](auto a, auto b) { return std::abs(a) < std::abs(b); });
  return sorted;
}

// Mass m on a translational joint along x, spring k and damper c to ground; force input and
// position, velocity, acceleration outputs at the mass's marker, ground axes. Hand model:
// m ẍ + c ẋ + k x = f_x: s = (−c ± i√(4km − c²)) / 2m, static gains x/f_x = 1/k, ẋ/f_x = 0,
// and the acceleration's feedthrough ẍ/f_x = 1/m at once; f_y, f_z go into the joint
// (zero gains). Tolerance 1e-9: the spring and damper are linear, the central differences exact
// to their rounding (1e-16/ε, ε = 1e-6, as the modes' test measures: 1.3e-11).
TEST(StateSpace, SpringMassHasItsRootsItsComplianceAndItsFeedthrough) {
  const double m = 4.0, k = 400.0, c = 8.0;
  const Model model = testing::spring_mass_on_slider(m, k, c);
  const int marker = marker_index(model, "S.mass");
  const StateSpace ss = linear_model(
      model, {{"push", LinearInputKind::kForce, marker, -1, ChannelAxes::kGround}},
      {{"x", LinearOutputKind::kPosition, marker, ChannelAxes::kGround},
       {"v", LinearOutputKind::kVelocity, marker, ChannelAxes::kGround},
       {"a", LinearOutputKind::kAcceleration, marker, ChannelAxes::kGround}});
  ASSERT_EQ(ss.A.rows(), 2);
  ASSERT_EQ(ss.B.cols(), 3);
  ASSERT_EQ(ss.C.rows(), 9);
  EXPECT_EQ(ss.input_names[0], "push.x");
  EXPECT_EQ(ss.output_names[6], "a.x");

  const std::vector<std::complex<double>> s = eigenvalues(ss.A);
  const std::complex<double> root(-c / (2 * m), std::sqrt(4 * k * m - c * c) / (2 * m));
  for (const auto& si : s) {
    EXPECT_NEAR(std::abs(si - (si.imag() > 0 ? root : std::conj(root))) / std::abs(root), 0.0, 1e-9) << si;
  }
  const Eigen::MatrixXd gain = -ss.C * ss.A.lu().solve(ss.B) + ss.D;
  EXPECT_NEAR(gain(0, 0) * k, 1.0, 1e-9);                               // x / f_x: the compliance
  EXPECT_NEAR(gain.block(3, 0, 3, 3).cwiseAbs().maxCoeff(), 0.0, 1e-9 / k);  // no steady velocity
  EXPECT_NEAR(gain.block(6, 0, 3, 3).cwiseAbs().maxCoeff(), 0.0, 1e-9 / m);  // nor acceleration
  EXPECT_NEAR(ss.D(6, 0) * m, 1.0, 1e-9);                                // ẍ = f/m at once
  for (int r = 0; r < 9; ++r) {
    for (int i = 1; i < 3; ++i) EXPECT_NEAR(gain(r, i), 0.0, 1e-9 / k) << r << " " << i;
  }
  // Only accelerations feed through.
  EXPECT_EQ(ss.D.topRows(6).cwiseAbs().maxCoeff(), 0.0);
}

// A disc hinged to ground about z through its centre, torsion spring k, inertia J about the
// axis: J θ̈ + k θ = τ, s = ±i√(k/J), static gain θ/τ = 1/k, for τ the RSDA's actuator
// torque (one channel) and for a torque at the disc's marker along ground z (three channels,
// x and y taken by the hinge); the rotation output's z channel in ground and in marker axes
// (the marker turned 90° about x: its y axis is ground z). Tolerance 1e-9 as above.
TEST(StateSpace, TorsionSpringHasItsFrequencyAndItsComplianceForBothTorqueInputs) {
  const double J = 0.5, k = 20.0;
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("disc", 3.0, Eigen::Vector3d(0.4, 0.45, J), Eigen::Vector3d::Zero()));
  builder.add_marker_at("H.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_marker_at("H.disc", "disc", Eigen::Vector3d::Zero());
  builder.add_joint("H", JointType::kRevolute, "H.ground", "H.disc");
  builder.add_rsda({"spring", "H.ground", "H.disc", k, 0.0, 0.0, {}, false, {}});
  const Eigen::Matrix3d R_turned = frame_from_axes(-Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
  builder.add_marker_at("rim", "disc", Eigen::Vector3d(0.3, 0, 0), R_turned);
  const Model model = builder.build();
  const int rim = marker_index(model, "rim");
  const StateSpace ss = linear_model(
      model,
      {{"motor", LinearInputKind::kRsdaTorque, -1, 0, ChannelAxes::kGround},
       {"torque", LinearInputKind::kTorque, rim, -1, ChannelAxes::kGround}},
      {{"turn", LinearOutputKind::kRotation, rim, ChannelAxes::kGround},
       {"turn_m", LinearOutputKind::kRotation, rim, ChannelAxes::kMarker},
       {"rim", LinearOutputKind::kPosition, rim, ChannelAxes::kGround}});
  ASSERT_EQ(ss.A.rows(), 2);
  ASSERT_EQ(ss.B.cols(), 4);
  const double w = std::sqrt(k / J);
  for (const auto& si : eigenvalues(ss.A)) {
    EXPECT_NEAR(si.real() / w, 0.0, 1e-9);
    EXPECT_NEAR(std::abs(si.imag()) / w, 1.0, 1e-9);
  }
  const Eigen::MatrixXd gain = -ss.C * ss.A.lu().solve(ss.B);
  for (const int input : {0, 3}) {          // motor; torque.z
    EXPECT_NEAR(gain(2, input) * k, 1.0, 1e-9) << input;   // turn.z
    EXPECT_NEAR(gain(4, input) * k, 1.0, 1e-9) << input;   // turn_m.y: ground z in marker axes
    EXPECT_NEAR(gain(7, input) * k, 0.3, 1e-9) << input;   // rim.y = r θ
  }
  EXPECT_NEAR(gain.col(1).cwiseAbs().maxCoeff(), 0.0, 1e-9 / k);  // torque.x, torque.y: the hinge's
  EXPECT_NEAR(gain.col(2).cwiseAbs().maxCoeff(), 0.0, 1e-9 / k);
}

// Two rigid bodies floating free, revolute through both centres of mass, torsion spring k:
// A (14 x 14) has the relative rotation's ±iω, ω = √(k (1/J1 + 1/J2)), and twelve eigenvalues
// at zero (six rigid modes, each a double root). Tolerance on ω 1e-8 (the modes' test
// measures 7e-11); the zeros: |s| below 1e-4 ω, the rigid-mode threshold of linearization.h
// (the differences' noise on K gives |s| ≈ 1e-5 ω at most).
TEST(StateSpace, FloatingHingedPairHasTheTorsionPairAndTwelveZeros) {
  const double J1 = 3.0, J2 = 0.5, k = 20.0;
  const StateSpace ss = linear_model(testing::floating_hinged_pair(J1, J2, k), {}, {});
  ASSERT_EQ(ss.A.rows(), 14);
  EXPECT_EQ(ss.B.cols(), 0);
  EXPECT_EQ(ss.C.rows(), 0);
  const double w = std::sqrt(k * (1.0 / J1 + 1.0 / J2));
  const std::vector<std::complex<double>> s = eigenvalues(ss.A);
  for (int i = 0; i < 12; ++i) EXPECT_LT(std::abs(s[static_cast<std::size_t>(i)]), 1e-4 * w) << i;
  for (int i = 12; i < 14; ++i) {
    EXPECT_NEAR(s[static_cast<std::size_t>(i)].real() / w, 0.0, 1e-8);
    EXPECT_NEAR(std::abs(s[static_cast<std::size_t>(i)].imag()) / w, 1.0, 1e-8);
  }
}

}  // namespace
}  // namespace limber::multibody
