// Linearization (multibody/linearization.h, hybrid_coordinates.h) against closed forms: a
// free-floating hinged pair with a torsion spring (centres on and off the axis), a pendulum
// about its hanging and its upside-down equilibrium, a preloaded spring held by a slider about
// the equilibrium statics finds,
// a damped spring–mass on a slider, a clamped flexible beam against its own component modes,
// the effective masses' completeness on an appendage held by springs and on a clamped rod with
// all its modes, the coupling matrices of a cantilever against Euler–Bernoulli; and a singular
// linearization point named.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fe/assembly.h"
#include "flexible_test_models.h"
#include "linear_test_models.h"
#include "modal/rigid_body_modes.h"
#include "multibody/assembly.h"
#include "multibody/hybrid_coordinates.h"
#include "multibody/linearization.h"
#include "multibody/redundancy.h"
#include "multibody/statics.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The assembled start (or its equilibrium), tangent matrices and the system modes.
struct Linearized {
  State point;
  ConstraintPartition partition;
  TangentMatrices tangent;
  int free_motions = 0;
  SystemModes modes;
};

Linearized linearize(const Model& model, bool statics) {
  Linearized out;
  out.point = initial_state(model);
  Workspace ws(model);
  EXPECT_EQ(assemble_positions(model, out.point, ws).status, AssemblyStatus::kOk);
  out.partition = analyse_redundancy(model, out.point, ws);
  if (statics) {
    const StaticsResult equilibrium = solve_statics(model, out.partition, out.point);
    EXPECT_EQ(equilibrium.status, StaticsStatus::kOk) << equilibrium.message;
    out.point = equilibrium.state;
  }
  std::string message;
  EXPECT_EQ(tangent_matrices(model, out.partition, out.point, out.tangent, message), LinearizationStatus::kOk)
      << message;
  const Eigen::MatrixXd Z = null_space_basis(out.tangent.G, model.nv);
  out.free_motions = static_cast<int>(Z.cols());
  out.modes = system_modes(out.tangent, Z);
  return out;
}

// Two rigid bodies floating free, joined by a revolute about z through both centres of mass,
// with a torsion spring k: six rigid modes and one relative rotation at
// f = √(k (1/J1 + 1/J2)) / 2π. Tolerance 1e-8 relative: the spring is linear in the hinge angle
// and unloaded at the state, so only the differences' rounding of that angle (1e-16 / ε with
// ε = 1e-6, per entry of M⁻¹K) is left: measured 7e-11.
TEST(Linearization, FloatingHingedPairHasSixRigidModesAndTheTorsionFrequency) {
  const double J1 = 3.0, J2 = 0.5, k = 20.0;
  const Linearized lin = linearize(testing::floating_hinged_pair(J1, J2, k), false);
  EXPECT_EQ(lin.free_motions, 7);
  EXPECT_EQ(lin.modes.rigid_modes, 6);
  const double f = std::sqrt(k * (1.0 / J1 + 1.0 / J2)) / kTwoPi;
  EXPECT_NEAR(lin.modes.frequencies_hz(6) / f, 1.0, 1e-8);
  EXPECT_NEAR(lin.modes.damping(6), 0.0, 1e-12);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(lin.modes.frequencies_hz(i), 0.0);
  // The rigid zeros sit far below the threshold (1e-4 of the highest frequency).
  EXPECT_LT(lin.modes.zero_threshold_hz, 1e-3 * f);
}

// The same pair with both centres of mass off the axis (r1, r2 from the hinge, in the plane
// normal to it): the motion stays planar (mirror symmetry in z), the hinge point's translation
// h is cyclic, and condensing it at zero momentum (hand derivation: T = ½ Σ m_i |ḣ + θ̇_i ẑ×r_i|²
// + ½ J_i θ̇_i², Routh) leaves on (θ1, θ2) the mass M' = diag(J_i + m_i |r_i|²) − m_i m_j
// (ẑ×r_i)·(ẑ×r_j)/(m1 + m2) against K = k u uᵀ, u = (−1, 1): ω² = k uᵀ M'⁻¹ u. Six rigid modes
// again. Tolerance 1e-8 as above (measured 7e-11).
TEST(Linearization, FloatingHingedPairWithOffsetCentresMatchesTheHandDerivation) {
  const double m1 = 50.0, m2 = 2.0, J1 = 3.0, J2 = 0.5, k = 20.0;
  const Eigen::Vector2d r1(-0.4, 0.1), r2(0.7, -0.2);
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("bus", m1, Eigen::Vector3d(4.0, 5.0, J1), Eigen::Vector3d::Zero(),
                                   Eigen::Matrix3d::Identity(), Eigen::Vector3d(r1.x(), r1.y(), 0)));
  builder.add_rigid_body(body_spec("panel", m2, Eigen::Vector3d(0.7, 0.9, J2), Eigen::Vector3d::Zero(),
                                   Eigen::Matrix3d::Identity(), Eigen::Vector3d(r2.x(), r2.y(), 0)));
  builder.add_marker_at("H.bus", "bus", Eigen::Vector3d::Zero());
  builder.add_marker_at("H.panel", "panel", Eigen::Vector3d::Zero());
  builder.add_joint("H", JointType::kRevolute, "H.bus", "H.panel");
  builder.add_rsda({"spring", "H.bus", "H.panel", k, 0.0, 0.0, {}, false, {}});
  const Model model = builder.build();
  const Linearized lin = linearize(model, false);
  EXPECT_EQ(lin.modes.rigid_modes, 6);
  const Eigen::Vector2d a1(-r1.y(), r1.x()), a2(-r2.y(), r2.x());  // ẑ × r_i
  Eigen::Matrix2d M;
  M << J1 + m1 * r1.squaredNorm() - m1 * m1 * a1.dot(a1) / (m1 + m2), -m1 * m2 * a1.dot(a2) / (m1 + m2),
      -m1 * m2 * a1.dot(a2) / (m1 + m2), J2 + m2 * r2.squaredNorm() - m2 * m2 * a2.dot(a2) / (m1 + m2);
  const Eigen::Vector2d u(-1.0, 1.0);
  const double f = std::sqrt(k * u.dot(M.inverse() * u)) / kTwoPi;
  EXPECT_NEAR(lin.modes.frequencies_hz(6) / f, 1.0, 1e-8);
}

// A body hinged to ground about y at its frame origin, centre of mass l below, hanging under
// gravity (the equilibrium from statics): f = √(m g l / J_pivot) / 2π. The stiffness is the
// joint's geometric term ∂(Gᵀλ)/∂ξ and gravity's moment: both in the differences. Tolerance
// 1e-8 relative: the differences' rounding, 1e-16 / ε of forces ~ m g, is 1e-10 of the
// stiffness m g l.
TEST(Linearization, PendulumAboutItsHangingEquilibriumHasTheClosedFormFrequency) {
  const double m = 2.0, l = 0.5, g = 9.81, Jy = 0.2;
  const Model model = testing::pendulum_builder(m, Jy, g, -l).build();
  const Linearized lin = linearize(model, true);
  ASSERT_EQ(lin.free_motions, 1);
  EXPECT_EQ(lin.modes.rigid_modes, 0);
  const double f = std::sqrt(m * g * l / (Jy + m * l * l)) / kTwoPi;
  EXPECT_NEAR(lin.modes.frequencies_hz(0) / f, 1.0, 1e-8);
  EXPECT_NEAR(lin.modes.undamped_hz(0) / f, 1.0, 1e-8);
  EXPECT_NEAR(lin.tangent.vdot.norm(), 0.0, 1e-9);  // an equilibrium: v̇0 = 0
}

// The same pendulum balanced upside down (centre of mass l above the pivot, an equilibrium):
// one unstable mode, reported as the negative frequency −√(m g l / J_pivot)/2π, with a zero
// damping ratio rather than a NaN. Tolerance as above.
TEST(Linearization, InvertedPendulumIsOneUnstableModeWithANegativeFrequency) {
  const double m = 2.0, l = 0.5, g = 9.81, Jy = 0.2;
  const Model model = testing::pendulum_builder(m, Jy, g, l).build();
  const Linearized lin = linearize(model, true);
  ASSERT_EQ(lin.free_motions, 1);
  EXPECT_EQ(lin.modes.unstable_modes, 1);
  const double f = std::sqrt(m * g * l / (Jy + m * l * l)) / kTwoPi;
  EXPECT_NEAR(lin.modes.frequencies_hz(0) / -f, 1.0, 1e-8);
  EXPECT_EQ(lin.modes.damping(0), 0.0);
  EXPECT_EQ(lin.modes.approximate_damping, 0);
}

// A preloaded spring held in equilibrium by a joint, about the equilibrium from statics: a
// mass m on a translational joint along y through (L, 0, 0), a spring k of free length L0 < L
// from the ground origin to it. Its tension T = k (L − L0) is held by the joint; across the
// joint only the spring's turning gives stiffness. Hand derivation: with the spring's length
// l(y) = √(L² + y²), V(y) = ½ k (l − L0)², V'' = k (1 − L0 L² / l³), the equilibrium y = 0
// and ω² = V''(0) / m = T / (m L) (a string's transverse stiffness). The run starts off the
// equilibrium at y0, which statics must move to y = 0; about the assembled start instead the
// frequency is √(V''(y0) / m) (M constant, so K = V''(y0) there although v̇0 ≠ 0), which the
// second half checks. Tolerance 1e-8 relative: statics stops at a force residual of 1e-9 of
// T, an error of ~1e-9 L in y that moves V'' by O(y²); the differences' rounding is 1e-10.
TEST(Linearization, PreloadedSpringHeldByASliderHasTheStringStiffnessAboutItsEquilibrium) {
  const double m = 2.0, k = 500.0, L = 1.0, L0 = 0.6, y0 = 0.3;
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("mass", m, Eigen::Vector3d(0.1, 0.1, 0.1), Eigen::Vector3d(L, y0, 0)));
  const Eigen::Matrix3d R_y = frame_from_axes(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
  builder.add_marker_at("T.ground", "ground", Eigen::Vector3d(L, 0, 0), R_y);
  builder.add_marker_at("T.mass", "mass", Eigen::Vector3d(L, y0, 0), R_y);
  builder.add_joint("T", JointType::kTranslational, "T.ground", "T.mass");
  builder.add_marker_at("S.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_marker_at("S.mass", "mass", Eigen::Vector3d(L, y0, 0));
  builder.add_tsda({"spring", "S.ground", "S.mass", k, 0.0, L0, {}});
  const Model model = builder.build();
  const auto V_yy = [&](double y) { return k * (1.0 - L0 * L * L / std::pow(L * L + y * y, 1.5)); };

  const Linearized held = linearize(model, true);
  ASSERT_EQ(held.free_motions, 1);
  const int y_index = model.bodies[static_cast<std::size_t>(model.find_body("mass"))].q_offset + 1;
  EXPECT_NEAR(held.point.q(y_index), 0.0, 1e-9);  // statics found the equilibrium
  const double f = std::sqrt(k * (L - L0) / (m * L)) / kTwoPi;
  EXPECT_NEAR(V_yy(0.0), k * (L - L0) / L, 1e-12 * k);
  EXPECT_NEAR(held.modes.frequencies_hz(0) / f, 1.0, 1e-8);
  EXPECT_NEAR(held.tangent.vdot.norm(), 0.0, 1e-9);

  const Linearized start = linearize(model, false);
  EXPECT_NEAR(start.modes.frequencies_hz(0) / (std::sqrt(V_yy(y0) / m) / kTwoPi), 1.0, 1e-8);
  EXPECT_GT(start.tangent.vdot.norm(), 1.0);  // not an equilibrium: the spring pulls it back
}

// A mass on a translational joint along x, held by a spring–damper (k, c) to ground at its
// free length: f = √(k/m) / 2π (the natural frequency |s| of the damped pair) and
// ζ = c / (2 √(k m)). Tolerance 1e-9: linear spring and damper, the differences exact to their
// rounding (measured 1.3e-11 on both).
TEST(Linearization, DampedSpringMassOnASliderHasTheClosedFormDampingRatio) {
  const double m = 4.0, k = 400.0, c = 8.0;
  const Linearized lin = linearize(testing::spring_mass_on_slider(m, k, c), false);
  ASSERT_EQ(lin.free_motions, 1);
  EXPECT_NEAR(lin.modes.frequencies_hz(0) / (std::sqrt(k / m) / kTwoPi), 1.0, 1e-9);
  EXPECT_NEAR(lin.modes.damping(0) / (c / (2.0 * std::sqrt(k * m))), 1.0, 1e-9);
  EXPECT_EQ(lin.modes.approximate_damping, 0);
}

// The seed rod (1 m, 10 beams) clamped at node 0 and bracketed to ground there, with 4 normal
// modes and the tip's attachment mode: the linearized mechanism's frequencies are the mode
// set's own (the second method: limber's modal reduction), and each mode's damping ratio the
// body's modal ratio. Tolerance 1e-9 relative: the elastic forces are linear in η and the
// frame is held, so the differences are exact to rounding.
TEST(Linearization, ClampedFlexibleBeamHasItsComponentModesFrequencies) {
  const fe::FeModel fe_model = testing::straight_rod(1.0, 10, {0});
  const int tip = fe_model.node_count() - 1;
  const modal::ModeSet modes = testing::normal_modes(fe_model, 4, {{tip, {fe::Dof::kUz}}});
  ModelBuilder builder;
  builder.add_flexible_body(testing::flexible_spec("rod", fe_model, modes, {}));
  builder.add_marker_at("root.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_node_marker("root.rod", "rod", 0);
  builder.add_joint("root", JointType::kBracket, "root.ground", "root.rod");
  const Model model = builder.build();
  const Linearized lin = linearize(model, false);
  const int nm = static_cast<int>(modes.modes.size());
  ASSERT_EQ(lin.free_motions, nm);
  EXPECT_EQ(lin.modes.rigid_modes, 0);
  for (int i = 0; i < nm; ++i) {
    const double f = std::sqrt(modes.modal_stiffness(i)) / kTwoPi;
    EXPECT_NEAR(lin.modes.undamped_hz(i) / f, 1.0, 1e-9) << "mode " << i;
    EXPECT_NEAR(lin.modes.frequencies_hz(i) / modes.modes[static_cast<std::size_t>(i)].frequency_hz, 1.0, 1e-9)
        << "mode " << i;
    EXPECT_NEAR(lin.modes.damping(i), kDefaultModalDampingRatio, 1e-9) << "mode " << i;
  }
}

// A bus and an appendage joined by six springs only (no joint), floating: with the bus held,
// every appendage motion is a held motion, so the effective masses over all held modes sum to
// the appendage's rigid mass about the bus centre of mass: m in T1–T3 and I_c + m (|d|² − d_k²)
// in R1–R3 (d the appendage's CoM from the bus's). Tolerance 1e-9 relative: Ψ, M and the
// orthonormal null-space basis are exact to rounding (~1e-13). The whole pair's mass
// properties checked against the hand sums likewise.
TEST(Linearization, EffectiveMassesOfAnAppendageOnSpringsSumToItsRigidMass) {
  const double mb = 100.0, ma = 5.0;
  const Eigen::Vector3d Jb(10, 12, 14), Ja(0.2, 0.3, 0.4), d(0.3, 0.0, 2.0);
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("bus", mb, Jb, Eigen::Vector3d::Zero()));
  builder.add_rigid_body(body_spec("wing", ma, Ja, d));
  // Three vertical springs (z, rx, ry) and three horizontal ones (x, y, rz).
  const Eigen::Vector3d a1 = d + Eigen::Vector3d(0.5, 0, 0), a2 = d + Eigen::Vector3d(-0.5, 0, 0),
                        a3 = d + Eigen::Vector3d(0, 0.5, 0);
  const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> springs = {
      {a1, a1 - Eigen::Vector3d(0, 0, 1)}, {a2, a2 - Eigen::Vector3d(0, 0, 1)}, {a3, a3 - Eigen::Vector3d(0, 0, 1)},
      {a1, a1 - Eigen::Vector3d(0, 1, 0)}, {a2, a2 - Eigen::Vector3d(0, 1, 0)}, {a3, a3 - Eigen::Vector3d(1, 0, 0)}};
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const std::string name = "k" + std::to_string(s);
    builder.add_marker_at(name + ".wing", "wing", springs[s].first);
    builder.add_marker_at(name + ".bus", "bus", springs[s].second);
    builder.add_tsda({name, name + ".bus", name + ".wing", 1e4 * (1.0 + s), 0.0, 1.0, {}});
  }
  const Model model = builder.build();
  const Linearized lin = linearize(model, false);
  EXPECT_EQ(lin.modes.rigid_modes, 6);
  const CantileveredModes held = cantilevered_modes(model, lin.point, lin.tangent, model.find_body("bus"));
  ASSERT_EQ(held.modes.frequencies_hz.size(), 6);
  EXPECT_EQ(held.modes.rigid_modes, 0);
  const Eigen::Matrix<double, 6, 1> expected =
      (Eigen::Matrix<double, 6, 1>() << ma, ma, ma, Ja.x() + ma * (d.y() * d.y() + d.z() * d.z()),
       Ja.y() + ma * (d.x() * d.x() + d.z() * d.z()), Ja.z() + ma * (d.x() * d.x() + d.y() * d.y()))
          .finished();
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(held.effective_sum(k) / expected(k), 1.0, 1e-9) << "direction " << k;
    EXPECT_NEAR(held.appendage_mass(k, k) / expected(k), 1.0, 1e-9) << "direction " << k;
  }
  EXPECT_LT(held.largest_constraint_rate, 1e-12);

  // The pair's mass, centre of mass and inertia about it.
  const Eigen::MatrixXd Psi = rigid_motion_basis(model, lin.point, Eigen::Vector3d::Zero());
  const MassProperties mp = mass_properties(Psi.transpose() * lin.tangent.M * Psi, Eigen::Vector3d::Zero());
  const double m = mb + ma;
  const Eigen::Vector3d c = ma * d / m;
  EXPECT_NEAR(mp.mass / m, 1.0, 1e-12);
  EXPECT_NEAR((mp.com_W - c).norm(), 0.0, 1e-12);
  const auto shift = [](double mass, const Eigen::Vector3d& r) {
    return Eigen::Matrix3d(mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose()));
  };
  const Eigen::Matrix3d I_c = Eigen::Matrix3d(Jb.asDiagonal()) + shift(mb, -c) +
                              Eigen::Matrix3d(Ja.asDiagonal()) + shift(ma, d - c);
  EXPECT_NEAR((mp.inertia_com_W - I_c).cwiseAbs().maxCoeff(), 0.0, 1e-10 * I_c.norm());
}

// The seed rod (1 m, 10 beams, 6 normal modes clamped at node 0) bracketed to a floating hub
// at the hub's centre of mass, hub held: the held modes are the rod's, and their coupling
// matrices and effective masses are Euler–Bernoulli's for a cantilever of mass m, length L
// (mode shape φ = cosh βx − cos βx − σ(sinh βx − sin βx), ∫φ² = L, ∫φ = 2σ/β, ∫xφ = 2/β²):
// translational effective mass 4σ²/(βL)² m (0.6131 m, 0.1883 m for the first two bendings)
// and rotational about the root 4 m L²/(βL)⁴, each along its bending plane only. Tolerance
// 1e-3 relative: the FE mass carries the sections' rotary inertia, which Euler–Bernoulli
// omits, ~(h²/12)(β)² relative: 3e-5 × 22 = 7e-4 for the second bending of the 20 mm side;
// measured 4e-5 to 5.4e-4 (ten cubic elements add far less).
TEST(Linearization, CantileverOnAFreeHubHasEulerBernoulliEffectiveMasses) {
  const double L = 1.0;
  const fe::FeModel fe_model = testing::straight_rod(L, 10, {0});
  const modal::ModeSet modes = testing::normal_modes(fe_model, 6);
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("hub", 100.0, Eigen::Vector3d(10, 12, 14), Eigen::Vector3d::Zero()));
  builder.add_flexible_body(testing::flexible_spec("rod", fe_model, modes, {}));
  builder.add_marker_at("root.hub", "hub", Eigen::Vector3d::Zero());
  builder.add_node_marker("root.rod", "rod", 0);
  builder.add_joint("root", JointType::kBracket, "root.hub", "root.rod");
  const Model model = builder.build();
  const Linearized lin = linearize(model, false);
  EXPECT_EQ(lin.modes.rigid_modes, 6);
  const CantileveredModes held = cantilevered_modes(model, lin.point, lin.tangent, model.find_body("hub"));
  ASSERT_EQ(held.modes.frequencies_hz.size(), 6);
  const double m = model.bodies[static_cast<std::size_t>(model.find_body("rod"))].mass;
  // Modes 1 and 3 bend in the soft plane, 2 and 4 in the stiff one (the section is 1:2).
  const double beta_L[] = {1.8751040687, 1.8751040687, 4.6940911330, 4.6940911330};
  for (int i = 0; i < 4; ++i) {
    const double bl = beta_L[i];
    const double sigma = (std::sinh(bl) - std::sin(bl)) / (std::cosh(bl) + std::cos(bl));
    const Eigen::VectorXd meff = held.effective_mass.row(i).transpose();
    Eigen::Index t = 0, r = 0;
    meff.head<3>().maxCoeff(&t);
    meff.tail<3>().maxCoeff(&r);
    EXPECT_NEAR(meff(t) / (4.0 * sigma * sigma / (bl * bl) * m), 1.0, 1e-3) << "mode " << i + 1;
    EXPECT_NEAR(meff(3 + r) / (4.0 * m * L * L / std::pow(bl, 4)), 1.0, 1e-3) << "mode " << i + 1;
    // Bending along one axis (t, normal to the rod along x) turns about the third one.
    EXPECT_NE(t, 0);
    EXPECT_EQ(t + r, 3) << "mode " << i + 1;
    // The coupling matrices' columns, signed (the shape's sign cancels in the ratio): a turn
    // about z moves the rod along +y by x, one about y along −z by x, so the rotational over
    // the translational participation is ±∫xφ/∫φ = ±L/(σ βL), the mode's lever arm about the root.
    const double lever = (t == 1 ? 1.0 : -1.0) * L / (sigma * bl);
    EXPECT_NEAR(held.participation(i, 3 + r) / held.participation(i, t) / lever, 1.0, 1e-3) << "mode " << i + 1;
    for (int d = 0; d < 6; ++d) {
      if (d == t || d == 3 + r) continue;
      EXPECT_LT(meff(d), 1e-9 * m) << "mode " << i + 1 << " direction " << d;
    }
  }
}

// Completeness for a clamped flexible appendage: the seed rod (1 m, n beams) clamped at node 0
// with all 6n of its clamped normal modes (they span the clamped rod's FE space), bracketed to a
// floating hub, hub held. The held motions are then exactly the rod's free DOFs f (its root node
// r moves with the hub), and Σ_i Lᵢᵀ Lᵢ is the M-orthogonal projection of its rigid motion Ψ
// onto them (Craig & Bampton 1968; the boundary's "residual mass"):
//   Σ_i Lᵢᵀ Lᵢ = (M_f: Ψ)ᵀ M_ff⁻¹ (M_f: Ψ) = Ψᵀ M Ψ − Ψ_rᵀ S Ψ_r,   S = M_rr − M_rf M_ff⁻¹ M_fr,
// the rod's rigid mass about the root less the root node's condensed mass S, which the hub
// carries. Second method: that formula from the FE matrices alone (no modes, no multibody).
// Tolerance 1e-9 relative (of the largest entry): both sides are exact to rounding; measured
// ≤ 1.3e-15. Closed form along the rod (T1, and the twist R1 likewise): the consistent rod
// elements' chain, [2 1; 1 2] m_e/6 each, condenses node by node from the tip (in m_e/6:
// S ← 4 − 1/S from 2, converging as (2 − √3)^2 per element to 2 + √3) to S = 2 − 1/(2 + √3) = √3
// at the root, m_e/(2√3), so Σ meff_T1 = m (1 − 1/(2√3 n)) to 1e-11 at n = 10: it tends to m
// with the mesh, as Euler–Bernoulli's Σ 4σ²/(βL)² = 1 across the rod does.
// Across the rod (T2, T3) the root's share also falls with the mesh, 3.0 % to 1.6 % of m.
TEST(Linearization, EffectiveMassesOfAClampedRodWithAllItsModesSumToItsMassLessTheRoot) {
  double residual_T3[2] = {0.0, 0.0};
  for (const int elements : {10, 20}) {
    SCOPED_TRACE(elements);
    const fe::FeModel fe_model = testing::straight_rod(1.0, elements, {0});
    const int n_free = fe::kDofsPerNode * elements;
    const modal::ModeSet modes = testing::normal_modes(fe_model, n_free);
    ModelBuilder builder;
    builder.add_rigid_body(body_spec("hub", 100.0, Eigen::Vector3d(10, 12, 14), Eigen::Vector3d::Zero()));
    builder.add_flexible_body(testing::flexible_spec("rod", fe_model, modes, {}));
    builder.add_marker_at("root.hub", "hub", Eigen::Vector3d::Zero());
    builder.add_node_marker("root.rod", "rod", 0);
    builder.add_joint("root", JointType::kBracket, "root.hub", "root.rod");
    const Model model = builder.build();
    const Linearized lin = linearize(model, false);
    const CantileveredModes held = cantilevered_modes(model, lin.point, lin.tangent, model.find_body("hub"));
    ASSERT_EQ(held.modes.frequencies_hz.size(), n_free);

    // The FE side: M, Ψ about the root (= the hub's centre of mass), the root's 6 DOFs first.
    const Eigen::MatrixXd M = Eigen::MatrixXd(fe::assemble(fe_model).mass);
    const Eigen::MatrixXd Psi = modal::rigid_body_modes(fe_model);
    const Eigen::MatrixXd M_f_Psi = M.bottomRows(n_free) * Psi;
    const Eigen::MatrixXd expected =
        M_f_Psi.transpose() * M.bottomRightCorner(n_free, n_free).ldlt().solve(M_f_Psi);
    const Eigen::MatrixXd rigid = Psi.transpose() * M * Psi;
    const Eigen::MatrixXd sum = held.participation.transpose() * held.participation;
    EXPECT_LT((sum - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());
    EXPECT_LT((held.appendage_mass - rigid).cwiseAbs().maxCoeff(), 1e-9 * rigid.cwiseAbs().maxCoeff());
    for (int d = 0; d < 6; ++d) EXPECT_NEAR(held.effective_sum(d) / expected(d, d), 1.0, 1e-9) << "direction " << d;
    // Along the rod: the closed form of the rod chain's root share.
    const double along = 1.0 - 1.0 / (2.0 * std::sqrt(3.0) * elements);
    EXPECT_NEAR(held.effective_sum(0) / (along * rigid(0, 0)), 1.0, 1e-9);
    EXPECT_NEAR(held.effective_sum(3) / (along * rigid(3, 3)), 1.0, 1e-9);
    residual_T3[elements == 10 ? 0 : 1] = 1.0 - held.effective_sum(2) / rigid(2, 2);
  }
  EXPECT_GT(residual_T3[1], 0.0);
  EXPECT_LT(residual_T3[1], 0.6 * residual_T3[0]);
}

// Rows that depend on each other at the state are a singular linearization point: named, no
// NaN. Two cases: more rows kept than coordinates (two coaxial hinges on one bar, 10 rows on 6)
// and as many (two ball joints on one bar, 6 rows of rank 5: the turn about the bar's line).
TEST(Linearization, SingularConstraintsAreNamed) {
  for (const JointType type : {JointType::kRevolute, JointType::kSpherical}) {
    ModelBuilder builder;
    builder.add_rigid_body(body_spec("bar", 1.0, Eigen::Vector3d(0.1, 0.1, 0.1), Eigen::Vector3d::Zero()));
    builder.add_marker_at("A.ground", "ground", Eigen::Vector3d::Zero());
    builder.add_marker_at("A.bar", "bar", Eigen::Vector3d::Zero());
    builder.add_joint("A", type, "A.ground", "A.bar");
    builder.add_marker_at("B.ground", "ground", Eigen::Vector3d(0, 0, 1));
    builder.add_marker_at("B.bar", "bar", Eigen::Vector3d(0, 0, 1));
    builder.add_joint("B", type, "B.ground", "B.bar");
    const Model model = builder.build();
    ConstraintPartition all;
    for (int row = 0; row < model.num_equations(); ++row) all.independent.push_back(row);
    TangentMatrices tangent;
    std::string message;
    EXPECT_EQ(tangent_matrices(model, all, initial_state(model), tangent, message),
              LinearizationStatus::kSingularConstraints) << to_string(type);
    EXPECT_NE(message.find("constraints are singular"), std::string::npos) << message;
    EXPECT_NE(message.find("equation(s) "), std::string::npos) << message;
    EXPECT_EQ(message.find("nan"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace limber::multibody
