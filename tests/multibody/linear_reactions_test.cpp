// Joint reactions as state-space outputs (multibody/linear_reactions.h): a pendulum's pivot
// force about its hanging equilibrium against a hand derivation, in ground and joint axes; a
// double pendulum in motion (a revolute to ground, a spherical joint, gravity, a spring–damper
// and a force input) against central differences of the full nonlinear reaction
// (solve_accelerations, then compute_reactions) along every state and input; and the reaction
// of a redundant joint refused by name.
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "multibody/assembly.h"
#include "multibody/linearization.h"
#include "multibody/reactions.h"
#include "multibody/redundancy.h"
#include "multibody/state_space.h"
#include "multibody/statics.h"
#include "linear_test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;
using testing::marker_index;

int joint_index(const Model& model, const std::string& name) {
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    if (model.joints[j].name == name) return static_cast<int>(j);
  }
  ADD_FAILURE() << "no joint " << name;
  return -1;
}

LinearOutput reaction(const Model& model, const std::string& joint, LinearOutputKind kind, ChannelAxes axes) {
  LinearOutput out;
  out.name = joint + (kind == LinearOutputKind::kReactionForce ? "_force" : "_torque");
  out.kind = kind;
  out.joint = joint_index(model, joint);
  out.axes = axes;
  return out;
}

// The linearization point, its partition, tangent matrices and basis Z.
struct Point {
  State state;
  ConstraintPartition partition;
  TangentMatrices tangent;
  Eigen::MatrixXd Z;
};

Point tangent_at(const Model& model, const State& state, const ConstraintPartition& partition) {
  Point p{state, partition, {}, {}};
  std::string message;
  EXPECT_EQ(tangent_matrices(model, partition, state, p.tangent, message), LinearizationStatus::kOk) << message;
  p.Z = null_space_basis(p.tangent.G, model.nv);
  return p;
}

// The hanging pendulum (linear_test_models.h) about its equilibrium. Hand derivation (θ about
// +y, torque τ about +y on the bob):
// the centre of mass c = (−l sin θ, 0, −l cos θ), J_p θ̈ = −m g l θ + τ (J_p = J_y + m l²), and
// the pivot's force on the bob F = m c̈ − m g = (−m l θ̈, 0, m g) to first order (c̈_z is
// second order), so in ground axes δF_x = (m² g l² / J_p) θ − (m l / J_p) τ and nothing else.
// In the joint frame (marker P.bob's axes, turning with the bob) the steady m g along z turns
// too: δF = R_m0ᵀ (δF_x − m g θ, 0, 0), i.e. along the marker's x (= ground x)
// −(m g J_y / J_p) θ − (m l / J_p) τ. The torques stay zero (principal axes, planar motion).
// The state y is along Z, θ = Z_wy y. Tolerance 1e-8 relative to m g: the differences'
// rounding (1e-16/ε of forces ~ m g, ε = 1e-6) leaves 1e-10, statics' residual 1e-9 of m g.
TEST(LinearReactions, PendulumPivotForceMatchesTheHandDerivation) {
  const double m = 2.0, l = 0.5, Jy = 0.2, g = 9.81, Jp = Jy + m * l * l;
  const Model model = testing::pendulum_builder(m, Jy, g, -l).build();
  State start = initial_state(model);
  Workspace ws(model);
  ASSERT_EQ(assemble_positions(model, start, ws).status, AssemblyStatus::kOk);
  const ConstraintPartition partition = analyse_redundancy(model, start, ws);
  const StaticsResult equilibrium = solve_statics(model, partition, start);
  ASSERT_EQ(equilibrium.status, StaticsStatus::kOk) << equilibrium.message;
  const Point p = tangent_at(model, equilibrium.state, partition);
  ASSERT_EQ(p.Z.cols(), 1);

  LinearInput torque;
  torque.name = "motor";
  torque.kind = LinearInputKind::kTorque;
  torque.marker = marker_index(model, "P.bob");
  const std::vector<LinearOutput> outputs = {
      reaction(model, "P", LinearOutputKind::kReactionForce, ChannelAxes::kGround),
      reaction(model, "P", LinearOutputKind::kReactionForce, ChannelAxes::kMarker),
      reaction(model, "P", LinearOutputKind::kReactionTorque, ChannelAxes::kGround)};
  const StateSpace ss = state_space(model, p.state, p.tangent, p.Z, {torque}, outputs);
  ASSERT_EQ(ss.C.rows(), 9);
  ASSERT_EQ(ss.D.cols(), 3);

  const int wy = model.bodies[static_cast<std::size_t>(model.find_body("bob"))].v_offset + 4;
  const double theta_per_y = p.Z(wy, 0);
  ASSERT_NEAR(std::abs(theta_per_y), 1.0, 1e-12);
  const double tol = 1e-8 * m * g;
  // Ground axes: δF_x per θ and per τ_y; nothing along y, z; no rate dependence.
  EXPECT_NEAR(ss.C(0, 0) / theta_per_y, m * m * g * l * l / Jp, tol);
  EXPECT_NEAR(ss.D(0, 1), -m * l / Jp, tol);
  for (int r : {1, 2}) {
    EXPECT_NEAR(ss.C(r, 0), 0.0, tol);
    EXPECT_NEAR(ss.D(r, 1), 0.0, tol);
  }
  for (int r = 0; r < 9; ++r) EXPECT_NEAR(ss.C(r, 1), 0.0, tol) << ss.output_names[static_cast<std::size_t>(r)];
  // The torques about x and z do not reach the pivot force.
  EXPECT_NEAR(ss.D(0, 0), 0.0, tol);
  EXPECT_NEAR(ss.D(0, 2), 0.0, tol);
  // Joint axes: the marker's x is ground x at the point.
  EXPECT_NEAR(ss.C(3, 0) / theta_per_y, -m * g * Jy / Jp, tol);
  EXPECT_NEAR(ss.D(3, 1), -m * l / Jp, tol);
  EXPECT_NEAR(ss.C(4, 0), 0.0, tol);
  EXPECT_NEAR(ss.C(5, 0), 0.0, tol);
  // Torques: none.
  for (int r = 6; r < 9; ++r) {
    EXPECT_NEAR(ss.C(r, 0), 0.0, tol);
    EXPECT_NEAR(ss.D(r, 1), 0.0, tol);
  }
}

// A double pendulum in 3-D: link1 on a revolute to ground about a skew axis, link2 on a
// spherical joint at link1's tip, gravity, a spring–damper from ground to link2, and a force
// `load` at link2's tip (marker "tip").
Model double_pendulum(const Eigen::Vector3d& load) {
  ModelBuilder builder;
  builder.set_gravity(Eigen::Vector3d(0, 0, -9.81));
  builder.add_rigid_body(body_spec("link1", 2.0, Eigen::Vector3d(0.05, 0.2, 0.18), Eigen::Vector3d(0, 0, -0.5)));
  builder.add_rigid_body(body_spec("link2", 1.0, Eigen::Vector3d(0.08, 0.06, 0.03), Eigen::Vector3d(0.2, 0, -1.3)));
  const Eigen::Matrix3d R_h = frame_from_axes(Eigen::Vector3d(0.2, 1.0, 0.1).normalized(), Eigen::Vector3d::UnitX());
  builder.add_marker_at("R.ground", "ground", Eigen::Vector3d::Zero(), R_h);
  builder.add_marker_at("R.link1", "link1", Eigen::Vector3d::Zero(), R_h);
  builder.add_joint("R", JointType::kRevolute, "R.ground", "R.link1");
  builder.add_marker_at("S.link1", "link1", Eigen::Vector3d(0, 0, -1.0));
  builder.add_marker_at("S.link2", "link2", Eigen::Vector3d(0, 0, -1.0));
  builder.add_joint("S", JointType::kSpherical, "S.link1", "S.link2");
  builder.add_marker_at("spring.ground", "ground", Eigen::Vector3d(1.0, 0.5, -1.5));
  builder.add_marker_at("tip", "link2", Eigen::Vector3d(0.4, 0, -1.6));
  builder.add_tsda({"spring", "spring.ground", "tip", 40.0, 3.0, 0.7, {}});
  if (load.norm() > 0.0) builder.add_point_load({"load", "tip", load, Eigen::Vector3d::Zero()});
  return builder.build();
}

// The three reaction channels of `output` from the nonlinear path at `state`.
Eigen::Vector3d nonlinear_reaction(const Model& model, const State& state, const ConstraintPartition& partition,
                                   const LinearOutput& output) {
  Workspace ws(model);
  Eigen::VectorXd v_dot, lambda;
  solve_accelerations(model, state, partition, ws, v_dot, lambda);
  const JointReaction r = compute_reactions(model, state, v_dot, partition, ws).joints[output.joint];
  const bool force = output.kind == LinearOutputKind::kReactionForce;
  if (output.axes == ChannelAxes::kGround) return force ? r.force_j_W : r.torque_j_W;
  return force ? r.force_j_J : r.torque_j_J;
}

// The second method: about a state in motion (off equilibrium, both links turning), each
// column of C and D against central differences of the nonlinear reaction along q0 ⊕ Z y,
// v0 + Z ẏ and the load (step h = 1e-5: truncation h² ~ 1e-10 of the third derivatives,
// rounding 1e-16/h ~ 1e-11 of the forces). Tolerance 1e-6 of the largest reaction (~30 N): the
// linearization's own differences (ε = 1e-6 in K, C and A's derivatives) leave ~1e-9 of the
// largest stiffness entry, amplified by the solve; measured 1.1e-10.
TEST(LinearReactions, DoublePendulumInMotionMatchesDifferencesOfTheNonlinearReaction) {
  const Model model = double_pendulum(Eigen::Vector3d::Zero());
  State point = initial_state(model);
  Workspace ws(model);
  ASSERT_EQ(assemble_positions(model, point, ws).status, AssemblyStatus::kOk);
  point.v.setRandom();
  assemble_velocities(model, point, ws);
  const ConstraintPartition partition = analyse_redundancy(model, point, ws);
  const Point p = tangent_at(model, point, partition);
  const Eigen::Index n = p.Z.cols();
  ASSERT_EQ(n, 4);  // the revolute's angle and the spherical joint's three

  LinearInput force;
  force.name = "push";
  force.kind = LinearInputKind::kForce;
  force.marker = marker_index(model, "tip");
  std::vector<LinearOutput> outputs;
  for (const char* joint : {"R", "S"}) {
    for (LinearOutputKind kind : {LinearOutputKind::kReactionForce, LinearOutputKind::kReactionTorque}) {
      for (ChannelAxes axes : {ChannelAxes::kGround, ChannelAxes::kMarker}) {
        outputs.push_back(reaction(model, joint, kind, axes));
      }
    }
  }
  const StateSpace ss = state_space(model, p.state, p.tangent, p.Z, {force}, outputs);

  const double h = 1e-5;
  double scale = 0.0, worst = 0.0;
  for (std::size_t o = 0; o < outputs.size(); ++o) {
    const auto rows = Eigen::seqN(3 * static_cast<Eigen::Index>(o), 3);
    scale = std::max(scale, nonlinear_reaction(model, point, partition, outputs[o]).norm());
    for (Eigen::Index c = 0; c < 2 * n; ++c) {
      State plus = point, minus = point;
      if (c < n) {
        plus.q = displaced_coordinates(model, point.q, h * p.Z.col(c));
        minus.q = displaced_coordinates(model, point.q, -h * p.Z.col(c));
      } else {
        plus.v += h * p.Z.col(c - n);
        minus.v -= h * p.Z.col(c - n);
      }
      const Eigen::Vector3d difference = (nonlinear_reaction(model, plus, partition, outputs[o]) -
                                          nonlinear_reaction(model, minus, partition, outputs[o])) / (2.0 * h);
      worst = std::max(worst, (ss.C(rows, c) - difference).cwiseAbs().maxCoeff());
    }
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d load = h * Eigen::Vector3d::Unit(k);
      const Eigen::Vector3d difference =
          (nonlinear_reaction(double_pendulum(load), point, partition, outputs[o]) -
           nonlinear_reaction(double_pendulum(-load), point, partition, outputs[o])) / (2.0 * h);
      worst = std::max(worst, (ss.D(rows, k) - difference).cwiseAbs().maxCoeff());
    }
  }
  EXPECT_GT(scale, 10.0);
  EXPECT_LT(worst, 1e-6 * scale) << "largest difference " << worst << " of reactions up to " << scale;
  std::cout << "largest difference " << worst / scale << " of the largest reaction, " << scale << " N or N m\n";
}

// A body hinged to ground twice about one axis: the second hinge's equations are redundant,
// its reaction not determined; asking for it is refused naming the output and the joint.
TEST(LinearReactions, RedundantJointsReactionIsRefusedByName) {
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("wheel", 1.0, Eigen::Vector3d(0.1, 0.1, 0.2), Eigen::Vector3d::Zero()));
  for (const char* hinge : {"A", "B"}) {
    const Eigen::Vector3d at(0, 0, hinge[0] == 'A' ? 0.1 : -0.1);
    builder.add_marker_at(std::string(hinge) + ".ground", "ground", at);
    builder.add_marker_at(std::string(hinge) + ".wheel", "wheel", at);
    builder.add_joint(hinge, JointType::kRevolute, std::string(hinge) + ".ground", std::string(hinge) + ".wheel");
  }
  const Model model = builder.build();
  State point = initial_state(model);
  Workspace ws(model);
  ASSERT_EQ(assemble_positions(model, point, ws).status, AssemblyStatus::kOk);
  const ConstraintPartition partition = analyse_redundancy(model, point, ws);
  const Point p = tangent_at(model, point, partition);
  const LinearOutput output = reaction(model, "B", LinearOutputKind::kReactionForce, ChannelAxes::kGround);
  try {
    state_space(model, p.state, p.tangent, p.Z, {}, {output});
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("linearize output 'B_force'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("got 'B' with equation"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace limber::multibody
