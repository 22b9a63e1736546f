// The spin-up beam of Kane, Ryan & Banerjee 1987 / Simo & Vu-Quoc 1986 through the co-rotational
// beam's dynamics (dynamic_solver.h): bounded where an unstiffened linear modal model diverges,
// and its peak tip deflection against the project's two independent computations.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>

#include "fe/assembly.h"
#include "nonlinear_beam/beam_inertia.h"
#include "nonlinear_beam/beam_structure.h"
#include "nonlinear_beam/dynamic_solver.h"
#include "nonlinear_beam/rotation.h"
#include "beam_test_support.h"

namespace limber::nonlinear_beam {
namespace {

using test_models::BeamSpec;
using test_models::Built;
using test_models::seconds_since;
using test_models::straight_beam;

// The spin-up beam (Kane, Ryan & Banerjee, J. Guidance 10 (1987) 139-151; Simo & Vu-Quoc,
// J. Appl. Mech. 53 (1986) 849-863): L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m², ρA = 1.2 kg/m,
// clamped to a hub turned by θ(t) = ωs/Ts (t²/2 + (Ts/2π)² (cos(2πt/Ts) − 1)) for t < Ts,
// ωs t − ωs Ts/2 after, ωs = 4 rad/s, Ts = 15 s; the tip's transverse deflection in the
// hub's rotating frame over 20 s.
Eigen::Vector3d spin_up_angle(double t, double omega_s, double t_s) {
  if (t >= t_s) return Eigen::Vector3d(omega_s * t - 0.5 * omega_s * t_s, omega_s, 0.0);
  const double c = t_s / (2.0 * std::numbers::pi);
  const double phase = 2.0 * std::numbers::pi * t / t_s;
  return (omega_s / t_s) *
         Eigen::Vector3d(0.5 * t * t + c * c * (std::cos(phase) - 1.0), t - c * std::sin(phase),
                         1.0 - std::cos(phase));
}

struct SpinUpRun {
  double peak = 0.0;         // most negative tip deflection [m]
  double peak_time = 0.0;    // [s]
  double max_abs = 0.0;      // max |deflection| over the run [m]
  double after_spin_up = 0.0;  // max |deflection| for t > Ts + 1 s [m]
  double wall = 0.0;
  long steps = 0, newton = 0;
};

SpinUpRun spin_up(double omega_s, int elements, double h, double duration) {
  constexpr double kTs = 15.0;
  BeamSpec spec;
  spec.length = 10.0;
  spec.elements = elements;
  spec.youngs_modulus = 7e10;  // with A = 4e-4 m², I = 2e-7 m⁴, ρ = 3000 kg/m³: EA, EI, ρA
  spec.area = 4e-4;            // of the benchmark (the section's own values are free)
  spec.inertia_y = spec.inertia_z = 2e-7;
  spec.torsion_constant = 4e-7;
  spec.density = 3000.0;
  spec.clamped = false;  // the hub node is prescribed instead
  const Built b = straight_beam(spec);
  const BeamStructure structure = build_beam_structure(b.model);
  const NodalInertia inertia = lumped_inertia(b.model);
  const int hub = b.nodes.front();
  const int tip = b.nodes.back();

  DynamicOptions options;
  options.step = h;
  options.rho_inf = 0.9;
  options.prescribed.push_back(hub_rotation(structure, hub, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                            [omega_s](double t) { return spin_up_angle(t, omega_s, kTs); }));
  BeamGeneralizedAlpha integrator(structure, inertia, options);
  EXPECT_EQ(integrator.init(0.0, reference_state(structure), zero_velocity(structure.node_count())).status,
            DynamicStatus::kOk);
  SpinUpRun out;
  const auto start = std::chrono::steady_clock::now();
  while (integrator.time() < duration - 1e-9) {
    const DynamicReport r = integrator.step();
    EXPECT_EQ(r.status, DynamicStatus::kOk) << r.message;
    if (r.status != DynamicStatus::kOk) break;
    // Tip in the hub frame: y component is the transverse deflection.
    const double t = integrator.time();
    const Eigen::Matrix3d hub_rotation_now = integrator.state().rotations[hub].toRotationMatrix();
    const double y = (hub_rotation_now.transpose() * integrator.state().positions[tip]).y();
    if (y < out.peak) {
      out.peak = y;
      out.peak_time = t;
    }
    out.max_abs = std::max(out.max_abs, std::abs(y));
    if (t > kTs + 1.0) out.after_spin_up = std::max(out.after_spin_up, std::abs(y));
  }
  out.wall = seconds_since(start);
  out.steps = integrator.statistics().steps;
  out.newton = integrator.statistics().newton_iterations;
  std::cout << "spin-up to " << omega_s << " rad/s, " << elements << " elements, h = " << h << " s: tip peak " << out.peak
            << " m at " << out.peak_time << " s, max |y| " << out.max_abs
            << " m, after the spin-up within " << out.after_spin_up << " m; " << out.steps
            << " steps, " << out.newton << " Newton its., " << out.wall << " s\n";
  return out;
}

// The conventional linear model of the same beam in the hub frame, without geometric
// stiffening (Kane, Ryan & Banerjee's "linear theory"): in-plane bending only, with the
// centrifugal softening of the transverse translations and the hub's angular acceleration as
// the load, on the linear FE stiffness and the same lumped mass (all modes, so no truncation):
//   M q'' + (K − θ'² M_y) q = −θ'' (m_i x_i) on the uy DOFs,
// integrated by the trapezoidal rule at the same step. Returns max |tip uy| over the run [m].
double unstiffened_linear_spin_up(double omega_s, int elements, double h, double duration) {
  constexpr double kTs = 15.0;
  BeamSpec spec;
  spec.length = 10.0;
  spec.elements = elements;
  spec.youngs_modulus = 7e10;
  spec.area = 4e-4;
  spec.inertia_y = spec.inertia_z = 2e-7;
  spec.torsion_constant = 4e-7;
  spec.density = 3000.0;
  const Built b = straight_beam(spec);
  const NodalInertia inertia = lumped_inertia(b.model);
  const Eigen::MatrixXd k_full = Eigen::MatrixXd(fe::assemble(b.model).stiffness);
  // In-plane DOFs (uy, rz) of the free nodes.
  std::vector<int> dofs;
  for (std::size_t i = 1; i < b.nodes.size(); ++i) {
    dofs.push_back(6 * b.nodes[i] + 1);
    dofs.push_back(6 * b.nodes[i] + 5);
  }
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd k(n, n);
  Eigen::VectorXd m(n), m_y(n), arm(n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) k(r, c) = k_full(dofs[r], dofs[c]);
    const int node = dofs[r] / 6;
    const bool translation = dofs[r] % 6 == 1;
    m(r) = translation ? inertia.mass[node] : inertia.inertia[node](2, 2);
    m_y(r) = translation ? inertia.mass[node] : 0.0;
    arm(r) = translation ? b.model.node_positions[node].x() : 0.0;
  }
  // Trapezoidal rule on q'' = M⁻¹(f − K_eff q).
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n), v = q, a = q;
  double max_tip = 0.0;
  for (double t = 0.0; t < duration - 1e-9; t += h) {
    const Eigen::Vector3d th = spin_up_angle(t + h, omega_s, kTs);
    const Eigen::MatrixXd k_eff = k - Eigen::MatrixXd((th(1) * th(1) * m_y).asDiagonal());
    const Eigen::VectorXd f = -th(2) * m_y.cwiseProduct(arm);
    // (4/h² M + K_eff) q1 = f + M (4/h² q + 4/h v + a)
    const Eigen::MatrixXd lhs = Eigen::MatrixXd((4.0 / (h * h)) * m.asDiagonal()) + k_eff;
    const Eigen::VectorXd rhs = f + m.cwiseProduct((4.0 / (h * h)) * q + (4.0 / h) * v + a);
    const Eigen::VectorXd q1 = lhs.partialPivLu().solve(rhs);
    const Eigen::VectorXd a1 = (4.0 / (h * h)) * (q1 - q) - (4.0 / h) * v - a;
    v += 0.5 * h * (a + a1);
    a = a1;
    q = q1;
    max_tip = std::max(max_tip, std::abs(q(n - 2)));
    if (!std::isfinite(max_tip) || max_tip > 1e6) break;  // diverged: enough
  }
  return max_tip;
}

TEST(CorotationalDynamics, SpinUpBeamStaysBoundedAndPeaksAtTheReferenceDeflection) {
  const SpinUpRun run = spin_up(4.0, 20, 5e-3, 20.0);
  // Reference: −0.4004 m at t = 6.95 s from the 40-element planar co-rotational beam with
  // lumped masses, HHT-α at 1 ms (tests/multibody/corotational_spin_beam.h), and −0.4003 m at
  // 6.95 s from the first-order stiffened theory (6 modes, and the 20-element FE beam in the
  // rotating frame): docs/geometric-stiffening.md. The published curves (Kane et al. 1987,
  // Simo & Vu-Quoc 1986, figure for ωs = 4 rad/s) are drawn at a scale where the peak reads
  // about −0.4 m to ±0.01 m (±2.5 %), but no tabulated or digitised value could be found in
  // this project's sources, so the assertion is against the two independent computations:
  // 0.5 % of the peak covers the first-order theory's neglected (δ/L)² = 0.16 % and the
  // mesh and time-step differences (20 vs 40 elements, 5 ms vs 1 ms, both second order).
  // Measured: −0.40117 m (20 elements, 5 ms), −0.40038 m (40 elements, 2.5 ms; the
  // disabled study below): the 20-element mesh error is +0.19 %.
  EXPECT_NEAR(run.peak, -0.4004, 0.005 * 0.4004);
  // Time of the peak within 0.1 s (the reference's sampling, and 1/16 of the first period).
  EXPECT_NEAR(run.peak_time, 6.95, 0.1);
  // Bounded: the deflection never exceeds the peak (a linear modal model without geometric
  // stiffening diverges on this manoeuvre, docs/geometric-stiffening.md), and after the
  // spin-up the tip vibrates about 0 within 1 cm (reference: 4.1 mm).
  EXPECT_LE(run.max_abs, 0.41);
  EXPECT_LT(run.after_spin_up, 0.01);
  // The contrast: the linear model without stiffening diverges once θ' passes the first
  // bending frequency (3.8 rad/s, at t ≈ 13 s): its tip leaves any beam's range (> 10 m = L).
  const double linear = unstiffened_linear_spin_up(4.0, 20, 5e-3, 20.0);
  std::cout << "unstiffened linear model: max |tip| " << linear << " m\n";
  EXPECT_GT(linear, 10.0);
}

// Ωs = 10 rad/s, past the first bending frequency (3.8 rad/s): the manoeuvre on which a linear
// modal model without geometric stiffening diverges (1.1e14 m by 12 s,
// docs/geometric-stiffening.md). Reference −0.8586 m at 6.45 s (the 40-element planar
// co-rotational beam; the first-order stiffened theory −0.8593 m). 0.5 % as above: the
// 20-element mesh error is measured at +0.24 % (40 elements at 2.5 ms: −0.85866 m).
TEST(CorotationalDynamics, SpinUpBeamAtTenRadiansPerSecondStaysBounded) {
  const SpinUpRun run = spin_up(10.0, 20, 5e-3, 20.0);
  EXPECT_NEAR(run.peak, -0.8586, 0.005 * 0.8586);
  EXPECT_NEAR(run.peak_time, 6.45, 0.1);
  EXPECT_LE(run.max_abs, 0.87);
  EXPECT_LT(run.after_spin_up, 0.01);  // reference: 6.3 mm
}

// The mesh and step study of the spin-up figures in docs/nonlinear-beams.md (about 40 s; run
// with --gtest_also_run_disabled_tests).
TEST(CorotationalDynamics, DISABLED_SpinUpMeshAndStepStudy) {
  for (double omega_s : {4.0, 6.0, 10.0}) {
    spin_up(omega_s, 20, 5e-3, 20.0);
    spin_up(omega_s, 40, 5e-3, 20.0);
    spin_up(omega_s, 20, 2.5e-3, 20.0);
    spin_up(omega_s, 40, 2.5e-3, 20.0);
  }
}

}  // namespace
}  // namespace limber::nonlinear_beam
