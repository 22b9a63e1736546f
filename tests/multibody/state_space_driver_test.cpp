// Driver efforts as inputs of the state-space model (multibody/state_space.h): the driver is
// released and its effort's deviation drives its coordinate. Against hand models: a driven
// disc on a preloaded torsion spring and damper (angle / effort = 1/(J s² + c s + k)), a
// driven slider on a preloaded spring (displacement / effort = 1/(m s² + c s + k)), a
// free-floating hinged pair (relative angle / effort = 1/(J_r s² + k), J_r = J1 J2/(J1 + J2),
// no angular momentum), and two drivers on one coordinate, which no effort input can release.
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include "core/error.h"
#include "multibody/assembly.h"
#include "multibody/linearization.h"
#include "multibody/redundancy.h"
#include "multibody/state_space.h"
#include "linear_test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;
using testing::marker_index;

struct Linear {
  TangentMatrices tangent;
  Eigen::MatrixXd Z;  // the joints' free motions, drivers held
  StateSpace ss;
};

// The assembled start, linearized, with `inputs` and `outputs`.
Linear linearize(const Model& model, const std::vector<LinearInput>& inputs, const std::vector<LinearOutput>& outputs) {
  State point = initial_state(model);
  Workspace ws(model);
  EXPECT_EQ(assemble_positions(model, point, ws).status, AssemblyStatus::kOk);
  const ConstraintPartition partition = analyse_redundancy(model, point, ws);
  Linear out;
  std::string message;
  EXPECT_EQ(tangent_matrices(model, partition, point, out.tangent, message), LinearizationStatus::kOk) << message;
  out.Z = null_space_basis(out.tangent.G, model.nv);
  out.ss = state_space(model, point, out.tangent, out.Z, inputs, outputs);
  return out;
}

// The transfer matrix C (sI − A)⁻¹ B + D at s.
Eigen::MatrixXcd transfer(const StateSpace& ss, std::complex<double> s) {
  const Eigen::Index n = ss.A.rows();
  const Eigen::MatrixXcd sI_A = s * Eigen::MatrixXcd::Identity(n, n) - ss.A.cast<std::complex<double>>();
  return ss.C.cast<std::complex<double>>() * sI_A.partialPivLu().solve(ss.B.cast<std::complex<double>>()) +
         ss.D.cast<std::complex<double>>();
}

LinearInput effort(const std::string& name, int driver) {
  LinearInput input{name, LinearInputKind::kDriverEffort};
  input.driver = driver;
  return input;
}

// A disc of inertia J about z hinged to ground at its centre (H), a torsion spring k and damper
// c whose free angle is 0.2 rad, and a driver holding the hinge at 0: the driver's effort there
// is the spring's preload, −λ0 = −k 0.2 (reactions.h: effort = −λ, on the disc about z). Held,
// the disc has no free motion; released, J θ̈ + c θ̇ + k θ = u, the effort's deviation, so
// θ/u = 1/(J s² + c s + k) at every s and the rim (r = 0.3 m) moves r θ along y.
// Compared as u/θ against J s² + c s + k, relative to its largest term J|s|² + k (at resonance
// θ/u itself is 1/(c s): J s² + k cancels, and a rounding of K would show amplified by 1/2ζ).
// Tolerance 1e-9: the spring and damper are linear, the differences exact to their rounding
// (1e-16/ε, ε = 1e-6: the spring–mass modes' test measures 1.3e-11).
TEST(StateSpaceDriverEffort, DrivenDiscFollowsItsInertiaDamperAndSpring) {
  const double J = 0.5, c = 0.3, k = 20.0, preload_angle = 0.2, r = 0.3;
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("disc", 3.0, Eigen::Vector3d(0.4, 0.45, J), Eigen::Vector3d::Zero()));
  builder.add_marker_at("H.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_marker_at("H.disc", "disc", Eigen::Vector3d::Zero());
  builder.add_joint("H", JointType::kRevolute, "H.ground", "H.disc");
  builder.add_rsda({"spring", "H.ground", "H.disc", k, c, preload_angle, {}, false, {}});
  builder.add_driver("drive", "H", DriverCoordinate::kRotation, TimeFunction::constant(0.0));
  builder.add_marker_at("rim", "disc", Eigen::Vector3d(r, 0, 0));
  const Model model = builder.build();
  const int rim = marker_index(model, "rim");
  const Linear lin = linearize(model, {effort("motor", 0)},
                               {{"turn", LinearOutputKind::kRotation, rim, ChannelAxes::kGround},
                                {"rim", LinearOutputKind::kPosition, rim, ChannelAxes::kGround}});
  // Held: nothing moves; the effort at the point is the preload.
  EXPECT_EQ(lin.Z.cols(), 0);
  const int driver_row = model.drivers[0].row;
  const auto position = std::find(lin.tangent.rows.begin(), lin.tangent.rows.end(), driver_row) - lin.tangent.rows.begin();
  EXPECT_NEAR(-lin.tangent.lambda(position), -k * preload_angle, 1e-9 * k);
  // Released: one free motion, the roots of J s² + c s + k.
  ASSERT_EQ(lin.ss.A.rows(), 2);
  ASSERT_EQ(lin.ss.B.cols(), 1);
  EXPECT_EQ(lin.ss.input_names[0], "motor");
  EXPECT_EQ(lin.ss.Z.cols(), 1);
  const double w = std::sqrt(k / J);
  const std::complex<double> root(-c / (2 * J), std::sqrt(4 * k * J - c * c) / (2 * J));
  const Eigen::VectorXcd s = Eigen::EigenSolver<Eigen::MatrixXd>(lin.ss.A, false).eigenvalues();
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    EXPECT_NEAR(std::abs(s(i) - (s(i).imag() > 0 ? root : std::conj(root))) / w, 0.0, 1e-9) << s(i);
  }
  // The transfer at rest, below, near and above resonance, and on the real axis.
  for (const std::complex<double> si : {std::complex<double>(0.0, 0.0), std::complex<double>(0.0, 0.5 * w),
                                        std::complex<double>(0.0, w), std::complex<double>(0.0, 3.0 * w),
                                        std::complex<double>(1.3 * w, 0.0)}) {
    const Eigen::MatrixXcd G = transfer(lin.ss, si);
    const std::complex<double> turn = G(2, 0);  // turn.z
    EXPECT_NEAR(std::abs(1.0 / turn - (J * si * si + c * si + k)) / (J * std::norm(si) + k), 0.0, 1e-9) << si;
    EXPECT_NEAR(std::abs(G(4, 0) - r * turn) / std::abs(turn), 0.0, 1e-9) << si;          // rim.y = r θ
    EXPECT_NEAR(std::abs(G(0, 0)) + std::abs(G(1, 0)), 0.0, 1e-9 * std::abs(turn)) << si;  // the hinge's
  }
}

// A mass m on a translational joint along ground x, a spring k (stretched 0.1 m: preloaded)
// and damper c to ground, a driver holding the slide at 0: released, m ẍ + c ẋ + k x = u, the
// force along the joint's axis, x/u = 1/(m s² + c s + k). Tolerance 1e-9 as above.
TEST(StateSpaceDriverEffort, DrivenSliderFollowsItsMassDamperAndSpring) {
  const double m = 4.0, c = 8.0, k = 400.0;
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("mass", m, Eigen::Vector3d(0.1, 0.1, 0.1), Eigen::Vector3d(1, 0, 0)));
  const Eigen::Matrix3d R_x = frame_from_axes(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
  builder.add_marker_at("T.ground", "ground", Eigen::Vector3d(1, 0, 0), R_x);
  builder.add_marker_at("T.mass", "mass", Eigen::Vector3d(1, 0, 0), R_x);
  builder.add_joint("T", JointType::kTranslational, "T.ground", "T.mass");
  builder.add_marker_at("S.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_marker_at("S.mass", "mass", Eigen::Vector3d(1, 0, 0));
  builder.add_tsda({"spring", "S.ground", "S.mass", k, c, 0.9, {}});
  builder.add_driver("slide", "T", DriverCoordinate::kTranslation, TimeFunction::constant(0.0));
  const Model model = builder.build();
  const int marker = marker_index(model, "S.mass");
  const Linear lin =
      linearize(model, {effort("push", 0)}, {{"x", LinearOutputKind::kPosition, marker, ChannelAxes::kGround}});
  EXPECT_EQ(lin.Z.cols(), 0);
  ASSERT_EQ(lin.ss.A.rows(), 2);
  const double w = std::sqrt(k / m);
  for (const std::complex<double> si : {std::complex<double>(0.0, 0.0), std::complex<double>(0.0, 0.7 * w),
                                        std::complex<double>(0.0, 2.0 * w), std::complex<double>(0.5 * w, 0.0)}) {
    const Eigen::MatrixXcd G = transfer(lin.ss, si);
    EXPECT_NEAR(std::abs(1.0 / G(0, 0) - (m * si * si + c * si + k)) / (m * std::norm(si) + k), 0.0, 1e-9) << si;
    EXPECT_NEAR(std::abs(G(1, 0)) + std::abs(G(2, 0)), 0.0, 1e-9 * std::abs(G(0, 0))) << si;
  }
}

// The free-floating hinged pair (bus J1, panel J2 about the hinge axis z through both centres
// of mass, spring k) with a driver on the hinge: released, the effort is an internal torque,
// +u on the panel and −u on the bus, so the relative angle follows 1/(J_r s² + k) with
// J_r = J1 J2/(J1 + J2), and the angular momentum J1 θ_bus + J2 θ_panel stays zero. Held,
// the pair moves as one rigid body (6 free motions); released, 7, and A (14 x 14) has the
// torsion pair. Tolerance 1e-8, as the pair's modes test (it measures 7e-11).
TEST(StateSpaceDriverEffort, FloatingPairTurnsAboutItsHingeWithTheReducedInertia) {
  const double J1 = 3.0, J2 = 0.5, k = 20.0;
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("bus", 50.0, Eigen::Vector3d(4.0, 5.0, J1), Eigen::Vector3d::Zero()));
  builder.add_rigid_body(body_spec("panel", 2.0, Eigen::Vector3d(0.7, 0.9, J2), Eigen::Vector3d(0, 0, 1.0)));
  builder.add_marker_at("H.bus", "bus", Eigen::Vector3d(0, 0, 0.5));
  builder.add_marker_at("H.panel", "panel", Eigen::Vector3d(0, 0, 0.5));
  builder.add_joint("H", JointType::kRevolute, "H.bus", "H.panel");
  builder.add_rsda({"spring", "H.bus", "H.panel", k, 0.0, 0.0, {}, false, {}});
  builder.add_driver("hinge_drive", "H", DriverCoordinate::kRotation, TimeFunction::constant(0.0));
  const Model model = builder.build();
  const int bus = marker_index(model, "H.bus"), panel = marker_index(model, "H.panel");
  const Linear lin = linearize(model, {effort("hinge_motor", 0)},
                               {{"bus", LinearOutputKind::kRotation, bus, ChannelAxes::kGround},
                                {"panel", LinearOutputKind::kRotation, panel, ChannelAxes::kGround}});
  EXPECT_EQ(lin.Z.cols(), 6);
  ASSERT_EQ(lin.ss.A.rows(), 14);
  const double J_r = J1 * J2 / (J1 + J2), w = std::sqrt(k / J_r);
  for (const std::complex<double> si : {std::complex<double>(0.0, 0.4 * w), std::complex<double>(0.0, 2.5 * w),
                                        std::complex<double>(0.8 * w, 0.0)}) {
    const Eigen::MatrixXcd G = transfer(lin.ss, si);
    const std::complex<double> relative = G(5, 0) - G(2, 0);  // panel.z − bus.z
    EXPECT_NEAR(std::abs(1.0 / relative - (J_r * si * si + k)) / (J_r * std::norm(si) + k), 0.0, 1e-8) << si;
    EXPECT_NEAR(std::abs(J1 * G(2, 0) + J2 * G(5, 0)) / (J_r * std::abs(relative)), 0.0, 1e-8) << si;
  }
}

// Two revolutes on one axis between ground and a disc, each driven to 0: the coordinate is
// held twice, one driver equation is redundant, and releasing either leaves the other holding
// it. Neither effort can be an input: InputError naming the input and the driver.
TEST(StateSpaceDriverEffort, ADriverSharingItsCoordinateIsNamed) {
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("disc", 3.0, Eigen::Vector3d(0.4, 0.45, 0.5), Eigen::Vector3d::Zero()));
  builder.add_marker_at("A.ground", "ground", Eigen::Vector3d(0, 0, -0.2));
  builder.add_marker_at("A.disc", "disc", Eigen::Vector3d(0, 0, -0.2));
  builder.add_joint("A", JointType::kRevolute, "A.ground", "A.disc");
  builder.add_marker_at("B.ground", "ground", Eigen::Vector3d(0, 0, 0.2));
  builder.add_marker_at("B.disc", "disc", Eigen::Vector3d(0, 0, 0.2));
  builder.add_joint("B", JointType::kRevolute, "B.ground", "B.disc");
  builder.add_driver("drive_A", "A", DriverCoordinate::kRotation, TimeFunction::constant(0.0));
  builder.add_driver("drive_B", "B", DriverCoordinate::kRotation, TimeFunction::constant(0.0));
  const Model model = builder.build();
  for (int d = 0; d < 2; ++d) {
    const std::string name = model.drivers[static_cast<std::size_t>(d)].name;
    try {
      linearize(model, {effort("torque", d)}, {});
      ADD_FAILURE() << "no error for " << name;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("linearize input 'torque'"), std::string::npos) << what;
      EXPECT_NE(what.find("got '" + name + "'"), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace limber::multibody
