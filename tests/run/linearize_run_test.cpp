// `limber linearize`'s library (run/linearize_run.h) on case files: bad input named (a
// reference body the case lacks, a singular linearization point), and the stowed satellite's
// system modes, mass properties and modes with the bus held, whose hybrid-coordinate model
// reproduces the free spacecraft's frequencies.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <numbers>

#include <cmath>
#include <complex>
#include <string>

#include "core/error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/linearize_reader.h"
#include "io/mechanism_builder.h"
#include "../multibody/test_models.h"
#include "multibody/model_builder.h"
#include "multibody/rotation.h"
#include "run/linearize_at.h"
#include "run/linearize_run.h"

namespace limber::run {
namespace {

io::Mechanism build(const std::string& path) {
  const io::Case input = io::read_case_file(path);
  return io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
}

// A --reference-body that names no moving body: InputError listing the bodies there are.
TEST(LinearizeRun, UnknownReferenceBodyIsAnInputErrorNamingTheBodies) {
  const io::Mechanism m = build(std::string(LIMBER_CASES_DIR) + "/four_bar.yaml");
  LinearizeSettings settings;
  settings.reference_body = "no_such_body";
  try {
    linearize_mechanism(m.model, m.assembly, settings);
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("got 'no_such_body'"), std::string::npos) << text;
    EXPECT_NE(text.find(m.model.bodies[1].name), std::string::npos) << text;
  }
}

// The parallelogram assembled at its singular configuration: a failure named, no modes, no NaN.
TEST(LinearizeRun, SingularLinearizationPointIsNamed) {
  const io::Mechanism m = build(std::string(LIMBER_TEST_DATA_DIR) + "/parallelogram_singular_start.yaml");
  const LinearizeSummary s = linearize_mechanism(m.model, m.assembly, {});
  EXPECT_FALSE(s.ok);
  EXPECT_EQ(s.failure, "singular start");
  EXPECT_NE(s.message.find("constraints are singular at the linearization point: equation(s) R"), std::string::npos)
      << s.message;
  EXPECT_EQ(s.modes.frequencies_hz.size(), 0);
}

// The stowed satellite about its static equilibrium, bus held: six rigid modes of the free
// spacecraft; every number finite; the whole spacecraft's mass the sum of the bodies' (bus
// 400 kg and four panels); effective masses never above the totals about the bus CoM.
TEST(LinearizeRun, StowedSatelliteHasSixRigidModesAndConsistentMassProperties) {
  const io::Mechanism m = build(std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml");
  LinearizeSettings settings;
  settings.statics = true;
  settings.reference_body = "bus";
  const LinearizeSummary s = linearize_mechanism(m.model, m.assembly, settings);
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_EQ(s.modes.rigid_modes, 6);
  EXPECT_EQ(s.modes.unstable_modes, 0);
  EXPECT_TRUE(s.modes.frequencies_hz.allFinite() && s.modes.damping.allFinite());
  double mass = 0.0;
  for (const multibody::Body& body : m.model.bodies) mass += body.mass;
  // Flexible bodies' mass is their undeformed invariant: equal to rounding (1e-12).
  EXPECT_NEAR(s.mass.mass / mass, 1.0, 1e-12);
  ASSERT_TRUE(s.cantilevered.has_value());
  const multibody::CantileveredModes& c = *s.cantilevered;
  EXPECT_EQ(c.modes.frequencies_hz.size() + 6, s.modes.frequencies_hz.size());
  for (int d = 0; d < 6; ++d) EXPECT_LE(c.effective_sum(d), c.appendage_mass(d, d) * (1.0 + 1e-12)) << d;
  EXPECT_LT(c.largest_constraint_rate, 1e-9);

  // Second method: the hybrid-coordinate model rebuilt from the spacecraft data alone, mass
  // [M_rr Lᵀ; L I] and stiffness diag(0, ω_c²) (Likins; Hughes ch. 10), has the free system's
  // undamped frequencies: the held modes and the bus-driven rigid motions Ψ span the same
  // motions (G Ψ = 0 above), and Ψ meets no stiffness on a floating spacecraft: a change of
  // basis. Tolerance 1e-9 relative: what differs is only K Ψ, zero up to the differences'
  // rounding (~1e-10 of K's entries), which moves the elastic ω² at second order; measured
  // ≤ 1e-14 on all 16 modes.
  const int n = static_cast<int>(c.modes.frequencies_hz.size());
  Eigen::MatrixXd M_h = Eigen::MatrixXd::Identity(6 + n, 6 + n), K_h = Eigen::MatrixXd::Zero(6 + n, 6 + n);
  M_h.topLeftCorner(6, 6) = c.rigid_mass;
  M_h.bottomLeftCorner(n, 6) = c.participation;
  M_h.topRightCorner(6, n) = c.participation.transpose();
  for (int i = 0; i < n; ++i) K_h(6 + i, 6 + i) = std::pow(2.0 * std::numbers::pi * c.modes.undamped_hz(i), 2);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> hybrid(K_h, M_h, Eigen::EigenvaluesOnly);
  for (int i = 0; i < n; ++i) {
    const double f_hybrid = std::sqrt(hybrid.eigenvalues()(6 + i)) / (2.0 * std::numbers::pi);
    EXPECT_NEAR(f_hybrid / s.modes.undamped_hz(6 + i), 1.0, 1e-9) << "mode " << 6 + i;
  }
}

// The stowed satellite's plant (cases/satellite_linearized.yaml, about its statics) against
// Euler's equations of the whole spacecraft: at frequencies far below the elastic modes
// (ω = 0.01 rad/s against 813 rad/s) a torque τ on the bus spins the whole, so the bus rate
// from the wheels' torque is G(s) → I⁻¹ / s with I the spacecraft's inertia about its centre
// of mass (summary.mass; bus axes are ground axes here), and the hinge motor, an internal
// torque on a wing the hold-downs lock, leaves no rate: s G(s) → 0. Tolerance 1e-4 relative:
// the rigid roots' noise (|s| ≤ 4e-5 rad/s) enters as (4e-5 / 0.01)² = 2e-5, the elastic modes
// as (0.01 / 813)² (and the hinge motor's as s² times a compliance). Measured: 5.4e-6 and
// 3.6e-12.
TEST(LinearizeRun, StowedSatellitePlantSpinsByEulersEquationAtLowFrequency) {
  const io::Case input = io::read_case_file(std::string(LIMBER_CASES_DIR) + "/satellite_linearized.yaml");
  const io::Mechanism m = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  LinearizeSettings settings;
  settings.statics = true;
  settings.inputs = io::linear_inputs(input.mechanism->linearize, m.model);
  settings.outputs = io::linear_outputs(input.mechanism->linearize, m.model);
  const LinearizeSummary s = linearize_mechanism(m.model, m.assembly, settings);
  ASSERT_TRUE(s.ok) << s.message;
  const multibody::StateSpace& ss = s.state_space;
  ASSERT_EQ(ss.input_names[3], "hinge_motor");
  ASSERT_EQ(ss.output_names[3], "rate.x");
  const std::complex<double> jw(0.0, 0.01);
  const Eigen::MatrixXcd sI_A = jw * Eigen::MatrixXcd::Identity(ss.A.rows(), ss.A.cols()) - ss.A.cast<std::complex<double>>();
  const Eigen::MatrixXcd sG =
      jw * ss.C.cast<std::complex<double>>() * sI_A.partialPivLu().solve(ss.B.cast<std::complex<double>>());
  const Eigen::Matrix3d I_inv = s.mass.inertia_com_W.inverse();
  const Eigen::Matrix3cd rate_from_wheels = sG.block(3, 0, 3, 3);
  EXPECT_LT((rate_from_wheels - I_inv.cast<std::complex<double>>()).norm() / I_inv.norm(), 1e-4);
  EXPECT_LT(sG.block(3, 3, 3, 1).norm() / I_inv.norm(), 1e-4);
}

// --at T: a pendulum with a hinge damper, released 0.3 rad from hanging and run for 12 s until
// it has settled (ζ = 0.2 at ω = 4.3 rad/s: amplitude 0.3 e^(−0.2·4.3·12) ≈ 1e-5 rad), then
// linearized there: the hanging pendulum's f = √(m g l / J_pivot)/2π and ζ = c/(2 J_pivot ω).
// Tolerance 1e-6 relative: the state at T is off the equilibrium by ~1e-5 rad and moving
// (2e-6 rad/s); the frequency depends on the angle at second order (1e-10), M v̇0 and the
// velocity terms at first order in the residual motion's effect on forces (measured 3.5e-10).
TEST(LinearizeRun, AtTimeTLinearizesAboutTheStateTheRunReaches) {
  using multibody::testing::body_spec;
  const double m = 2.0, l = 0.5, g = 9.81, Jy = 0.2, J = Jy + m * l * l;
  const double w = std::sqrt(m * g * l / J), c = 2.0 * 0.2 * J * w;
  multibody::ModelBuilder builder;
  builder.set_gravity(Eigen::Vector3d(0, 0, -g));
  const double a = 0.3;  // initial angle about y, centre of mass swung towards −x
  builder.add_rigid_body(body_spec("bob", m, Eigen::Vector3d(0.1, Jy, 0.1), Eigen::Vector3d::Zero(),
                                   multibody::axis_angle_matrix(Eigen::Vector3d::UnitY(), a),
                                   Eigen::Vector3d(0, 0, -l)));
  const Eigen::Matrix3d R_y = multibody::frame_from_axes(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
  builder.add_marker_at("P.ground", "ground", Eigen::Vector3d::Zero(), R_y);
  builder.add_marker_at("P.bob", "bob", Eigen::Vector3d::Zero(), R_y);
  builder.add_joint("P", multibody::JointType::kRevolute, "P.ground", "P.bob");
  builder.add_rsda({"damper", "P.ground", "P.bob", 0.0, c, 0.0, {}, false, {}});
  const multibody::Model model = builder.build();
  io::RunSettings run;
  run.t_end = 12.0;
  run.sample_interval = 0.5;
  run.integrator.rtol = 1e-8;
  run.integrator.atol = 1e-10;
  const LinearizeSummary s = linearize_at(model, {}, run, 12.0, {});
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_DOUBLE_EQ(s.point.t, 12.0);
  ASSERT_EQ(s.free_motions, 1);
  EXPECT_NEAR(s.modes.frequencies_hz(0) / (w / (2.0 * std::numbers::pi)), 1.0, 1e-6);
  EXPECT_NEAR(s.modes.damping(0) / 0.2, 1.0, 1e-6);
  // Beyond the run, or not after its start: bad input.
  EXPECT_THROW(linearize_at(model, {}, run, 12.5, {}), InputError);
  EXPECT_THROW(linearize_at(model, {}, run, 0.0, {}), InputError);
}

// The same pendulum at T = 1 s, still swinging (≈ 0.1 rad): about that state in motion the
// linearization is indicative only (M v̇0 ≠ 0 and the velocity terms frozen at one instant);
// with statics (--at T --statics) it is about the hanging equilibrium reached from there, the
// bob straight below the pivot, and the closed form holds again. Tolerance 1e-8 as about the
// equilibrium at t = 0 (Linearization.PendulumAboutItsHangingEquilibrium...): statics converges
// to 1e-9 of the forces, the differences are exact to 1e-10.
TEST(LinearizeRun, AtTimeTWithStaticsLinearizesAboutTheEquilibriumReachedFromThere) {
  using multibody::testing::body_spec;
  const double m = 2.0, l = 0.5, g = 9.81, Jy = 0.2, J = Jy + m * l * l;
  const double w = std::sqrt(m * g * l / J), c = 2.0 * 0.2 * J * w;
  multibody::ModelBuilder builder;
  builder.set_gravity(Eigen::Vector3d(0, 0, -g));
  builder.add_rigid_body(body_spec("bob", m, Eigen::Vector3d(0.1, Jy, 0.1), Eigen::Vector3d::Zero(),
                                   multibody::axis_angle_matrix(Eigen::Vector3d::UnitY(), 0.3),
                                   Eigen::Vector3d(0, 0, -l)));
  const Eigen::Matrix3d R_y = multibody::frame_from_axes(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
  builder.add_marker_at("P.ground", "ground", Eigen::Vector3d::Zero(), R_y);
  builder.add_marker_at("P.bob", "bob", Eigen::Vector3d::Zero(), R_y);
  builder.add_joint("P", multibody::JointType::kRevolute, "P.ground", "P.bob");
  builder.add_rsda({"damper", "P.ground", "P.bob", 0.0, c, 0.0, {}, false, {}});
  const multibody::Model model = builder.build();
  io::RunSettings run;
  run.t_end = 2.0;
  run.sample_interval = 0.5;
  run.integrator.rtol = 1e-8;
  run.integrator.atol = 1e-10;
  LinearizeSettings settings;
  settings.statics = true;
  const LinearizeSummary s = linearize_at(model, {}, run, 1.0, settings);
  ASSERT_TRUE(s.ok) << s.message;
  ASSERT_TRUE(s.statics.has_value());
  EXPECT_STREQ(linearization_point_kind(s), "statics");
  EXPECT_DOUBLE_EQ(s.at, 1.0);
  EXPECT_LT(s.point.v.norm(), 1e-15);
  // The bob hangs straight below the pivot: its orientation is the identity.
  EXPECT_LT((multibody::rotation_matrix(s.point.q.segment<4>(3)) - Eigen::Matrix3d::Identity()).norm(), 1e-9);
  ASSERT_EQ(s.free_motions, 1);
  EXPECT_NEAR(s.modes.frequencies_hz(0) / (w / (2.0 * std::numbers::pi)), 1.0, 1e-8);
  EXPECT_NEAR(s.modes.damping(0) / 0.2, 1.0, 1e-8);
  // The snapshot in motion at the same instant is off by far more.
  const LinearizeSummary moving = linearize_at(model, {}, run, 1.0, {});
  ASSERT_TRUE(moving.ok) << moving.message;
  EXPECT_GT(std::abs(moving.modes.frequencies_hz(0) / (w / (2.0 * std::numbers::pi)) - 1.0), 1e-4);
}

// A disc on a hinge about z driven by a preloaded spring (k_s, free angle 3 rad) into a latch at
// 1 rad (k_L, c_L, damping_depth d): it latches at ~3.2 rad/s, overshoots the depth d by far
// (≈ 0.07 rad) and so seats, its damping in full from then on (hinge_limit.h), then rings down
// to the preload's penetration k_s (3 − 1) / k_L = 2e-3 rad, a fifth of d. Linearized at 10 s the
// locked hinge is the closed form ω² = (k_L + k_s)/J, ζ = c_L / (2 √((k_L + k_s) J)); a latch
// left in its unseated mode (the run does not report seating as an event) would give the
// damping's share at 2e-3 rad instead, 0.104 of it. Tolerance 1e-6: the ringing has decayed by
// e^-18 at 10 s, so the point is the equilibrium to that.
TEST(LinearizeRun, AtTimeTALatchThatSeatedKeepsItsFullDamping) {
  using multibody::testing::body_spec;
  const double J = 0.5, k_s = 1.0, k_L = 1000.0, c_L = 2.0, d = 1e-2;
  multibody::ModelBuilder builder;
  builder.add_rigid_body(body_spec("disc", 1.0, Eigen::Vector3d(0.3, 0.3, J), Eigen::Vector3d::Zero()));
  builder.add_marker_at("H.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_marker_at("H.disc", "disc", Eigen::Vector3d::Zero());
  builder.add_joint("H", multibody::JointType::kRevolute, "H.ground", "H.disc");
  builder.add_rsda({"spring", "H.ground", "H.disc", k_s, 0.0, 3.0, {}, false, {}});
  builder.add_hinge_limit({"latch", "H", multibody::HingeLimitKind::kLatch, 1.0, k_L, c_L, d});
  const multibody::Model model = builder.build();
  io::RunSettings run;
  run.t_end = 10.0;
  run.sample_interval = 1e-2;
  run.integrator.rtol = 1e-8;
  run.integrator.atol = 1e-10;
  const LinearizeSummary s = linearize_at(model, {}, run, 10.0, {});
  ASSERT_TRUE(s.ok) << s.message;
  ASSERT_EQ(s.free_motions, 1);
  const double w = std::sqrt((k_L + k_s) / J);
  EXPECT_NEAR(s.modes.frequencies_hz(0) / (w / (2.0 * std::numbers::pi)), 1.0, 1e-6);
  EXPECT_NEAR(s.modes.damping(0) / (c_L / (2.0 * std::sqrt((k_L + k_s) * J))), 1.0, 1e-6);
}

}  // namespace
}  // namespace limber::run
