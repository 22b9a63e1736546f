// The elastic displacement relative to a rigid fit through joint nodes (relative_deflection.h):
// a rigidly moved body has none, a known bending shape between two joint nodes comes back
// exactly, and the joint nodes are the mesh nodes nearest the joints on the body.
#include "relative_deflection.h"
#include "world_triad.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace limber::render {
namespace {

// A 1 m rod along body x, 11 nodes, and a 0.6 m plate of 3 x 4 nodes in the xy plane beside it.
RowMatrix3d rod_and_plate_nodes() {
  RowMatrix3d nodes(11 + 12, 3);
  for (int k = 0; k <= 10; ++k) nodes.row(k) << 0.1 * k, 0.0, 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) nodes.row(11 + 4 * i + j) << 0.3 * i, 0.5 + 0.2 * j, 0.05 * i * j;
  }
  return nodes;
}

// The linearised rigid displacement t + θ × X of every node.
RowMatrix3d rigid_displacement(const RowMatrix3d& nodes, const Eigen::Vector3d& t,
                               const Eigen::Vector3d& theta) {
  RowMatrix3d u(nodes.rows(), 3);
  for (Eigen::Index n = 0; n < nodes.rows(); ++n) {
    u.row(n) = (t + theta.cross(nodes.row(n).transpose())).transpose();
  }
  return u;
}

TEST(RelativeDeflection, RigidlyMovedBodyHasNone) {
  const RowMatrix3d nodes = rod_and_plate_nodes();
  const RowMatrix3d u = rigid_displacement(nodes, {0.1, -0.2, 0.3}, {0.01, -0.02, 0.03});
  // Three joint nodes not on one line see every rigid motion: u_rel = 0 at every node, to
  // rounding (|u| ~ 0.3 m, a few operations: 1e-15 m).
  const RowMatrix3d three = relative_displacements(rigid_fit_basis(nodes, {0, 10, 22}), nodes, u);
  EXPECT_LT(three.cwiseAbs().maxCoeff(), 1e-15);
  // Two joint nodes (the rod's ends) cannot see the spin about the rod's axis; the rod's own
  // nodes, on that axis, still have none.
  const RowMatrix3d two = relative_displacements(rigid_fit_basis(nodes, {0, 10}), nodes, u);
  EXPECT_LT(two.topRows(11).cwiseAbs().maxCoeff(), 1e-15);
  // One joint node: translation only; a pure translation leaves nothing.
  const RowMatrix3d moved = rigid_displacement(nodes, {0.1, -0.2, 0.3}, Eigen::Vector3d::Zero());
  EXPECT_LT(relative_displacements(rigid_fit_basis(nodes, {5}), nodes, moved).cwiseAbs().maxCoeff(), 1e-15);
  // No joint node: u as it is.
  EXPECT_EQ(relative_displacements(rigid_fit_basis(nodes, {}), nodes, u), u);
}

TEST(RelativeDeflection, BendingBetweenTwoJointNodesIsRecovered) {
  // u = rigid part + w(x) z, w = a sin(pi x): zero at both joint nodes, so the fit through them
  // is the rigid part alone and u_rel = w z at every rod node (1e-15 m: rounding of |u| ~ 0.3).
  const RowMatrix3d nodes = rod_and_plate_nodes().topRows(11);
  const double a = 0.007;
  RowMatrix3d u = rigid_displacement(nodes, {0.1, -0.2, 0.3}, {0.0, -0.02, 0.03});
  RowMatrix3d bending = RowMatrix3d::Zero(nodes.rows(), 3);
  for (Eigen::Index n = 0; n < nodes.rows(); ++n) bending(n, 2) = a * std::sin(std::numbers::pi * nodes(n, 0));
  u += bending;
  const RowMatrix3d relative = relative_displacements(rigid_fit_basis(nodes, {0, 10}), nodes, u);
  EXPECT_LT((relative - bending).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(relative(5, 2), a, 1e-15);  // mid-span: the whole amplitude
}

TEST(RelativeDeflection, JointNodesAreTheNodesNearestTheJointsOnTheBody) {
  Results results;
  results.time = Eigen::VectorXd::Zero(1);
  BodyTrack rod;
  rod.name = "rod";
  rod.flexible = true;
  rod.mesh.nodes = rod_and_plate_nodes().topRows(11);
  rod.position = RowMatrix3d::Constant(1, 3, 0.0);
  rod.position.row(0) << 2.0, 0.0, 0.0;  // frame 2 m along ground x, axes turned 90° about z
  rod.orientation.resize(1, 4);
  rod.orientation.row(0) << std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5);
  results.bodies.push_back(rod);
  auto joint = [](const std::string& name, const std::string& body_j, const Eigen::Vector3d& p) {
    JointTrack j;
    j.name = name;
    j.body_i = "ground";
    j.body_j = body_j;
    j.position = p.transpose();
    return j;
  };
  // Body x is ground y: node k sits at (2, 0.1 k, 0). "far" joins another body.
  results.joints = {joint("end", "rod", {2.0, 1.02, 0.0}), joint("start", "rod", {2.01, 0.0, 0.0}),
                    joint("far", "crank", {2.0, 0.5, 0.0})};
  std::vector<std::string> names;
  EXPECT_EQ(joint_nodes(results, results.bodies[0], &names), (std::vector<Eigen::Index>{10, 0}));
  EXPECT_EQ(names, (std::vector<std::string>{"end", "start"}));
}

TEST(WorldTriad, ArrowLengthIsTheSmallestRoundLengthAboveSevenTenthsOfTheWish) {
  EXPECT_DOUBLE_EQ(round_length(0.15), 0.2);   // 0.105 -> 0.2 (0.1 is below)
  EXPECT_DOUBLE_EQ(round_length(0.07), 0.05);  // 0.049 -> 0.05
  EXPECT_DOUBLE_EQ(round_length(1.0), 1.0);
  EXPECT_DOUBLE_EQ(round_length(3.0), 5.0);    // 2.1 -> 5
  EXPECT_DOUBLE_EQ(round_length(9.0), 10.0);   // 6.3 -> 10
}

}  // namespace
}  // namespace limber::render
