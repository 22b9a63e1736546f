// Equations of motion of a flexible body checked at one instant, without an integrator:
// along the motion v̇ = M⁻¹ Q of a free body the linear and angular momentum (momentum.h)
// must not change and the energy must fall by the damping power only (central differences in
// time); the modal rows must satisfy Lagrange's equations; gravity must be −∂V/∂q. Also
// the builder's checks of flexible bodies and the linear-range warning.
#include <cmath>

#include <gtest/gtest.h>

#include "multibody/assembly.h"
#include "multibody/body.h"
#include "multibody/dynamics.h"
#include "multibody/linear_range.h"
#include "multibody/momentum.h"
#include "multibody/rotation.h"
#include "flexible_test_models.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

// Central differences: truncation h² |f'''| ~ 1e-10 |f|, rounding 1e-16 |f| / h ~ 1e-11 |f|.
constexpr double kStep = 1e-5;
// Along the motion the modal accelerations are large (ω² η ~ 1e4 for modes up to 2.8 kHz):
// a plain central difference with q ⊕ ±h v, v ± h v̇ has an h² error of 1e-2 relative at
// h = 1e-5 (measured); one Richardson step (h, h/2) removes it, leaving O(h⁴) ~ 1e-10 at
// h = 1e-6, with rounding 1e-16/h ~ 1e-10 relative.
constexpr double kMotionStep = 1e-6;

// The space frame floating free in a generic deformed, spinning, vibrating state.
// constrained: modes clamped at node 0 (frame attached there), else free-free modes.
Model floating_frame(bool constrained, bool gravity) {
  const fe::FeModel frame = testing::space_frame(4, constrained ? std::vector<int>{0} : std::vector<int>{});
  FlexibleBodySpec spec = testing::flexible_spec("frame", frame, testing::normal_modes(frame, 5), ModalDamping::ratio(0.02));
  spec.initial_pose.position = Eigen::Vector3d(0.2, -0.1, 0.3);
  spec.initial_pose.orientation = quaternion_from_matrix(axis_angle_matrix(Eigen::Vector3d(1, -1, 2), 0.7));
  spec.initial_velocity_W = Eigen::Vector3d(0.3, -0.2, 0.5);
  spec.initial_angular_velocity_B = Eigen::Vector3d(4.0, -3.0, 5.0);
  spec.initial_modal_coordinates = (Eigen::VectorXd(5) << 0.01, -0.008, 0.006, 0.004, -0.003).finished();
  spec.initial_modal_velocities = (Eigen::VectorXd(5) << 0.5, 0.3, -0.4, 0.2, 0.1).finished();
  ModelBuilder builder;
  if (gravity) builder.set_gravity(Eigen::Vector3d(1.0, -2.0, -9.81));
  builder.add_flexible_body(spec);
  return builder.build();
}

Eigen::VectorXd perturb(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& dv) {
  Eigen::VectorXd out = q;
  for (size_t b = 0; b < model.bodies.size(); ++b) integrate_body_coordinates(model, b, q, dv, out);
  return out;
}

Eigen::VectorXd accelerations(const Model& model, const State& state, Workspace& ws) {
  mass_matrix(model, state, ws);
  generalized_forces(model, state, ws);
  return ws.M.llt().solve(ws.Q);
}

// Rate of f along the motion: central differences with q ⊕ ±h v, v ± h v̇ (second-order
// terms equal on both sides), h = kMotionStep and h/2 combined by Richardson extrapolation.
template <class F>
auto rate_along_motion(const Model& model, const State& state, const Eigen::VectorXd& v_dot, F f) {
  const auto central = [&](double h) {
    State plus = state, minus = state;
    plus.q = perturb(model, state.q, h * state.v);
    minus.q = perturb(model, state.q, -h * state.v);
    plus.v = state.v + h * v_dot;
    minus.v = state.v - h * v_dot;
    return ((f(plus) - f(minus)) / (2 * h)).eval();
  };
  return ((4.0 * central(0.5 * kMotionStep) - central(kMotionStep)) / 3.0).eval();
}

class FreeFlexibleBody : public ::testing::TestWithParam<bool> {};

TEST_P(FreeFlexibleBody, MomentumIsConservedAndEnergyFallsByTheDampingPower) {
  const Model model = floating_frame(GetParam(), false);
  Workspace ws(model);
  const State state = initial_state(model);
  const Eigen::VectorXd v_dot = accelerations(model, state, ws);
  // Momentum: its rate against the size of the terms that make it up (|M v̇| rows).
  const auto dh =
      rate_along_motion(model, state, v_dot, [&](const State& s) { return system_momentum(model, s); });
  const double scale = (ws.M * v_dot).head<6>().cwiseAbs().maxCoeff() + 1.0;
  EXPECT_LT(dh.cwiseAbs().maxCoeff(), 1e-7 * scale) << dh.transpose();
  // Energy T + V_strain falls by η̇ᵀ C η̇ (internal damping, the only non-conservative force).
  const Body& body = model.bodies[1];
  const Eigen::VectorXd eta_dot = state.v.tail(body.nv - 6);
  const double damping_power = eta_dot.dot(body.flexible->damping.cwiseProduct(eta_dot));
  const auto de = rate_along_motion(model, state, v_dot, [&](const State& s) {
    const EnergyTerms e = energies(model, s, ws);
    return Eigen::Matrix<double, 1, 1>(e.kinetic + e.strain);
  });
  EXPECT_NEAR(de(0), -damping_power, 1e-7 * (damping_power + 1.0));
  EXPECT_GT(damping_power, 1e-3);  // the check has something to see
}

TEST_P(FreeFlexibleBody, ModalRowsSatisfyLagrangesEquations) {
  // η are true coordinates: Q_v,η = ∂T/∂η − (Ṁ v)_η, with Q_v the quadratic-velocity
  // forces (Q without the elastic −K η and damping −C η̇; no gravity here).
  const Model model = floating_frame(GetParam(), false);
  Workspace ws(model);
  const State state = initial_state(model);
  const Body& body = model.bodies[1];
  const int nm = body.nv - 6;
  generalized_forces(model, state, ws);
  const Eigen::VectorXd eta = state.q.tail(nm), eta_dot = state.v.tail(nm);
  const Eigen::VectorXd Q_v = ws.Q.tail(nm) + body.flexible->stiffness.cwiseProduct(eta) +
                              body.flexible->damping.cwiseProduct(eta_dot);
  const auto Mv_rate = rate_along_motion(model, state, Eigen::VectorXd::Zero(model.nv), [&](const State& s) {
    mass_matrix(model, s, ws);
    return Eigen::VectorXd(ws.M * state.v);  // Ṁ v: v held
  });
  Eigen::VectorXd dT_deta(nm);
  for (int k = 0; k < nm; ++k) {
    State plus = state, minus = state;
    plus.q(7 + k) += kStep;
    minus.q(7 + k) -= kStep;
    dT_deta(k) = (energies(model, plus, ws).kinetic - energies(model, minus, ws).kinetic) / (2 * kStep);
  }
  const Eigen::VectorXd expected = dT_deta - Mv_rate.tail(nm);
  EXPECT_LT((Q_v - expected).cwiseAbs().maxCoeff(), 1e-7 * (expected.cwiseAbs().maxCoeff() + 1.0))
      << "Q_v,η " << Q_v.transpose() << "\nexpected " << expected.transpose();
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 1e-2);  // centrifugal and gyroscopic terms are there
}

TEST_P(FreeFlexibleBody, GravityIsMinusTheGradientOfItsPotential) {
  const Model with = floating_frame(GetParam(), true), without = floating_frame(GetParam(), false);
  Workspace ws_with(with), ws_without(without);
  const State state = initial_state(with);
  generalized_forces(with, state, ws_with);
  generalized_forces(without, state, ws_without);
  const Eigen::VectorXd Q_g = ws_with.Q - ws_without.Q;
  for (int k = 0; k < with.nv; ++k) {
    State plus = state, minus = state;
    plus.q = perturb(with, state.q, kStep * Eigen::VectorXd::Unit(with.nv, k));
    minus.q = perturb(with, state.q, -kStep * Eigen::VectorXd::Unit(with.nv, k));
    const double dV = (energies(with, plus, ws_with).gravity - energies(with, minus, ws_with).gravity) / (2 * kStep);
    EXPECT_NEAR(Q_g(k), -dV, 1e-8 * (std::abs(dV) + 1.0)) << "velocity direction " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(FreeFreeAndConstrainedModes, FreeFlexibleBody, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Constrained" : "FreeFree"; });

TEST(FlexibleBody, StrainEnergyIsHalfEtaKEta) {
  const Model model = floating_frame(false, false);
  Workspace ws(model);
  const State state = initial_state(model);
  const FlexibleBody& f = *model.bodies[1].flexible;
  const Eigen::VectorXd eta = state.q.tail(f.mode_count());
  EXPECT_DOUBLE_EQ(energies(model, state, ws).strain, 0.5 * eta.dot(f.stiffness.cwiseProduct(eta)));
}

TEST(FlexibleBody, BuilderRejectsInconsistentInput) {
  const fe::FeModel rod = testing::straight_rod(1.0, 10);
  const modal::ModeSet modes = testing::normal_modes(rod, 3);
  ModelBuilder builder;
  // Nodes that do not match the shapes.
  FlexibleBodySpec wrong_nodes = testing::flexible_spec("a", rod, modes, {});
  wrong_nodes.node_positions_B.pop_back();
  EXPECT_THROW(builder.add_flexible_body(wrong_nodes), InputError);
  // A rigid translation among the modes: the frame already carries it.
  FlexibleBodySpec rigid_mode = testing::flexible_spec("b", rod, modes, {});
  for (int p = 0; p < rod.node_count(); ++p) {
    rigid_mode.modes.shapes.block(6 * p, 0, 6, 1) << 0, 0, 1.0 / std::sqrt(1.564), 0, 0, 0;
  }
  rigid_mode.modes.invariants.translation_coupling.col(0) << 0, 0, std::sqrt(1.564);
  EXPECT_THROW(builder.add_flexible_body(rigid_mode), InputError);
  // Negative damping, wrong number of ratios.
  EXPECT_THROW(builder.add_flexible_body(testing::flexible_spec("c", rod, modes, ModalDamping::ratio(-0.1))), InputError);
  EXPECT_THROW(builder.add_flexible_body(testing::flexible_spec("c", rod, modes, ModalDamping::per_mode(Eigen::Vector2d(0.1, 0.1)))),
               InputError);
  // Markers: on nodes of flexible bodies only, and existing nodes.
  builder.add_flexible_body(testing::flexible_spec("rod", rod, modes, {}));
  builder.add_rigid_body(testing::body_spec("box", 1.0, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d::Zero()));
  EXPECT_THROW(builder.add_marker("m", "rod", Eigen::Vector3d::Zero()), InputError);
  EXPECT_THROW(builder.add_node_marker("m", "box", 0), InputError);
  EXPECT_THROW(builder.add_node_marker("m", "rod", 11), InputError);
  builder.add_node_marker("tip", "rod", 10);
  const Model model = builder.build();
  EXPECT_EQ(model.nq, 7 + 3 + 7);
  EXPECT_EQ(model.nv, 6 + 3 + 6);
  EXPECT_EQ(model.markers[0].p_BM, Eigen::Vector3d(1, 0, 0));
  // Default damping: kDefaultModalDampingRatio in every mode, c_i = 2 ζ ω_i.
  const FlexibleBody& f = *model.bodies[1].flexible;
  EXPECT_NEAR(f.damping(2), 2 * kDefaultModalDampingRatio * std::sqrt(f.stiffness(2)), 1e-12 * f.damping(2));
}

TEST(FlexibleBody, LinearRangeWarning) {
  // First free-free bending mode of the 1 m rod scaled to a given peak displacement: the
  // warning fires above 5 % of the size (1 m) and names the body.
  const fe::FeModel rod = testing::straight_rod(1.0, 20);
  ModelBuilder builder;
  builder.add_flexible_body(testing::flexible_spec("rod", rod, testing::normal_modes(rod, 1), {}));
  const Model model = builder.build();
  const FlexibleBody& f = *model.bodies[1].flexible;
  double peak = 0.0;
  for (int p = 0; p < f.node_count(); ++p) peak = std::max(peak, f.translation_shapes(p).col(0).norm());
  // The end slope of the first free-free mode is ~4.7 times its peak over the length:
  // 0.19 rad at 4 cm, above the rotation limit; a looser rotation limit isolates the
  // displacement check.
  const LinearRangeLimits limits{0.05, 0.5};
  State state = initial_state(model);
  state.q(7) = 0.04 / peak;
  std::vector<LinearRangeCheck> checks = check_linear_range(model, state, limits);
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_NEAR(checks[0].max_displacement, 0.04, 1e-12);
  EXPECT_NEAR(checks[0].size, 1.0, 1e-12);
  EXPECT_TRUE(checks[0].warning.empty()) << checks[0].warning;
  state.q(7) = 0.06 / peak;
  checks = check_linear_range(model, state, limits);
  EXPECT_NE(checks[0].warning.find("\"rod\""), std::string::npos) << checks[0].warning;
  EXPECT_NE(checks[0].warning.find("6.0 %"), std::string::npos) << checks[0].warning;
  // With the default limits the same deflection's end rotation is flagged.
  checks = check_linear_range(model, state);
  EXPECT_NE(checks[0].warning.find("rotation"), std::string::npos) << checks[0].warning;
  // The mode is symmetric: both ends rotate alike, equal to the eigen-solver's tolerance
  // (1e-10), so either end may be the one named.
  EXPECT_TRUE(checks[0].rotation_node == 0 || checks[0].rotation_node == rod.node_count() - 1)
      << checks[0].rotation_node;
}

// A 1 m rod (20 beams, 4 free-free modes, no axial one) from the ground origin along x,
// joined to ground at both ends by spherical joints, the far end's ground point at p_far;
// with `clamp`, the near end is a bracket.
Model rod_to_point(bool clamp, const Eigen::Vector3d& p_far) {
  const fe::FeModel rod = testing::straight_rod(1.0, 20);
  ModelBuilder builder;
  builder.add_flexible_body(testing::flexible_spec("rod", rod, testing::normal_modes(rod, 4), ModalDamping::ratio(0.0)));
  builder.add_node_marker("A.rod", "rod", 0);
  builder.add_marker("A.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_node_marker("B.rod", "rod", 20);
  builder.add_marker("B.ground", "ground", p_far);
  builder.add_joint("A", clamp ? JointType::kBracket : JointType::kSpherical, "A.ground", "A.rod");
  builder.add_joint("B", JointType::kSpherical, "B.ground", "B.rod");
  return builder.build();
}

TEST(FlexibleBody, AssemblyDeformsTheBodyOnlyWhenTheJointsRequireIt) {
  // Pinned at the near end, the rod reaches a point 1 m away, 1 mm up, by turning: its modes
  // keep their given zero values exactly.
  const Model pinned = rod_to_point(false, Eigen::Vector3d(std::sqrt(1.0 - 1e-6), 0.0, 1e-3));
  Workspace ws_pinned(pinned);
  State state = initial_state(pinned);
  const AssemblyResult turned = assemble_positions(pinned, state, ws_pinned);
  ASSERT_EQ(turned.status, AssemblyStatus::kOk) << turned.message;
  EXPECT_FALSE(turned.modes_released);
  const Body& rod = pinned.bodies[1];
  EXPECT_EQ(state.q.segment(rod.q_offset + 7, rod.nv - 6).lpNorm<Eigen::Infinity>(), 0.0);
  // Clamped, it reaches a point 0.01 mm above its tip only by bending: the modes are let move
  // and the joints close (0.01 mm: linear modes cannot shorten the chord, and the frame's tilt
  // costs (δ/L)²/2 = 5e-11 m, below the assembly tolerance).
  const Model clamped = rod_to_point(true, Eigen::Vector3d(1.0, 0.0, 1e-5));
  Workspace ws_clamped(clamped);
  state = initial_state(clamped);
  const AssemblyResult bent = assemble_positions(clamped, state, ws_clamped);
  ASSERT_EQ(bent.status, AssemblyStatus::kOk) << bent.message;
  EXPECT_TRUE(bent.modes_released);
  EXPECT_LE(bent.residual, 1e-10);
  // η of mass-normalised modes (tip amplitude ~1.6 per unit η, seed rod) for 1e-5 m.
  EXPECT_GT(state.q.segment(clamped.bodies[1].q_offset + 7, 4).lpNorm<Eigen::Infinity>(), 1e-6);
}

}  // namespace
}  // namespace limber::multibody
