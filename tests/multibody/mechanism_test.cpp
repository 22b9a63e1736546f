// Closed-loop mechanisms: assembly of a four-bar from perturbed positions, a failing
// assembly, and the seed slider-crank (redundant 3D model vs closed form and vs a
// non-redundant model).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "multibody/assembly.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/evaluated.h"
#include "multibody/momentum.h"
#include "multibody/reactions.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;

// Planar four-bar in ground x-y (axes z): A = (0,0), D = (d,0), crank AB = a at φ,
// coupler BC = b, rocker DC = c. Bodies start at the exact poses rotated/shifted by
// `perturbation` (m and rad), except the crank.
struct FourBar {
  double a = 0.4, b = 1.2, c = 0.8, d = 1.0, phi = 0.9;
};

Eigen::Vector2d four_bar_point_c(const FourBar& f) {
  // Circle intersection |C − B| = b, |C − D| = c, the branch above the line BD.
  const Eigen::Vector2d B(f.a * std::cos(f.phi), f.a * std::sin(f.phi)), D(f.d, 0);
  const double l = (D - B).norm();
  const double along = (f.b * f.b - f.c * f.c + l * l) / (2 * l);
  const double h = std::sqrt(f.b * f.b - along * along);
  const Eigen::Vector2d u = (D - B) / l;
  return B + along * u + h * Eigen::Vector2d(-u.y(), u.x());
}

Model four_bar(const FourBar& f, double perturbation) {
  ModelBuilder builder;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector2d C2 = four_bar_point_c(f);
  const Eigen::Vector3d A(0, 0, 0), B(f.a * std::cos(f.phi), f.a * std::sin(f.phi), 0), C(C2.x(), C2.y(), 0),
      D(f.d, 0, 0);
  auto link = [&](const std::string& name, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double delta) {
    const Eigen::Vector3d e = (q - p).normalized();
    Eigen::Matrix3d R;
    R << e, z.cross(e), z;
    builder.add_rigid_body(body_spec(name, 1.0, testing::rod_inertia(1.0, (q - p).norm()), 0.5 * (p + q) + delta * Eigen::Vector3d(1, -1, 0.5),
                                     axis_angle_matrix(Eigen::Vector3d(0.3, 0.2, 1), delta) * R));
  };
  link("crank", A, B, 0.0);
  link("coupler", B, C, perturbation);
  link("rocker", D, C, -perturbation);
  // Markers placed with the exact geometry on the exact bodies, then bodies perturbed:
  // markers are given in body frames computed from the exact poses.
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  auto marker = [&](const std::string& name, const std::string& body, const Eigen::Vector3d& p_W,
                    const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    const Eigen::Vector3d e = (to - from).normalized();
    Eigen::Matrix3d R;
    R << e, z.cross(e), z;
    builder.add_marker(name, body, R.transpose() * (p_W - 0.5 * (from + to)), R.transpose() * I);
  };
  builder.add_marker("A.ground", "ground", A);
  marker("A.crank", "crank", A, A, B);
  marker("B.crank", "crank", B, A, B);
  marker("B.coupler", "coupler", B, B, C);
  marker("C.coupler", "coupler", C, B, C);
  marker("C.rocker", "rocker", C, D, C);
  marker("D.rocker", "rocker", D, D, C);
  builder.add_marker("D.ground", "ground", D);
  builder.add_joint("A", JointType::kRevolute, "A.ground", "A.crank");
  builder.add_joint("B", JointType::kRevolute, "B.crank", "B.coupler");
  builder.add_joint("C", JointType::kRevolute, "C.coupler", "C.rocker");
  builder.add_joint("D", JointType::kRevolute, "D.ground", "D.rocker");
  return builder.build();
}

TEST(Assembly, FourBarFromPerturbedPositions) {
  // Crank angle held (rotation about its body z); the assembled rocker point C must be
  // the circle intersection. Newton converges quadratically to 1e-12, so positions are
  // exact to ~1e-12 m.
  const FourBar f;
  const Model model = four_bar(f, 0.05);
  Workspace ws(model);
  State state = initial_state(model);
  AssemblyOptions options;
  options.tolerance = 1e-12;
  options.held.push_back({model.find_body("crank"), 5});
  const AssemblyResult result = assemble_positions(model, state, ws, options);
  ASSERT_EQ(result.status, AssemblyStatus::kOk) << result.message;
  EXPECT_LE(result.iterations, 8);
  // Holding a velocity direction keeps the crank angle to second order in the
  // intermediate steps (rotations do not commute): φ moves by < 1e-8 rad.
  const Eigen::Vector3d B = ws.markers[2].p_W;  // "B.crank"
  FourBar actual = f;
  actual.phi = std::atan2(B.y(), B.x());
  EXPECT_NEAR(actual.phi, f.phi, 1e-8);
  const Eigen::Vector2d C = four_bar_point_c(actual);
  EXPECT_LT((ws.markers[5].p_W - Eigen::Vector3d(C.x(), C.y(), 0)).norm(), 1e-11);  // "C.rocker"
  // The planar four-bar of spatial revolutes has 20 equations, 18 DOF and mobility 1:
  // 3 redundant equations (Grübler 6·3 − 5·4 = −2).
  const ConstraintPartition partition = analyse_redundancy(model, state, ws);
  EXPECT_EQ(partition.redundant.size(), 3u);
}

TEST(Assembly, FailureNamesTheEquationThatDoesNotClose) {
  // Crank (0.3 m) and rocker (0.6 m) joined at B cannot span the 2 m between pivots.
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("crank", 1.0, Eigen::Vector3d(0.01, 0.02, 0.02), Eigen::Vector3d::Zero()));
  builder.add_rigid_body(body_spec("rocker", 1.0, Eigen::Vector3d(0.01, 0.02, 0.02), Eigen::Vector3d(2, 0, 0)));
  builder.add_marker("A.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_marker("A.crank", "crank", Eigen::Vector3d::Zero());
  builder.add_marker("B.crank", "crank", Eigen::Vector3d(0.3, 0, 0));
  builder.add_marker("B.rocker", "rocker", Eigen::Vector3d(-0.3, 0, 0));
  builder.add_marker("D.ground", "ground", Eigen::Vector3d(2, 0, 0));
  builder.add_marker("D.rocker", "rocker", Eigen::Vector3d(0.3, 0, 0));
  builder.add_joint("A", JointType::kRevolute, "A.ground", "A.crank");
  builder.add_joint("B", JointType::kSpherical, "B.crank", "B.rocker");
  builder.add_joint("D", JointType::kRevolute, "D.ground", "D.rocker");
  const Model bad = builder.build();
  Workspace ws(bad);
  State state = initial_state(bad);
  const AssemblyResult result = assemble_positions(bad, state, ws);
  EXPECT_EQ(result.status, AssemblyStatus::kNotConverged);
  // Gap: 2 − 0.3 − 0.6 = 1.1 m along x. No configuration closes it by less than an equal
  // split over the x equations of A, B and D (1.1/3 each), and Gauss–Newton's steps never
  // open it further than the stretched chain's 1.1 m. Where in between it stops depends on
  // the rank cut at the stretched (singular) configuration: 0.55 m with the relative cut
  // of redundancy.h.
  EXPECT_GE(std::abs(result.residual), 1.1 / 3 - 1e-9) << result.message;
  EXPECT_LE(std::abs(result.residual), 1.1 + 1e-9) << result.message;
  EXPECT_NE(result.message.find(".x (joint "), std::string::npos) << result.message;
  EXPECT_NE(result.message.find("does not close, residual "), std::string::npos) << result.message;
}

// Kinematic solution of the driven slider-crank at time t: assembled positions,
// velocities and accelerations (0 DOF after the driver).
struct Solution {
  State state;
  Eigen::VectorXd v_dot;
  Reactions reactions;
  ConstraintPartition partition;
};

Solution solve_at(const Model& model, double t) {
  Workspace ws(model);
  Solution s;
  s.state = initial_state(model);
  s.state.t = t;
  const AssemblyResult result = assemble_positions(model, s.state, ws, {1e-12, 50, {}});
  LIMBER_DEMAND(result.status == AssemblyStatus::kOk);
  assemble_velocities(model, s.state, ws);
  // Both levels closed: positions to the Newton tolerance, velocities to rounding.
  const ConstraintViolation violation = constraint_violation(model, s.state, ws);
  EXPECT_LE(violation.position, 1e-12);
  EXPECT_LT(violation.velocity, 1e-11);
  s.partition = analyse_redundancy(model, s.state, ws);
  Eigen::VectorXd lambda;
  solve_accelerations(model, s.state, s.partition, ws, s.v_dot, lambda);
  s.reactions = compute_reactions(model, s.state, s.v_dot, s.partition, ws);
  return s;
}

TEST(SliderCrank, RedundantModelReportsItsRedundantEquations) {
  // 3 moving bodies (18 DOF), 4 joints x 5 = 20 equations + 1 driver. The planar
  // mechanism has mobility 1 before the driver, so 20 − 17 = 3 equations are redundant
  // (the naive count 20 − 18 = 2 ignores the mobility), all out of the plane x-z:
  // translations along y and rotations about x and z of the joint frames (y, rot_x, rot_y
  // in the revolute frames whose z is ground y).
  const Model model = testing::slider_crank({});
  EXPECT_EQ(model.nv, 18);
  EXPECT_EQ(model.num_equations(), 21);
  const Solution s = solve_at(model, 0.0123);
  ASSERT_EQ(s.partition.redundant.size(), 3u);
  EXPECT_EQ(s.partition.independent.size(), 18u);
  // Column pivoting keeps R1, R3 and T whole and drops R2's out-of-plane equations
  // (revolute frames have z along ground y: "z" is the y translation, rot_x/rot_y the
  // tilts out of the plane). Each depends only on out-of-plane equations of the other
  // joints (T's frame: x along ground y, z along the slide).
  const char* expected[] = {"R2.z", "R2.rot_x", "R2.rot_y"};
  for (int k = 0; k < 3; ++k) {
    const RedundantEquation& r = s.partition.redundant[k];
    EXPECT_EQ(model.equations[r.row].name, expected[k]);
    EXPECT_FALSE(r.depends_on.empty());
    for (int row : r.depends_on) {
      const std::string& name = model.equations[row].name;
      const bool out_of_plane = name.ends_with(".z") || name.ends_with(".rot_x") || name.ends_with(".rot_y") ||
                                name == "T.x" || name == "T.rot_z";
      EXPECT_TRUE(out_of_plane) << name;
    }
  }
  EXPECT_EQ(s.partition.describe(model).size(), 3u);
  // The driver effort stays determinate and every moving joint is in a dependency group.
  EXPECT_FALSE(s.partition.row_indeterminate[model.find_equation("D1")]);
}

// The readers of one evaluation (evaluated.h, a sample's pass) against the functions that
// evaluate for themselves, on the redundant slider-crank in motion: violation and energies
// read the same numbers from the same arithmetic (equal to the bit); the reactions
// solve the same normal equations with Q − M v̇ summed over the whole M instead of body blocks
// and the wrench maps by the same LU, so they differ by rounding only: a few ε of the
// largest reaction, times the Gram matrix's condition (1e-10 of it leaves a margin of 1e3;
// torques against it over the rod's 1 m).
TEST(SliderCrank, ReadersOfOneEvaluationEqualTheEvaluatingFunctions) {
  const Model model = testing::slider_crank({});
  const Solution s = solve_at(model, 0.0123);
  Workspace pass(model), own(model);
  mass_matrix_and_forces(model, s.state, pass);
  evaluate_constraint_rows(model, s.state, Stage::kPosition, pass);

  const ConstraintViolation read = violation_of_rows(model, s.state, pass);
  const ConstraintViolation evaluated = constraint_violation(model, s.state, own);
  EXPECT_EQ(read.position, evaluated.position);
  EXPECT_EQ(read.velocity, evaluated.velocity);
  const EnergyTerms e_read = energies_at_markers(model, s.state, pass);
  const EnergyTerms e_evaluated = energies(model, s.state, own);
  EXPECT_EQ(e_read.kinetic, e_evaluated.kinetic);
  EXPECT_EQ(e_read.gravity, e_evaluated.gravity);
  EXPECT_EQ(e_read.spring, e_evaluated.spring);
  EXPECT_EQ(e_read.strain, e_evaluated.strain);
  // system_momentum multiplies M v body block by body block (mass_times): the same products
  // summed in another order, so equal to a few ε of the momentum (1e-12 leaves a margin of 1e3).
  const Eigen::Matrix<double, 6, 1> h_read = momentum_of(model, s.state, pass.M);
  EXPECT_LE((h_read - system_momentum(model, s.state)).norm(), 1e-12 * h_read.norm());
  EXPECT_GT(h_read.norm(), 0.0);

  const Reactions r_read = reactions_of_evaluation(model, s.state, s.v_dot, s.partition, pass);
  double largest = 0.0;
  for (const JointReaction& r : s.reactions.joints) largest = std::max(largest, r.force_j_W.norm());
  ASSERT_GT(largest, 1.0);  // the crank's drive loads the joints by newtons at least
  for (std::size_t k = 0; k < model.joints.size(); ++k) {
    EXPECT_LE((r_read.joints[k].force_j_W - s.reactions.joints[k].force_j_W).norm(), 1e-10 * largest) << k;
    EXPECT_LE((r_read.joints[k].torque_j_W - s.reactions.joints[k].torque_j_W).norm(), 1e-10 * largest) << k;
  }
  EXPECT_LE(std::abs(r_read.driver_efforts[0] - s.reactions.driver_efforts[0]), 1e-10 * largest);
}

TEST(SliderCrank, SliderFollowsClosedForm) {
  // x = a cos θ + sqrt(b² − a² sin² θ) at θ = ω t; velocity and acceleration from its
  // derivatives (central differences of the closed form, h = 1e-5 s: error ~ h² x⃛ ~ 1e-5
  // relative... so check ẋ, ẍ against the analytic derivatives instead).
  const testing::SliderCrankParameters p;
  const Model model = testing::slider_crank(p);
  const int slider = model.find_body("slider");
  for (double t : {0.0, 0.004, 0.011, 0.02, 0.0371}) {
    const Solution s = solve_at(model, t);
    const double th = p.speed * t, w = p.speed;
    const double root = std::sqrt(p.b * p.b - p.a * p.a * std::sin(th) * std::sin(th));
    const double x = p.a * std::cos(th) + root;
    // ẋ = −a ω sin θ − a² ω sin θ cos θ / root; ẍ by differentiating once more.
    const double s1 = std::sin(th), c1 = std::cos(th);
    const double x_dot = -p.a * w * s1 - p.a * p.a * w * s1 * c1 / root;
    const double x_ddot = -p.a * w * w * c1 -
                          p.a * p.a * w * w * (c1 * c1 - s1 * s1) / root -
                          std::pow(p.a, 4) * w * w * s1 * s1 * c1 * c1 / std::pow(root, 3);
    const int o = model.bodies[slider].v_offset;
    // Assembly to 1e-12 m; velocities and accelerations exact up to rounding
    // (ẍ ~ ω² a ~ 2400 m/s²: 1e-9 relative).
    EXPECT_NEAR(s.state.q(model.bodies[slider].q_offset), x, 1e-11) << "t = " << t;
    EXPECT_NEAR(s.state.v(o), x_dot, 1e-10 * std::abs(w)) << "t = " << t;
    EXPECT_NEAR(s.v_dot(o), x_ddot, 1e-9 * w * w) << "t = " << t;
  }
}

TEST(SliderCrank, RedundantAndNonRedundantModelsAgree) {
  // Same mechanism, R2 → universal, R3 → spherical: 5 + 4 + 3 + 5 + 1 = 18 independent
  // equations. Motion, driver torque and the in-plane reactions (determinate in both)
  // must agree to rounding of the solves (1e-9 relative to the largest force).
  testing::SliderCrankParameters p;
  const Model redundant = testing::slider_crank(p);
  p.non_redundant = true;
  const Model reference = testing::slider_crank(p);
  EXPECT_EQ(reference.num_equations(), 18);
  for (double t : {0.003, 0.017, 0.029}) {
    const Solution a = solve_at(redundant, t), b = solve_at(reference, t);
    EXPECT_TRUE(b.partition.redundant.empty());
    EXPECT_LT((a.state.q.head(14) - b.state.q.head(14)).norm(), 1e-10);
    EXPECT_LT((a.state.v - b.state.v).norm(), 1e-8);
    EXPECT_LT((a.v_dot - b.v_dot).norm(), 1e-9 * a.v_dot.norm());
    const double scale = a.reactions.joints[2].force_j_W.norm();
    EXPECT_NEAR(a.reactions.driver_efforts[0], b.reactions.driver_efforts[0], 1e-9 * scale);
    for (const char* joint : {"R1", "R2", "R3", "T"}) {
      const int k = redundant.find_joint(joint);
      const Eigen::Vector3d fa = a.reactions.joints[k].force_j_W, fb = b.reactions.joints[k].force_j_W;
      EXPECT_NEAR(fa.x(), fb.x(), 1e-9 * scale) << joint;
      EXPECT_NEAR(fa.z(), fb.z(), 1e-9 * scale) << joint;
      EXPECT_TRUE(a.reactions.joints[k].indeterminate || std::string(joint) == "R1") << joint;
      EXPECT_FALSE(b.reactions.joints[k].indeterminate) << joint;
    }
  }
}

}  // namespace
}  // namespace limber::multibody
