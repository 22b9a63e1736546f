// The clearance check (multibody/clearance.h) on small models with closed-form answers: two
// parallel shell plates a known gap apart, a plate partly inside a box (penetration depth),
// a plate's corner on and just inside a rotated box face, a plate bent by its modes under a
// box face, a hinged pair whose hinge vertices the joint band leaves out, and a satellite
// (bus and four panels, stowed and deployed) whose cost per evaluation is printed; the minimum
// over pairs (minimum_clearance) against the full check.
#include "multibody/clearance.h"
#include "multibody/clearance_minimum.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "multibody/flexible_marker.h"
#include "multibody/rotation.h"
#include "flexible_test_models.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

// Coordinates are O(1 m) and every distance comes from a few dot products and one sqrt:
// round-off ~1e-15 m; 1e-12 m leaves margin for the eigen-solver noise in modes (η = 0 here
// except in the bent-plate test).
constexpr double kTolerance = 1e-12;

// A free aluminium shell plate edge_x by edge_y in its body x-y plane, corner node 0 at the
// body origin, nx by ny quads, with its two lowest elastic modes.
struct Plate {
  fe::FeModel fe;
  modal::ModeSet modes;
};

Plate free_plate(double edge_x, double edge_y, int nx, int ny) {
  fe::FeModelBuilder builder;
  fe::RectangularPlateMesh mesh;
  mesh.edge_x = edge_x * Eigen::Vector3d::UnitX();
  mesh.edge_y = edge_y * Eigen::Vector3d::UnitY();
  mesh.elements_x = nx;
  mesh.elements_y = ny;
  mesh.property = builder.add_shell_property({"panel", {"aluminium", 70e9, 0.33, 2700.0}, 0.01});
  fe::add_rectangular_plate(builder, mesh);
  Plate plate;
  plate.fe = std::move(builder).build();
  plate.modes = testing::normal_modes(plate.fe, 2);
  return plate;
}

// The plate as a flexible body at pose (p_WB, R_WB), drawn (and checked) by its quads.
FlexibleBodySpec plate_body(const std::string& name, const Plate& plate, const Eigen::Vector3d& p_WB,
                            const Eigen::Matrix3d& R_WB) {
  FlexibleBodySpec spec = testing::flexible_spec(name, plate.fe, plate.modes, ModalDamping::ratio(0.01));
  for (const fe::ShellElement& shell : plate.fe.shells) spec.mesh.quads.push_back(shell.nodes);
  spec.initial_pose.position = p_WB;
  spec.initial_pose.orientation = quaternion_from_matrix(R_WB);
  return spec;
}

// A rigid body carrying one box of `edges` at offset (p_BS, R_BS).
RigidBodySpec box_body(const std::string& name, const Eigen::Vector3d& edges, const Eigen::Vector3d& p_WB,
                       const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& p_BS = Eigen::Vector3d::Zero(),
                       const Eigen::Matrix3d& R_BS = Eigen::Matrix3d::Identity()) {
  RigidBodySpec spec = testing::body_spec(name, 10.0, Eigen::Vector3d(1, 1, 1), p_WB, R_WB);
  Shape box;
  box.size = edges;
  box.offset.position = p_BS;
  box.offset.orientation = quaternion_from_matrix(R_BS);
  spec.shapes.push_back(box);
  return spec;
}

// A generic rotation (no axis aligned with ground).
Eigen::Matrix3d generic_rotation() { return axis_angle_matrix(Eigen::Vector3d(1, -2, 3).normalized(), 0.9); }

TEST(Clearance, ParallelPlatesAKnownGapApart) {
  // Plate b above plate a by the gap along their common normal, shifted in-plane by a
  // non-grid amount so its nodes fall inside a's triangles (and on their diagonals).
  const Plate plate = free_plate(1.0, 0.8, 4, 4);
  const Eigen::Matrix3d R = generic_rotation();
  const double gap = 0.0371;
  ModelBuilder builder;
  builder.add_flexible_body(plate_body("a", plate, Eigen::Vector3d(0.3, -0.2, 0.1), R));
  builder.add_flexible_body(
      plate_body("b", plate, Eigen::Vector3d(0.3, -0.2, 0.1) + R * Eigen::Vector3d(0.113, 0.071, gap), R));
  const Model model = builder.build();

  const Clearance clearance = compute_clearance(model, initial_state(model));
  ASSERT_EQ(clearance.pairs.size(), 1u);
  EXPECT_NEAR(clearance.minimum, gap, kTolerance);
  EXPECT_EQ(clearance.minimum_pair, 0);
  const PairClearance& pair = clearance.pairs[0];
  EXPECT_EQ(pair_name(model, pair.pair), "a, b");
  // The closest points are the gap apart along the plates' normal R z.
  EXPECT_NEAR((pair.point_b_W - pair.point_a_W).dot(R.col(2)), gap, kTolerance);
  EXPECT_NEAR((pair.point_b_W - pair.point_a_W).norm(), gap, kTolerance);
}

TEST(Clearance, PlatePartlyThroughABoxGivesMinusThePenetrationDepth) {
  // Plate 1 m along x at z = 0; the box's face at x = 0.7, its other faces farther from
  // the plate's nodes than 0.3 m: the edge x = 1 is 0.3 m deep.
  const Plate plate = free_plate(1.0, 0.6, 5, 3);
  ModelBuilder builder;
  builder.add_flexible_body(plate_body("panel", plate, Eigen::Vector3d(0, -0.3, 0), Eigen::Matrix3d::Identity()));
  // Box 2 x 2 x 1 m: body frame at (2, 0, 0), box offset by (−0.3, 0, 0) → x ∈ [0.7, 2.7].
  builder.add_rigid_body(box_body("bus", Eigen::Vector3d(2.0, 2.0, 1.0), Eigen::Vector3d(2.0, 0, 0),
                                  Eigen::Matrix3d::Identity(), Eigen::Vector3d(-0.3, 0, 0)));
  const Model model = builder.build();

  const Clearance clearance = compute_clearance(model, initial_state(model));
  EXPECT_NEAR(clearance.minimum, -0.3, kTolerance);
  const PairClearance& pair = clearance.pairs[0];
  EXPECT_EQ(pair_name(model, pair.pair), "panel, bus");
  // Deepest node on the plate's far edge, pushed out through the face x = 0.7.
  EXPECT_NEAR(pair.point_a_W.x(), 1.0, kTolerance);
  EXPECT_NEAR(pair.point_b_W.x(), 0.7, kTolerance);
  EXPECT_NEAR((pair.point_a_W - pair.point_b_W).tail<2>().norm(), 0.0, kTolerance);
}

// A rotated box and a plate whose corner node sits at `depth` below the centre of the
// box's +x face, the plate's in-plane axes both leaning out of that face (only the corner
// touches).
Model plate_at_rotated_face(double depth) {
  const Plate plate = free_plate(0.5, 0.5, 2, 2);
  const Eigen::Matrix3d R_WB = axis_angle_matrix(Eigen::Vector3d::UnitZ(), 0.5) *
                               axis_angle_matrix(Eigen::Vector3d::UnitX(), 0.35);
  const Eigen::Matrix3d R_BS = axis_angle_matrix(Eigen::Vector3d(0, 1, 1).normalized(), 0.4);
  const Eigen::Vector3d p_WB(0.2, 0.1, -0.3), p_BS(0.05, 0.0, 0.1), edges(1.0, 3.0, 3.0);
  const Eigen::Matrix3d R_WS = R_WB * R_BS;
  const Eigen::Vector3d n = R_WS.col(0), s = R_WS.col(1), t = R_WS.col(2);
  const Eigen::Vector3d face_point = p_WB + R_WB * p_BS + 0.5 * edges.x() * n;
  // Plate axes x = (n + s)/√2 and y ⟂ x in the plane of x and n + t: both have n · > 0.
  const Eigen::Vector3d x = (n + s).normalized();
  const Eigen::Vector3d y = ((n + t) - (n + t).dot(x) * x).normalized();
  Eigen::Matrix3d R_plate;
  R_plate << x, y, x.cross(y);
  ModelBuilder builder;
  builder.add_rigid_body(box_body("box", edges, p_WB, R_WB, p_BS, R_BS));
  builder.add_flexible_body(plate_body("plate", plate, face_point - depth * n, R_plate));
  return builder.build();
}

TEST(Clearance, PlateCornerOnARotatedBoxFace) {
  const Model model = plate_at_rotated_face(0.0);
  const Clearance clearance = compute_clearance(model, initial_state(model));
  EXPECT_NEAR(clearance.minimum, 0.0, kTolerance);
  const PairClearance& pair = clearance.pairs[0];
  // The touching point is the plate's node 0, on the box face.
  const Eigen::Vector3d corner = model.bodies[2].initial_pose.position;
  EXPECT_NEAR((pair.point_b_W - corner).norm(), 0.0, kTolerance);
  EXPECT_NEAR((pair.point_a_W - corner).norm(), 0.0, kTolerance);
}

TEST(Clearance, PlateCornerJustInsideARotatedBoxFace) {
  // 1 mm in: the face is the nearest one (the others are ≥ 0.5 m away), depth 1 mm.
  const Model model = plate_at_rotated_face(1e-3);
  const Clearance clearance = compute_clearance(model, initial_state(model));
  EXPECT_NEAR(clearance.minimum, -1e-3, kTolerance);
}

TEST(Clearance, PlateBentByItsModesUnderABoxFace) {
  // Plate at z = 0 under a 3 x 3 m box whose bottom face is at z = h: the nodes' distance
  // to the face is h − z_i (their projections fall inside it; the box corners are over 1 m
  // from the plate). z_i from node_frame_kinematics, the joints' path to the same nodes.
  const Plate plate = free_plate(1.0, 1.0, 4, 4);
  const double h = 0.1;
  FlexibleBodySpec spec = plate_body("panel", plate, Eigen::Vector3d(0.02, -0.01, 0), Eigen::Matrix3d::Identity());
  // Mass-normalised modes of a 27 kg plate, corners φ ~ 0.5 m/√kg: η ~ 0.05 bends it by cm.
  spec.initial_modal_coordinates = Eigen::Vector2d(0.06, -0.045);
  ModelBuilder builder;
  const int panel = builder.add_flexible_body(spec);
  builder.add_rigid_body(box_body("cover", Eigen::Vector3d(3, 3, 1), Eigen::Vector3d(0.5, 0.5, h + 0.5),
                                  Eigen::Matrix3d::Identity()));
  const Model model = builder.build();
  const State state = initial_state(model);

  double highest = -1.0;
  FrameKinematics node;
  for (int i = 0; i < plate.fe.node_count(); ++i) {
    node_frame_kinematics(model, panel, i, Eigen::Matrix3d::Identity(), state.q, nullptr, node);
    highest = std::max(highest, node.p_W.z());
  }
  ASSERT_GT(highest, 5e-3);  // the modes do bend it by millimetres
  ASSERT_LT(highest, h);     // and leave it below the face
  EXPECT_NEAR(compute_clearance(model, state).minimum, h - highest, kTolerance);
}

TEST(Clearance, JointBandLeavesOutTheHingeVertices) {
  // A panel hinged at its corner node 0 to the +x face of a box, leaning out of the face
  // (as in the rotated-box test, here axis-aligned): node 0 touches the face, its
  // neighbours along the plate axes x, y are h (x·n) and h (y·n) from it.
  const Plate plate = free_plate(1.0, 1.0, 4, 4);
  const double spacing = 0.25;
  const Eigen::Vector3d n = Eigen::Vector3d::UnitX(), s = Eigen::Vector3d::UnitY(), t = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d x = (n + s).normalized();
  const Eigen::Vector3d y = ((n + t) - (n + t).dot(x) * x).normalized();
  Eigen::Matrix3d R_plate;
  R_plate << x, y, x.cross(y);
  const Eigen::Vector3d hinge(0.5, 0.0, 0.0);
  ModelBuilder builder;
  builder.add_rigid_body(box_body("bus", Eigen::Vector3d(1, 2, 2), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()));
  builder.add_flexible_body(plate_body("panel", plate, hinge, R_plate));
  builder.add_marker_at("H.bus", "bus", hinge, frame_from_z_axis(t));
  builder.add_node_marker("H.panel", "panel", 0, R_plate.transpose() * frame_from_z_axis(t));
  builder.add_joint("H", JointType::kRevolute, "H.bus", "H.panel");
  const Model model = builder.build();
  const State state = initial_state(model);

  // Band 5 cm < spacing 25 cm: only node 0 is left out.
  const Clearance banded = compute_clearance(model, state);
  EXPECT_NEAR(banded.minimum, spacing * std::min(x.dot(n), y.dot(n)), kTolerance);
  // No band: the hinge vertex touches the face.
  EXPECT_NEAR(compute_clearance(model, state, {.joint_band = 0.0}).minimum, 0.0, kTolerance);
  // A band over the whole panel leaves nothing to check.
  const Clearance everything = compute_clearance(model, state, {.joint_band = 10.0});
  EXPECT_TRUE(std::isinf(everything.minimum));
  EXPECT_EQ(everything.minimum_pair, -1);
}

// Microseconds per compute_clearance at `state` (information only: not asserted).
double microseconds_per_evaluation(const Model& model, const State& state) {
  const int repeats = 200;
  const auto start = std::chrono::steady_clock::now();
  double sink = 0.0;
  for (int r = 0; r < repeats; ++r) sink += compute_clearance(model, state).minimum;
  const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(std::isfinite(sink));
  return us / repeats;
}

// Bus 1 x 1 x 1.5 m and four 1 x 1.4 m panels (10 x 14 quads, 165 nodes each), panel k
// facing the side wall of outward normal n_k = R_z(k π/2) x at gap_k from it: stowed
// parallel to the wall, or deployed (the same inner edge, the panel turned out to lie
// horizontally at mid-height).
constexpr std::array<const char*, 4> kPanels = {"panel_px", "panel_py", "panel_mx", "panel_my"};
constexpr std::array<double, 4> kGaps = {0.03, 0.04, 0.05, 0.06};

Pose panel_pose(int k, bool deployed) {
  const Eigen::Matrix3d R_k = axis_angle_matrix(Eigen::Vector3d::UnitZ(), k * std::numbers::pi / 2);
  const Eigen::Vector3d n = R_k.col(0), along = R_k.col(1), up = Eigen::Vector3d::UnitZ();
  // Plate x along the wall, y up the wall (stowed) or out from it (deployed).
  const Eigen::Vector3d y = deployed ? n : up;
  Eigen::Matrix3d R_panel;
  R_panel << along, y, along.cross(y);
  Pose pose;
  pose.position = (0.5 + kGaps[k]) * n - 0.5 * along - (deployed ? 0.0 : 0.7) * up;
  pose.orientation = quaternion_from_matrix(R_panel);
  return pose;
}

Model satellite() {
  const Plate plate = free_plate(1.0, 1.4, 10, 14);
  ModelBuilder builder;
  builder.add_rigid_body(box_body("bus", Eigen::Vector3d(1, 1, 1.5), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()));
  for (int k = 0; k < 4; ++k) {
    const Pose pose = panel_pose(k, false);
    builder.add_flexible_body(plate_body(kPanels[k], plate, pose.position, rotation_matrix(pose.orientation)));
  }
  return builder.build();
}

// The gaps are the same stowed and deployed: every panel's inner edge is gap_k from its
// wall (its nodes project onto the wall), and adjacent panels' nearest nodes are
// √(gap_i² + gap_j²) ≥ 50 mm apart, so the minimum is panel_px's 30 mm to the bus.
void expect_satellite_gaps(const Model& model, const Clearance& clearance) {
  ASSERT_EQ(clearance.pairs.size(), 10u);
  EXPECT_NEAR(clearance.minimum, 0.03, kTolerance);
  EXPECT_EQ(pair_name(model, clearance.pairs[static_cast<std::size_t>(clearance.minimum_pair)].pair), "bus, panel_px");
  // Pairs 0-3: the bus with each panel; pair 4: panel_px with panel_py.
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(clearance.pairs[static_cast<std::size_t>(k)].distance, kGaps[k], kTolerance);
  EXPECT_NEAR(clearance.pairs[4].distance, 0.05, kTolerance);
}

TEST(Clearance, SatelliteStowedAndDeployedGapsAndCost) {
  const Model model = satellite();
  const State stowed = initial_state(model);
  State deployed = stowed;
  for (int k = 0; k < 4; ++k) {
    const Body& panel = model.bodies[static_cast<std::size_t>(2 + k)];
    const Pose pose = panel_pose(k, true);
    deployed.q.segment<3>(panel.q_offset) = pose.position;
    deployed.q.segment<4>(panel.q_offset + 3) = pose.orientation;
  }
  expect_satellite_gaps(model, compute_clearance(model, stowed));
  expect_satellite_gaps(model, compute_clearance(model, deployed));
  std::printf("[ clearance ] bus + 4 x 165-node panels: stowed %.1f us, deployed %.1f us per evaluation\n",
              microseconds_per_evaluation(model, stowed), microseconds_per_evaluation(model, deployed));
}

// minimum_clearance skips pairs by a bound, so its answer must be compute_clearance's to the
// bit (the same per-pair scans; ties to the first pair).
void expect_same_minimum(const Model& model, const State& state, const ClearanceOptions& options = {}) {
  const Clearance all = compute_clearance(model, state, options);
  const ClearanceMinimum minimum = minimum_clearance(model, state, options);
  EXPECT_EQ(minimum.minimum, all.minimum);
  EXPECT_EQ(minimum.pair, all.minimum_pair);
}

TEST(Clearance, MinimumOverPairsEqualsTheFullCheck) {
  // The satellite stowed, deployed, and with panel_py pushed 0.1 m into the bus (a negative
  // minimum on the second pair, below panel_px's 30 mm).
  const Model model = satellite();
  const State stowed = initial_state(model);
  expect_same_minimum(model, stowed);
  State deployed = stowed, through = stowed;
  for (int k = 0; k < 4; ++k) {
    const Body& panel = model.bodies[static_cast<std::size_t>(2 + k)];
    const Pose pose = panel_pose(k, true);
    deployed.q.segment<3>(panel.q_offset) = pose.position;
    deployed.q.segment<4>(panel.q_offset + 3) = pose.orientation;
  }
  expect_same_minimum(model, deployed);
  const Body& panel_py = model.bodies[3];
  through.q.segment<3>(panel_py.q_offset) -= 0.14 * Eigen::Vector3d::UnitY();
  ASSERT_LT(compute_clearance(model, through).minimum, -0.05);
  expect_same_minimum(model, through);
  // Nothing to check: no pair, +∞.
  expect_same_minimum(model, stowed, {.joint_band = 10.0});
  // The mirror-image tie: two panels at the same gap; the first pair holds it.
  const Plate plate = free_plate(1.0, 1.0, 4, 4);
  ModelBuilder builder;
  builder.add_rigid_body(box_body("bus", Eigen::Vector3d(1, 1, 1), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()));
  Eigen::Matrix3d R_right, R_left;
  R_right << Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitY();
  R_left << -Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY();
  builder.add_flexible_body(plate_body("right", plate, Eigen::Vector3d(-0.5, 0.54, -0.5), R_right));
  builder.add_flexible_body(plate_body("left", plate, Eigen::Vector3d(0.5, -0.54, -0.5), R_left));
  const Model mirrored = builder.build();
  const State state = initial_state(mirrored);
  EXPECT_NEAR(compute_clearance(mirrored, state).pairs[1].distance, 0.04, kTolerance);
  expect_same_minimum(mirrored, state);
}

}  // namespace
}  // namespace limber::multibody
