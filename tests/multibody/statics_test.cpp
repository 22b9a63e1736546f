// Static equilibrium (multibody/statics.h) against closed forms: a spring-hinged bar under a
// tip load, a preloaded hinge held by a hold-down on a floating pair, a clamped flexible beam
// under a tip load and a pinned one sagging under gravity; and the failure named when a load
// meets no stiffness.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "flexible_test_models.h"
#include "multibody/assembly.h"
#include "multibody/constraints.h"
#include "multibody/reactions.h"
#include "multibody/redundancy.h"
#include "multibody/statics.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;
using testing::rod_inertia;

const Eigen::Vector3d kY = Eigen::Vector3d::UnitY();

// Assembled start, its redundancy analysis and the equilibrium from there.
struct Solved {
  State start;
  ConstraintPartition partition;
  StaticsResult statics;
};

Solved solve(const Model& model) {
  Solved s;
  s.start = initial_state(model);
  Workspace ws(model);
  EXPECT_EQ(assemble_positions(model, s.start, ws).status, AssemblyStatus::kOk);
  s.partition = analyse_redundancy(model, s.start, ws);
  s.statics = solve_statics(model, s.partition, s.start);
  return s;
}

// Joint reactions at the equilibrium (v̇ = 0).
Reactions reactions_at(const Model& model, const Solved& s) {
  Workspace ws(model);
  return compute_reactions(model, s.statics.state, Eigen::VectorXd::Zero(model.nv), s.partition, ws);
}

Eigen::Vector3d marker_position(const Model& model, const State& state, const std::string& name) {
  Workspace ws(model);
  update_marker_kinematics(model, state, Stage::kPosition, ws);
  for (std::size_t k = 0; k < model.markers.size(); ++k) {
    if (model.markers[k].name == name) return ws.markers[k].p_W;
  }
  ADD_FAILURE() << "no marker " << name;
  return Eigen::Vector3d::Zero();
}

// A bar of length L hinged to ground about y at the origin, a torsion spring k (free at
// θ = 0) and a downward tip load P: k θ = P L cos θ, θ the bar's turn from +x towards −z.
TEST(Statics, SpringHingedBarUnderTipLoadMatchesTheHandSolution) {
  const double L = 0.8, k = 12.0, P = 25.0;
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("bar", 2.0, rod_inertia(2.0, L), Eigen::Vector3d::Zero(),
                                   Eigen::Matrix3d::Identity(), Eigen::Vector3d(L / 2, 0, 0)));
  const Eigen::Matrix3d R_y = frame_from_axes(kY, Eigen::Vector3d::UnitX());
  builder.add_marker_at("H.ground", "ground", Eigen::Vector3d::Zero(), R_y);
  builder.add_marker_at("H.bar", "bar", Eigen::Vector3d::Zero(), R_y);
  builder.add_joint("H", JointType::kRevolute, "H.ground", "H.bar");
  builder.add_rsda({"spring", "H.ground", "H.bar", k, 0.0, 0.0, {}, false, {}});
  builder.add_marker_at("tip", "bar", Eigen::Vector3d(L, 0, 0));
  builder.add_point_load({"P", "tip", Eigen::Vector3d(0, 0, -P), Eigen::Vector3d::Zero(),
                          TimeFunction::constant(1.0), LoadFrame::kGround});
  const Model model = builder.build();
  const Solved s = solve(model);
  ASSERT_EQ(s.statics.status, StaticsStatus::kOk) << s.statics.message;

  // The hand solution by bisection on f(θ) = k θ − P L cos θ, increasing on [0, π/2].
  double lo = 0.0, hi = std::numbers::pi / 2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (k * mid - P * L * std::cos(mid) > 0.0 ? hi : lo) = mid;
  }
  const double theta = 0.5 * (lo + hi);
  const Eigen::Vector3d tip = marker_position(model, s.statics.state, "tip");
  // Newton stops at a force residual of 1e-9 of the largest force (statics.h): the angle's
  // error is that over the stiffness k + P L sin θ, ~1e-9 relative.
  EXPECT_NEAR(tip.x(), L * std::cos(theta), 1e-9);
  EXPECT_NEAR(tip.z(), -L * std::sin(theta), 1e-9);
  EXPECT_EQ(s.statics.unstable_directions, 0);
  // The hinge carries the load: on the bar, P upwards.
  const Reactions r = reactions_at(model, s);
  EXPECT_NEAR(r.joints[0].force_j_W.z(), P, 1e-7 * P);
  EXPECT_NEAR(r.joints[0].force_j_W.x(), 0.0, 1e-7 * P);
}

// A slider on a translational joint along x pushed along x: nothing holds it, no equilibrium.
// Pushed along y instead, the joint carries the load and the free slide is only reported.
TEST(Statics, LoadAlongAFreeMotionIsNamedNotSolved) {
  for (const bool along_slide : {true, false}) {
    ModelBuilder builder;
    builder.add_rigid_body(body_spec("slider", 1.0, Eigen::Vector3d(1e-2, 1e-2, 1e-2), Eigen::Vector3d::Zero()));
    const Eigen::Matrix3d R_x = frame_from_axes(Eigen::Vector3d::UnitX(), kY);
    builder.add_marker_at("T.ground", "ground", Eigen::Vector3d::Zero(), R_x);
    builder.add_marker_at("T.slider", "slider", Eigen::Vector3d::Zero(), R_x);
    builder.add_joint("T", JointType::kTranslational, "T.ground", "T.slider");
    builder.add_point_load({"push", "T.slider", along_slide ? Eigen::Vector3d(3, 0, 0) : Eigen::Vector3d(0, 3, 0),
                            Eigen::Vector3d::Zero(), TimeFunction::constant(1.0), LoadFrame::kGround});
    const Model model = builder.build();
    const Solved s = solve(model);
    ASSERT_EQ(s.statics.free_motions.size(), 1u);
    EXPECT_NE(s.statics.free_motions[0].description.find("slider translates along [1 0 0]"), std::string::npos)
        << s.statics.free_motions[0].description;
    if (along_slide) {
      EXPECT_EQ(s.statics.status, StaticsStatus::kFreeMotionUnderLoad);
      EXPECT_NEAR(s.statics.free_motions[0].load, 3.0, 1e-9);
      EXPECT_NE(s.statics.message.find("a load meets no stiffness"), std::string::npos) << s.statics.message;
    } else {
      EXPECT_EQ(s.statics.status, StaticsStatus::kOk) << s.statics.message;
      EXPECT_NEAR(s.statics.free_motions[0].load, 0.0, 1e-12);
    }
  }
}

// A floating "bus" and "panel" joined by a hinge about z at the origin whose spring is
// preloaded (torque τ0 = k θ_free on the panel at θ = 0), held shut by a spherical hold-down
// at (0, d, 0): nothing moves, and the hold-down alone carries the spring's torque about the
// hinge axis, |F_x| = τ0 / d on the panel (the revolute has no torque about its axis; the rest
// of the split between the two joints is indeterminate). No ground: the pair floats, with
// six free motions and no load along them.
TEST(Statics, PreloadedHingeHeldByAHoldDownMatchesHandStatics) {
  const double k = 0.5, free_angle = 4.0, d = 0.6;
  const double tau0 = k * free_angle;
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("bus", 400.0, Eigen::Vector3d(90, 90, 70), Eigen::Vector3d(-0.5, 0, 0)));
  builder.add_rigid_body(body_spec("panel", 2.3, Eigen::Vector3d(0.3, 0.1, 0.4), Eigen::Vector3d(0, 0.6, 0)));
  builder.add_marker_at("H.bus", "bus", Eigen::Vector3d::Zero());
  builder.add_marker_at("H.panel", "panel", Eigen::Vector3d::Zero());
  builder.add_joint("H", JointType::kRevolute, "H.bus", "H.panel");
  builder.add_rsda({"spring", "H.bus", "H.panel", k, 0.0, free_angle, {}, false, {}});
  builder.add_marker_at("D.bus", "bus", Eigen::Vector3d(0, d, 0));
  builder.add_marker_at("D.panel", "panel", Eigen::Vector3d(0, d, 0));
  builder.add_joint("D", JointType::kSpherical, "D.bus", "D.panel");
  const Model model = builder.build();
  const Solved s = solve(model);
  ASSERT_EQ(s.statics.status, StaticsStatus::kOk) << s.statics.message;
  EXPECT_EQ(s.statics.free_motions.size(), 6u);
  // Rigid bodies held shut: the start is the equilibrium (to the assembly's 1e-10).
  EXPECT_LT((s.statics.state.q - s.start.q).cwiseAbs().maxCoeff(), 1e-10);
  const Reactions r = reactions_at(model, s);
  // The spring turns the panel about +z, which would carry the point (0, d, 0) towards −x:
  // the hold-down pushes it back with +τ0/d along x (τ0 − d F_x = 0 about the axis), and the
  // revolute balances that force with −τ0/d. Rounding only: 1e-9.
  EXPECT_NEAR(r.joints[1].force_j_W.x(), tau0 / d, 1e-9 * tau0 / d);
  EXPECT_NEAR(r.joints[0].force_j_W.x(), -tau0 / d, 1e-9 * tau0 / d);
}

// A flexible cantilever: the seed rod (1 m, 10 beams) clamped at node 0, its frame fixed to
// ground by a bracket there, 4 normal modes and the attachment mode of the tip's z force.
// That mode spans the FE static solution K⁻¹ f exactly, so the tip deflection is Euler-
// Bernoulli's P L³ / (3 E I_y) (cubic beams are exact for a tip load) to the solver's 1e-9.
TEST(Statics, FlexibleCantileverTipLoadMatchesTheStaticSolution) {
  const double L = 1.0, P = 2.0;
  const fe::FeModel fe_model = testing::straight_rod(L, 10, {0});
  const int tip = fe_model.node_count() - 1;
  const modal::ModeSet modes = testing::normal_modes(fe_model, 4, {{tip, {fe::Dof::kUz}}});
  ModelBuilder builder;
  FlexibleBodySpec spec = testing::flexible_spec("rod", fe_model, modes, {});
  builder.add_flexible_body(spec);
  builder.add_marker_at("root.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_node_marker("root.rod", "rod", 0);
  builder.add_joint("root", JointType::kBracket, "root.ground", "root.rod");
  builder.add_node_marker("tip", "rod", tip);
  builder.add_point_load({"P", "tip", Eigen::Vector3d(0, 0, -P), Eigen::Vector3d::Zero(),
                          TimeFunction::constant(1.0), LoadFrame::kGround});
  const Model model = builder.build();
  const Solved s = solve(model);
  ASSERT_EQ(s.statics.status, StaticsStatus::kOk) << s.statics.message;
  const fe::BeamProperty rod = testing::seed_rod_property();
  const double delta = P * L * L * L / (3.0 * rod.material.youngs_modulus * rod.section.inertia_y);
  const Eigen::Vector3d p_tip = marker_position(model, s.statics.state, "tip");
  EXPECT_NEAR(p_tip.z() / -delta, 1.0, 1e-9);
  EXPECT_NEAR(p_tip.x(), L, 1e-12);
}

// The same rod free-free, pinned at both ends (spherical joints to ground; its spin about
// its own axis stays free and unloaded), sagging under gravity. Its deformation is the
// inertia-relief response to the support forces alone (gravity is a rigid-body load), which
// the attachment modes of the two supports' z forces span: mid-span sag 5 w L⁴ / (384 E I_y)
// with w = ρ A g, exact at the nodes of cubic beams, to the solver's tolerance.
TEST(Statics, PinnedBeamGravitySagMatchesTheClosedForm) {
  const double L = 1.0, g = 9.81;
  const fe::FeModel fe_model = testing::straight_rod(L, 10);
  const int end = fe_model.node_count() - 1, mid = end / 2;
  const modal::ModeSet modes =
      testing::normal_modes(fe_model, 4, {{0, {fe::Dof::kUz}}, {end, {fe::Dof::kUz}}});
  ModelBuilder builder;
  builder.set_gravity(Eigen::Vector3d(0, 0, -g));
  builder.add_flexible_body(testing::flexible_spec("rod", fe_model, modes, {}));
  builder.add_marker_at("A.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_node_marker("A.rod", "rod", 0);
  builder.add_joint("A", JointType::kSpherical, "A.ground", "A.rod");
  builder.add_marker_at("B.ground", "ground", Eigen::Vector3d(L, 0, 0));
  builder.add_node_marker("B.rod", "rod", end);
  builder.add_joint("B", JointType::kSpherical, "B.ground", "B.rod");
  builder.add_node_marker("mid", "rod", mid);
  const Model model = builder.build();
  const Solved s = solve(model);
  ASSERT_EQ(s.statics.status, StaticsStatus::kOk) << s.statics.message;
  const fe::BeamProperty rod = testing::seed_rod_property();
  const double w = rod.material.density * rod.section.area * g;
  const double sag = 5.0 * w * std::pow(L, 4) / (384.0 * rod.material.youngs_modulus * rod.section.inertia_y);
  EXPECT_NEAR(marker_position(model, s.statics.state, "mid").z() / -sag, 1.0, 1e-8);
  // Each support carries half the weight.
  const Reactions r = reactions_at(model, s);
  EXPECT_NEAR(r.joints[0].force_j_W.z(), 0.5 * w * L, 1e-8 * w * L);
  EXPECT_NEAR(r.joints[1].force_j_W.z(), 0.5 * w * L, 1e-8 * w * L);
}

}  // namespace
}  // namespace limber::multibody
