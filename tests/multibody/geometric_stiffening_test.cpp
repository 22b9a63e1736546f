// Geometric stiffening of a flexible body through the time integrators: the spin-up beam of
// Kane, Ryan & Banerjee ("Dynamics of a cantilever beam attached to a moving base",
// J. Guidance Control Dyn. 10(2), 1987): a cantilever L = 10 m, A = 4e-4 m², I = 2e-7 m⁴,
// E = 7e10 Pa, ρ = 3000 kg/m³ (EI = 1.4e4 N m², ρA = 1.2 kg/m, first bending frequency
// 3.80 rad/s) on a hub spun up about z by
//   Ω(t) = (Ωs/Ts)(t − (Ts/2π) sin(2πt/Ts)) for t < Ts = 15 s, then Ωs.
// The reduced body (6 clamped normal modes, the hub a driven revolute) is compared with a
// second method: the unreduced FE beam (20 elements, in-plane DOFs) in the rotating frame,
//   M ü + (K + Ω² (K_G1 − M)) u = −α M r,   r = (x, 1) the rigid rotation field,
// with the centrifugal tension N(x) = ρAΩ²(L² − x²)/2 in closed form (element averages),
// integrated by Newmark's average acceleration: Kane et al.'s first-order ("dynamically
// correct") linear theory, independent of the modal load cases, the inertia relief, the
// floating frame and IDA; and a geometrically nonlinear third, the unreduced beam as planar
// co-rotational elements in ground axes (corotational_spin_beam.h), whose stiffening comes out
// of the exact kinematics. Without stiffening the linear modes diverge at Ωs = 10 rad/s,
// where the references stay bounded.
// The node-load cases (full stiffening) on a pinned rod loaded axially through its joints, by
// a point load or by a spring at its end node: the first bending frequency falls as
// f0 √(1 − P/P_cr) (Euler column).
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <gtest/gtest.h>

#include "fe/assembly.h"
#include "fe/beam_geometric_stiffness.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "integrate/simulate.h"
#include "modal/component_modes.h"
#include "modal/geometric_stiffness.h"
#include "multibody/assembly.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/energy_rates.h"
#include "multibody/geometric_stiffening.h"
#include "multibody/model_builder.h"
#include "multibody/multibody_system.h"
#include "multibody/redundancy.h"
#include "kane_spin_up.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using namespace kane_spin_up;

// The unreduced rotating-frame reference (header), tip y at the sample times.
std::vector<double> full_tip(const fe::FeModel& beam, double spin, double t_end, double dt) {
  const fe::StructuralMatrices km = fe::assemble(beam);
  // In-plane DOFs uy, rz of the free nodes.
  std::vector<int> dofs;
  for (int p = 1; p <= kElements; ++p) {
    dofs.push_back(fe::FeModel::dof_index(p, fe::Dof::kUy));
    dofs.push_back(fe::FeModel::dof_index(p, fe::Dof::kRz));
  }
  const Eigen::Index n = static_cast<Eigen::Index>(dofs.size());
  const Eigen::MatrixXd M_all(km.mass), K_all(km.stiffness);
  Eigen::MatrixXd K_G_all = Eigen::MatrixXd::Zero(beam.dof_count(), beam.dof_count());
  for (const fe::BeamElement& e : beam.beams) {
    const Eigen::Vector3d &p0 = beam.node_positions[e.nodes[0]], &p1 = beam.node_positions[e.nodes[1]];
    // Element average of N(x)/Ω² = ρA (L² − x²)/2.
    const double x0 = p0.x(), x1 = p1.x();
    const double n_avg = kDensity * kArea * 0.5 * (kLength * kLength - (x0 * x0 + x0 * x1 + x1 * x1) / 3.0);
    const fe::Matrix12d k = fe::beam_geometric_stiffness(p0, p1, e.orientation, beam.beam_properties[0], n_avg);
    for (int a = 0; a < 12; ++a) {
      for (int b = 0; b < 12; ++b) K_G_all(6 * e.nodes[a / 6] + a % 6, 6 * e.nodes[b / 6] + b % 6) += k(a, b);
    }
  }
  Eigen::MatrixXd M(n, n), K(n, n), K_G(n, n);
  Eigen::VectorXd r(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      M(i, j) = M_all(dofs[i], dofs[j]);
      K(i, j) = K_all(dofs[i], dofs[j]);
      K_G(i, j) = K_G_all(dofs[i], dofs[j]);
    }
    r(i) = i % 2 == 0 ? beam.node_positions[i / 2 + 1].x() : 1.0;
  }
  const Eigen::VectorXd M_r = M * r;
  const auto stiffness = [&](double t) {
    const double w = spin_rate(spin, t)(0);
    return Eigen::MatrixXd(K + w * w * (K_G - M));
  };
  const auto force = [&](double t) { return Eigen::VectorXd(-spin_rate(spin, t)(1) * M_r); };
  // Newmark, average acceleration, from rest.
  constexpr double beta = 0.25, gamma = 0.5;
  const double h = 1e-3;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = u, a = M.ldlt().solve(force(0.0));
  std::vector<double> tip{0.0};
  const int steps = static_cast<int>(std::lround(t_end / h)), per_sample = static_cast<int>(std::lround(dt / h));
  for (int k = 1; k <= steps; ++k) {
    const double t = k * h;
    const Eigen::VectorXd u_star = u + h * v + (0.5 - beta) * h * h * a, v_star = v + (1.0 - gamma) * h * a;
    const Eigen::MatrixXd effective = stiffness(t) + M / (beta * h * h);
    u = effective.ldlt().solve(force(t) + M * u_star / (beta * h * h));
    a = (u - u_star) / (beta * h * h);
    v = v_star + gamma * h * a;
    if (k % per_sample == 0) tip.push_back(u(n - 2));
  }
  return tip;
}

void check_against_reference(double spin, double t_end) {
  const fe::FeModel beam = kane_beam();
  const double dt = 0.01;
  const std::vector<double> reduced = reduced_tip(beam, spin, GeometricStiffening::kInertia, t_end, dt);
  const std::vector<double> full = full_tip(beam, spin, t_end, dt);
  ASSERT_EQ(reduced.size(), full.size());
  double error = 0.0, peak = max_abs(full), late = 0.0;
  size_t at_peak = 0;
  for (size_t k = 0; k < full.size(); ++k) {
    error = std::max(error, std::abs(reduced[k] - full[k]));
    if (std::abs(full[k]) == peak) at_peak = k;
    if (k * dt >= kSpinUpTime) late = std::max(late, std::abs(reduced[k]));
  }
  std::printf("  Ωs = %g rad/s: tip peak %.4f m at %.2f s (reference %.4f m), max |difference| %.2e m, "
              "after spin-up |tip| ≤ %.4f m\n",
              spin, reduced[at_peak], at_peak * dt, full[at_peak], error, late);
  // Error budget: 6 modes against 20 elements' 40 in-plane DOFs (the α load is smooth and
  // slow, quasi-static in the higher modes: < 1e-3 of the peak), the floating frame's terms of
  // second order in the deflection (tip/L ≲ 5 %: ≲ 3e-3 of the peak) and the integrators'
  // errors (IDA rtol 1e-8, Newmark (ωh)²/12 ~ 1e-6): 1 % of the peak.
  EXPECT_LT(error, 1e-2 * peak);
  // Bounded: the spin-up's tangential inertia bends the beam back by a fraction of a metre,
  // and after the spin-up it vibrates about zero (no steady in-plane load on a radial beam).
  EXPECT_LT(peak, 0.1 * kLength);
  // The geometrically nonlinear, unreduced beam.
  const std::vector<double> exact = corotational_tip(spin, t_end, dt);
  ASSERT_EQ(exact.size(), reduced.size());
  double exact_error = 0.0, exact_peak = max_abs(exact);
  size_t at_exact_peak = 0;
  for (size_t k = 0; k < exact.size(); ++k) {
    exact_error = std::max(exact_error, std::abs(reduced[k] - exact[k]));
    if (std::abs(exact[k]) == exact_peak) at_exact_peak = k;
  }
  std::printf("  co-rotational beam: tip peak %.4f m at %.2f s, max |reduced − co-rotational| %.2e m (%.2f %% of "
              "its peak)\n", exact[at_exact_peak], at_exact_peak * dt, exact_error, 100.0 * exact_error / exact_peak);
  // Error budget: the terms of second order in the deflection that the first-order model
  // leaves out, (δ/L)² ≤ 0.75 % at δ = 0.86 m; the 6 modes (< 1e-3, above); the references'
  // own discretisation (40 lumped-mass elements against 20 consistent ones, HHT at 1 ms):
  // ~1e-3. 1 % of the peak.
  EXPECT_LT(exact_error, 1e-2 * exact_peak);
}

TEST(GeometricStiffening, AccelerationEstimateMatchesTheIndependentRowsSolve) {
  // The rigid slider-crank, redundant (R2.rot_x) and not, at a generic angle: the estimate's
  // v̇ and constraint forces Gᵀλ (unique even where λ is not) against solve_accelerations on the
  // independent rows. Both are direct solves of the same equations: agreement to round-off
  // of the scaled system (κ ~ 1e4 here: 1e-9 relative).
  for (bool non_redundant : {false, true}) {
    testing::SliderCrankParameters p;
    p.theta0 = 0.7;
    p.non_redundant = non_redundant;
    const Model model = testing::slider_crank(p);
    Workspace ws(model);
    State state = initial_state(model);
    ASSERT_EQ(assemble_positions(model, state, ws, {1e-12, 50, {}}).status, AssemblyStatus::kOk);
    assemble_velocities(model, state, ws);
    const ConstraintPartition partition = analyse_redundancy(model, state, ws);
    Eigen::VectorXd v_dot, lambda;
    solve_accelerations(model, state, partition, ws, v_dot, lambda);
    Eigen::VectorXd constraint_force = Eigen::VectorXd::Zero(model.nv);
    for (size_t k = 0; k < partition.independent.size(); ++k) {
      constraint_force += ws.G.row(partition.independent[k]).transpose() * lambda(static_cast<Eigen::Index>(k));
    }
    mass_matrix(model, state, ws);
    generalized_forces(model, state, ws);
    evaluate_constraints(model, state, Stage::kVelocity, ws);
    const AccelerationEstimate estimate = estimate_accelerations(ws.M, ws.G, ws.Q, ws.gamma);
    // Condition of the whitened rows B = G L⁻ᵀ over their nonzero singular values.
    const Eigen::MatrixXd B = ws.M.llt().matrixL().solve(ws.G.transpose()).transpose();
    const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(B).singularValues();
    double smallest = sigma(0);
    for (Eigen::Index i = 0; i < sigma.size(); ++i) {
      if (sigma(i) > 1e-8 * sigma(0)) smallest = sigma(i);
    }
    const double kappa = sigma(0) / smallest;
    const double v_error = (estimate.v_dot - v_dot).norm() / v_dot.norm();
    const double f_error = (ws.G.transpose() * estimate.lambda - constraint_force).norm() / constraint_force.norm();
    std::printf("  %s: κ(B) = %.3g, relative errors v̇ %.2e, Gᵀλ %.2e\n", non_redundant ? "non-redundant" : "redundant",
                kappa, v_error, f_error);
    // The estimate solves the normal equations B Bᵀ λ = …: relative error ~ ε κ(B)².
    const double bound = 10.0 * std::numeric_limits<double>::epsilon() * kappa * kappa;
    EXPECT_LT(v_error, bound);
    EXPECT_LT(f_error, bound);
  }
}

TEST(GeometricStiffening, KaneSpinUpBeamAt4RadPerSecondMatchesTheFirstOrderTheory) { check_against_reference(4.0, 20.0); }

TEST(GeometricStiffening, KaneSpinUpBeamAt10RadPerSecondStaysBoundedWithStiffeningAndDivergesWithout) {
  check_against_reference(10.0, 20.0);
  // Linear modes: past t ≈ 6.6 s, Ω > ω1 = 3.80 rad/s and the in-plane mode's stiffness
  // ω1² − Ω² turns negative: exponential growth (rate up to √(100 − 14.4) = 9.3 /s). The run
  // is stopped at 12 s, or fails earlier when the integrator cannot follow the growth.
  const std::vector<double> linear = reduced_tip(kane_beam(), 10.0, GeometricStiffening::kOff, 12.0, 0.01);
  const double largest = max_abs(linear);
  std::printf("  Ωs = 10 rad/s without stiffening: |tip| reached %.3g m by %.2f s\n", largest, (linear.size() - 1) * 0.01);
  EXPECT_GT(largest, kLength);  // a linear deflection larger than the beam: diverged
}

// How the axial load P (compression > 0) reaches the rod of rod_frequency.
enum class RodLoad {
  kThroughJoints,   // a point load on the slider: the rod gets it from the joints' multipliers
  kPointLoadAtNode,  // a point load on the rod's end node (the slider carries no axial load)
  kSpringAtNode,     // a preloaded spring from a ground anchor to the rod's end node
};

// The seed's rod (1 m, 0.01 x 0.02 m steel, 20 elements, no rotary inertia) with its
// pinned-pinned modes (node 0: ux uy uz rx; node 20: uy uz), hinged to the ground at node 0
// and at node 20 to a 1 kg slider on a translational joint along x, loaded along −x by P as
// `path` says. In-plane bending (y, weak axis Iz): P_cr = π² E Iz / L² = 3.40 kN. The rod
// starts bent in its first mode (η1 = 1e-4). Also returns ω0, the unloaded first frequency.
struct RodModel {
  Model model;
  double w0 = 0.0;  // [rad/s]
};
RodModel rod_model(RodLoad path, GeometricStiffening stiffening, double ratio) {
  fe::FeModelBuilder fe_builder;
  fe::BeamProperty property;
  property.name = "rod";
  property.material = {"steel", 206.8e9, 0.3, 7820.0};
  property.section.area = 2e-4;
  property.section.inertia_z = 0.02 * 1e-6 / 12.0;
  property.section.inertia_y = 0.01 * 8e-6 / 12.0;
  property.section.torsion_constant = 4.6e-9;
  property.rotary_inertia = false;
  fe::StraightBeamMesh mesh;
  mesh.elements = kElements;
  mesh.orientation = Eigen::Vector3d::UnitY();
  mesh.property = fe_builder.add_beam_property(property);
  const std::vector<int> nodes = fe::add_straight_beam(fe_builder, mesh);
  using fe::Dof;
  for (Dof d : {Dof::kUx, Dof::kUy, Dof::kUz, Dof::kRx}) fe_builder.fix(nodes.front(), d);
  for (Dof d : {Dof::kUy, Dof::kUz}) fe_builder.fix(nodes.back(), d);
  const fe::FeModel rod = std::move(fe_builder).build();
  const fe::StructuralMatrices km = fe::assemble(rod);
  modal::ModeRequest request;
  request.normal_count = 4;
  const modal::ModalResult modes = modal::compute_component_modes(rod, km, request);
  LIMBER_DEMAND(modes.status == modal::ModalStatus::kOk);
  // Mode 0 is the first in-plane (y) bending mode: the weak axis has the lowest frequency.
  LIMBER_DEMAND(std::abs(modes.mode_set.shapes(6 * (kElements / 2) + 1, 0)) > 1e-3);
  const double w0 = std::sqrt(modes.mode_set.modal_stiffness(0));
  const double load = ratio * kPi * kPi * 206.8e9 * property.section.inertia_z;
  FlexibleBodySpec spec;
  spec.name = "rod";
  spec.modes = modes.mode_set;
  spec.node_positions_B = rod.node_positions;
  spec.damping = ModalDamping::ratio(0.0);
  spec.stiffening = stiffening;
  spec.geometric = modal::compute_modal_geometric_stiffness(rod, km, modes.mode_set.shapes, {0, kElements}).stiffness;
  spec.initial_modal_coordinates = Eigen::VectorXd::Unit(4, 0) * 1e-4;
  ModelBuilder builder;
  builder.add_flexible_body(spec);
  RigidBodySpec slider;
  slider.name = "slider";
  slider.mass = 1.0;
  slider.inertia_com_B = 1e-3 * Eigen::Matrix3d::Identity();
  slider.initial_pose.position = Eigen::Vector3d(1.0, 0, 0);
  builder.add_rigid_body(slider);
  Eigen::Matrix3d along_x;
  along_x << 0, 0, 1, 1, 0, 0, 0, 1, 0;  // marker z along ground x
  builder.add_marker("pin.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_node_marker("pin.rod", "rod", 0);
  builder.add_joint("pin", JointType::kRevolute, "pin.ground", "pin.rod");
  builder.add_node_marker("end.rod", "rod", kElements);
  builder.add_marker("end.slider", "slider", Eigen::Vector3d::Zero());
  builder.add_joint("end", JointType::kRevolute, "end.rod", "end.slider");
  builder.add_marker("guide.ground", "ground", Eigen::Vector3d(1.0, 0, 0), along_x);
  builder.add_marker("guide.slider", "slider", Eigen::Vector3d::Zero(), along_x);
  builder.add_joint("guide", JointType::kTranslational, "guide.ground", "guide.slider");
  switch (path) {
    case RodLoad::kThroughJoints:
      builder.add_point_load({"push", "end.slider", Eigen::Vector3d(-load, 0, 0)});
      break;
    case RodLoad::kPointLoadAtNode:
      builder.add_point_load({"push", "end.rod", Eigen::Vector3d(-load, 0, 0)});
      break;
    case RodLoad::kSpringAtNode: {
      // Anchor 1 m beyond the end; the rod has no axial mode, so the spring keeps its length
      // and force f = −k (l − l0) = P (along −x on the rod).
      constexpr double k = 1e4, l = 1.0;
      builder.add_marker("anchor", "ground", Eigen::Vector3d(2.0, 0, 0));
      builder.add_tsda({"spring", "anchor", "end.rod", k, 0.0, l + load / k, TimeFunction::constant(0.0)});
      break;
    }
  }
  return {builder.build(), w0};
}

// The loaded rod's first bending frequency over ω0, from the zero crossings of η1 over 12
// periods.
double rod_frequency(RodLoad path, GeometricStiffening stiffening, double ratio) {
  const RodModel rod = rod_model(path, stiffening, ratio);
  const Model& model = rod.model;
  const double w0 = rod.w0;
  Workspace ws(model);
  State start = initial_state(model);
  LIMBER_DEMAND(assemble_positions(model, start, ws, {1e-12, 50, {}}).status == AssemblyStatus::kOk);
  assemble_velocities(model, start, ws);
  MultibodySystem system(model, analyse_redundancy(model, start, ws));
  const double period = 2 * kPi / w0;
  std::vector<double> crossings;
  double previous = 0.0, previous_t = 0.0;
  const auto result = integrate::simulate(
      system, integrate::IntegratorOptions::ida(1e-10, 1e-14), {0.0, start.q, start.v},
      integrate::uniform_sample_times(0.0, 12 * period, period / 200), [&](const integrate::Sample& s) {
        const double eta = s.q(7);
        if (s.t > 0.0 && previous < 0.0 && eta >= 0.0) {
          crossings.push_back(previous_t + (s.t - previous_t) * previous / (previous - eta));
        }
        previous = eta, previous_t = s.t;
      });
  EXPECT_TRUE(result.status.ok()) << result.status.message;
  LIMBER_DEMAND(crossings.size() >= 3);
  return 2 * kPi * (crossings.size() - 1) / (crossings.back() - crossings.front()) / w0;
}

// Full stiffening against the Euler column f0 √(1 − P/P_cr) at P = ±P_cr/2, and linear modes.
void check_euler_column(RodLoad path, const char* label) {
  for (double ratio : {0.5, -0.5}) {
    const double measured = rod_frequency(path, GeometricStiffening::kFull, ratio);
    std::printf("  %s, P = %+.2f P_cr: ω = %.6f ω0 (Euler column %.6f), linear modes %.6f ω0\n", label, ratio, measured,
                std::sqrt(1.0 - ratio), rod_frequency(path, GeometricStiffening::kOff, ratio));
    // The modal test (modal/) gives P_cr to 1e-6; here the loads come from the multipliers of
    // the last accepted step and the force elements, whose dynamic part (the bending's
    // transverse reactions) has no axial component to first order; crossings at 200 samples
    // per period, IDA at rtol 1e-10: 1e-4 relative.
    EXPECT_NEAR(measured, std::sqrt(1.0 - ratio), 1e-4);
  }
}

TEST(GeometricStiffening, RodPushedThroughItsJointsVibratesAsAnEulerColumn) {
  check_euler_column(RodLoad::kThroughJoints, "through the joints");
}

TEST(GeometricStiffening, RodLoadedByAPointLoadAtItsNodeVibratesAsAnEulerColumn) {
  check_euler_column(RodLoad::kPointLoadAtNode, "point load at the node");
}

TEST(GeometricStiffening, RodLoadedByASpringAtItsNodeVibratesAsAnEulerColumn) {
  check_euler_column(RodLoad::kSpringAtNode, "spring at the node");
}

// The largest |E_bal(t) − E_bal(0)| of a run, E_bal = kinetic + gravity + spring + strain +
// dissipated − driver and force work − geometric work (energy_rates through the integrator's
// quadrature, as `limber run` does), without and with the geometric work, and the energy scale
// (largest kinetic + strain energy).
struct BalanceResiduals {
  double with_geometric = 0.0, without_geometric = 0.0, scale = 0.0;
};
BalanceResiduals balance_residuals(const Model& model, double t_end, double dt) {
  Workspace ws(model), ws_power(model);
  State start = initial_state(model);
  LIMBER_DEMAND(assemble_positions(model, start, ws, {1e-12, 50, {}}).status == AssemblyStatus::kOk);
  assemble_velocities(model, start, ws);
  const ConstraintPartition partition = analyse_redundancy(model, start, ws);
  MultibodySystem system(model, partition);
  integrate::IntegratorOptions options = integrate::IntegratorOptions::ida(1e-10, 1e-14);
  options.quadrature.size = 3;
  options.quadrature.integrand = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                     const Eigen::VectorXd& v_dot, const Eigen::VectorXd& lambda, Eigen::VectorXd& f) {
    // The power of the geometric forces the dynamics apply: the system's lagged loads.
    const EnergyRates rates =
        energy_rates(model, partition, State{t, q, v, {}, system.stiffening_loads()}, v_dot, lambda, ws_power);
    f << rates.dissipation, rates.driver + rates.forces, rates.geometric;
  };
  BalanceResiduals out;
  double with0 = 0.0, without0 = 0.0;
  bool first = true;
  const auto result = integrate::simulate(
      system, options, {0.0, start.q, start.v}, integrate::uniform_sample_times(0.0, t_end, dt),
      [&](const integrate::Sample& s) {
        const EnergyTerms e = energies(model, State{s.t, s.q, s.v}, ws);
        const double without = e.kinetic + e.gravity + e.spring + e.strain + s.integrals(0) - s.integrals(1);
        const double with = without - s.integrals(2);
        if (first) with0 = with, without0 = without, first = false;
        out.with_geometric = std::max(out.with_geometric, std::abs(with - with0));
        out.without_geometric = std::max(out.without_geometric, std::abs(without - without0));
        out.scale = std::max(out.scale, e.kinetic + e.strain);
      });
  EXPECT_TRUE(result.status.ok()) << result.status.message;
  return out;
}

TEST(GeometricStiffening, EnergyBalanceClosesWithTheGeometricWork) {
  // Runs with stiffening on whose balance closes: (1) the rod of rod_model compressed to
  // P_cr/2 by a constant point load at its node (full stiffening: node-load cases), 12
  // periods; (2) the Kane beam spun up to 4 rad/s by its driver (inertia stiffening; the
  // driver's work enters the balance), 20 s.
  {
    const RodModel rod = rod_model(RodLoad::kPointLoadAtNode, GeometricStiffening::kFull, 0.5);
    const double period = 2 * kPi / rod.w0;
    const BalanceResiduals r = balance_residuals(rod.model, 12 * period, period / 50);
    std::printf("  rod at P_cr/2: balance residual %.2e J with the geometric work, %.2e J without (scale %.2e J)\n",
                r.with_geometric, r.without_geometric, r.scale);
    const BalanceResiduals linear =
        balance_residuals(rod_model(RodLoad::kPointLoadAtNode, GeometricStiffening::kOff, 0.5).model, 12 * period,
                          period / 50);
    std::printf("  same rod, linear modes: %.2e J (scale %.2e J)\n", linear.with_geometric, linear.scale);
    // The integrator's level is the linear run's residual (1.5e-7 of the scale at rtol 1e-10,
    // the energies being ~1e-4 J against atol 1e-14 on the coordinates): 1e-6 bounds both.
    // Without the geometric work the balance is off by the geometric potential ½ ηᵀ K_geo η,
    // of the order of (P/P_cr) U = U/2.
    EXPECT_LT(linear.with_geometric, 1e-6 * linear.scale);
    EXPECT_LT(r.with_geometric, 1e-6 * r.scale);
    EXPECT_GT(r.without_geometric, 0.1 * r.scale);
  }
  {
    const BalanceResiduals r =
        balance_residuals(kane_model(kane_beam(), 4.0, GeometricStiffening::kInertia).model, 20.0, 0.05);
    std::printf("  Kane beam to 4 rad/s: balance residual %.2e J with the geometric work, %.2e J without "
                "(scale %.2e J)\n", r.with_geometric, r.without_geometric, r.scale);
    // IDA at rtol 1e-10 on a 3.2 kJ run: 1e-8 of the scale is 100 times the tolerance. The
    // centrifugal stiffening's work (8e-4 of the scale) is 1e5 times that level.
    EXPECT_LT(r.with_geometric, 1e-8 * r.scale);
    EXPECT_GT(r.without_geometric, 1e-4 * r.scale);
  }
}

}  // namespace
}  // namespace limber::multibody
