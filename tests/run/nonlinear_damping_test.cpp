// Rayleigh damping of a nonlinear body in a mechanism (`damping: {rayleigh: [α, β]}`,
// multibody/nonlinear_body.h): β as Kelvin–Voigt damping of each element's deformation, α on the
// node velocities relative to the body's rigid motion. Checked against closed forms through the
// run driver: a clamped cantilever's first-mode damping ratio from its logarithmic decrement, a
// tumbling free beam that keeps its momentum, and the energy balance with the dissipated work.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "fe/assembly.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "multibody/nonlinear_body.h"
#include "multibody/rotation.h"
#include "multibody/state.h"
#include "nonlinear_beam/beam_inertia.h"
#include "nonlinear_beam_case.h"
#include "run/run_driver.h"

namespace limber::run {
namespace {

// The beam of nonlinear_beam_case.h with `damping`, then `rest`.
std::string beam_case(const std::string& damping, const std::string& rest) {
  return test::nonlinear_beam_case(damping, "", rest);
}

// The cantilever: clamped to ground at node 1, released under gravity along −y (its weak axis;
// static tip deflection 5.5 mm, in the linear range). ρ∞ = 1: no numerical damping, so the
// decay is the damping's; 2e-4 s is 1/600 of the first period.
std::string cantilever(const std::string& damping, double t_end) {
  return beam_case(damping, "gravity: [0, -9.81, 0]\n"
                            "joints:\n  clamp: {type: bracket, body_i: ground, body_j: beam, position: [0, 0, 0]}\n"
                            "run: {integrator: galpha, step: 2.0e-4, rho_inf: 1.0, t_end: " +
                                std::to_string(t_end) + ", sample_interval: 2.0e-4}\n");
}

struct History {
  std::vector<double> t, tip_y, balance, dissipated;
  std::vector<Eigen::Matrix<double, 6, 1>> momentum;
  RunSummary summary;
};

// Runs a case; records the tip node's ground y, the energy balance K + V_g + U + W_d (constant
// without drivers and forces), the dissipated work and the momentum.
History run_case_text(const std::string& text) {
  const io::Case input = io::read_case_text(text, "damped_beam.yaml");
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const int tip = built.model.find_body("beam.node21");
  EXPECT_GE(tip, 0);
  const int offset = built.model.bodies[static_cast<std::size_t>(tip)].q_offset;
  History out;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    out.t.push_back(sample.t);
    out.tip_y.push_back(sample.q(offset + 1));
    const std::vector<double>& e = record.energies;  // kinetic, gravity, spring, strain, dissipated, ...
    out.balance.push_back(e[0] + e[1] + e[2] + e[3] + e[4]);
    out.dissipated.push_back(e[4]);
    out.momentum.push_back(record.momentum);
  };
  out.summary = run_mechanism(built.model, built.assembly, built.run, hooks);
  EXPECT_TRUE(out.summary.ok) << out.summary.message;
  return out;
}

// Successive maxima and minima (index) of a sampled signal from index `from`.
std::vector<std::size_t> extrema(const std::vector<double>& x, std::size_t from, bool maxima) {
  std::vector<std::size_t> out;
  for (std::size_t i = std::max<std::size_t>(from, 1); i + 1 < x.size(); ++i) {
    const bool is = maxima ? (x[i] > x[i - 1] && x[i] >= x[i + 1]) : (x[i] < x[i - 1] && x[i] <= x[i + 1]);
    if (is) out.push_back(i);
  }
  return out;
}

// The cantilever's first mode from the FE stiffness and the lumped nodal mass the nonlinear body
// carries (root clamped): ω₁, and κ = 1 − |P φ|²_M / |φ|²_M, the share of the mode's M-norm
// outside the beam's six rigid velocities (P the M-orthogonal projection on them) — the share α
// acts on (α's damping ratio is κ α / (2 ω₁); 1 for a free-free mode).
struct FirstMode {
  double omega = 0.0, kappa = 0.0;
};

FirstMode cantilever_first_mode(const fe::FeModel& model) {
  const int n = model.dof_count();
  const Eigen::MatrixXd K = Eigen::MatrixXd(fe::assemble(model).stiffness);
  const nonlinear_beam::NodalInertia inertia = nonlinear_beam::lumped_inertia(model);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd psi = Eigen::MatrixXd::Zero(n, 6);  // rigid velocities about the origin
  for (int k = 0; k < model.node_count(); ++k) {
    M.block(6 * k, 6 * k, 3, 3).diagonal().setConstant(inertia.mass[static_cast<std::size_t>(k)]);
    M.block(6 * k + 3, 6 * k + 3, 3, 3) = inertia.inertia[static_cast<std::size_t>(k)];
    psi.block(6 * k, 0, 3, 3).setIdentity();
    psi.block(6 * k, 3, 3, 3) = -multibody::skew(model.node_positions[static_cast<std::size_t>(k)]);
    psi.block(6 * k + 3, 3, 3, 3).setIdentity();
  }
  // Root (node 0) clamped: the eigenproblem on the other DOFs.
  const int f = n - 6;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K.bottomRightCorner(f, f), M.bottomRightCorner(f, f));
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(n);
  phi.tail(f) = solver.eigenvectors().col(0);
  const Eigen::VectorXd Mphi = M * phi;
  const Eigen::VectorXd rigid_part = psi.transpose() * Mphi;
  const double projected = rigid_part.dot((psi.transpose() * M * psi).ldlt().solve(rigid_part));
  return {std::sqrt(solver.eigenvalues()(0)), 1.0 - projected / phi.dot(Mphi)};
}

// The free beam of beam_case with `damping` (no joints, no gravity), built.
multibody::Model free_beam(const std::string& damping) {
  const io::Case input = io::read_case_text(beam_case(damping, ""), "damped_beam.yaml");
  return io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies)).model;
}

// A deformed configuration of the free beam: every node moved and turned by a few mm and
// hundredths of a radian, deterministically, the whole turned by 0.7 rad.
Eigen::VectorXd deformed_configuration(const multibody::Model& model) {
  Eigen::VectorXd q = multibody::initial_state(model).q;
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  for (std::size_t b = 1; b < model.bodies.size(); ++b) {
    const double s = static_cast<double>(b);
    const int o = model.bodies[b].q_offset;
    const Eigen::Vector3d wobble(1e-3 * std::sin(s), 3e-3 * std::cos(1.3 * s), 2e-3 * std::sin(0.7 * s));
    q.segment<3>(o) = turn * (q.segment<3>(o) + wobble);
    const Eigen::Quaterniond own(Eigen::AngleAxisd(0.02 * std::cos(s), Eigen::Vector3d(std::sin(s), 1.0, 0.5).normalized()));
    const Eigen::Quaterniond p = (turn * own).normalized();
    q.segment<4>(o + 3) << p.w(), p.x(), p.y(), p.z();
  }
  return q;
}

// Q and the dissipated power of the beams at (q, v).
std::pair<Eigen::VectorXd, double> beam_forces(const multibody::Model& model, const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& v) {
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(model.nv);
  double dissipation = 0.0;
  multibody::add_nonlinear_body_forces(model, q, v, Q, &dissipation);
  return {Q, dissipation};
}

TEST(NonlinearDamping, RigidVelocitiesMakeNoDampingForce) {
  const multibody::Model model = free_beam("{rayleigh: [50, 2.0e-4]}");
  const Eigen::VectorXd q = deformed_configuration(model);
  // A rigid velocity of the deformed beam: 0.3 m/s and 20 rad/s about skew axes.
  const Eigen::MatrixXd rigid = multibody::rigid_nonlinear_velocity_basis(model, q);
  ASSERT_EQ(rigid.cols(), 6);
  const Eigen::VectorXd v = rigid * (Eigen::Matrix<double, 6, 1>() << 0.1, -0.2, 0.2, 12.0, -10.0, 11.0).finished();
  const auto [elastic, none] = beam_forces(model, q, Eigen::VectorXd::Zero(model.nv));
  const auto [moving, dissipation] = beam_forces(model, q, v);
  // Round-off: the deformation rates are differences of O(20 rad/s · 1 m) velocities, so
  // 1e-12 of the largest elastic force (the damping of a velocity that deforms: below).
  EXPECT_LT((moving - elastic).norm(), 1e-12 * elastic.norm());
  EXPECT_LT(std::abs(dissipation), 1e-12 * v.squaredNorm());
  // A deforming velocity is damped, with positive power, and the force has no net force or
  // moment (Ψᵀ ΔQ = 0, Ψ the rigid velocities).
  Eigen::VectorXd deforming = v;
  for (int i = 0; i < model.nv; ++i) deforming(i) += 0.05 * std::sin(1.7 * i);
  const auto [damped, power] = beam_forces(model, q, deforming);
  EXPECT_GT(power, 0.0);
  EXPECT_GT((damped - elastic).norm(), 1e-3 * elastic.norm());
  EXPECT_LT((rigid.transpose() * (damped - elastic)).norm(), 1e-10 * (damped - elastic).norm());
  // Power = −vᵀ ΔQ.
  EXPECT_NEAR(power, -deforming.dot(damped - elastic), 1e-10 * power);
}

TEST(NonlinearDamping, DampingMatrixIsTheVelocityDerivativeOfTheForce) {
  // β alone: its matrix is exact in v (the force is linear in v); α's leaves out the rank-6
  // projection, checked against it below.
  for (const std::string damping : {"{rayleigh: [0, 2.0e-4]}", "{rayleigh: [50, 0]}"}) {
    const multibody::Model model = free_beam(damping);
    const Eigen::VectorXd q = deformed_configuration(model);
    Eigen::SparseMatrix<double> C;
    ASSERT_TRUE(multibody::nonlinear_body_damping(model, q, C));
    // −∂Q/∂v by central differences. Q is linear in v, so a unit step is exact but for the
    // round-off of the elastic force it carries (1e-16 of ~1e6 N at this deformation).
    Eigen::MatrixXd difference(model.nv, model.nv);
    const Eigen::VectorXd v0 = Eigen::VectorXd::Zero(model.nv);
    for (int j = 0; j < model.nv; ++j) {
      Eigen::VectorXd plus = v0, minus = v0;
      plus(j) = 1.0;
      minus(j) = -1.0;
      difference.col(j) = -(beam_forces(model, q, plus).first - beam_forces(model, q, minus).first) / 2.0;
    }
    const Eigen::MatrixXd dense = Eigen::MatrixXd(C);
    if (damping.find("[0,") != std::string::npos) {
      EXPECT_LT((dense - difference).norm(), 1e-8 * dense.norm()) << damping;
    } else {
      // α: the difference is α M Ψ (Ψᵀ M Ψ)⁻¹ Ψᵀ M, of rank 6; the matrix is symmetric positive.
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(dense - difference);
      EXPECT_LT(svd.singularValues()(6), 1e-9 * svd.singularValues()(0)) << damping;
    }
    // No damping: no matrix.
    EXPECT_FALSE(multibody::nonlinear_body_damping(free_beam("0"), q, C));
  }
}

TEST(NonlinearDamping, CantileverFirstModeDecaysAtTheRayleighRatio) {
  // α large enough that its share, κ α / (2 ω₁) with κ ≈ 0.01 on a cantilever (header of
  // FirstMode), is comparable to β's: both terms are checked.
  const double alpha = 60.0, beta = 2e-4;  // [1/s], [s]
  const std::string text = cantilever("{rayleigh: [60, 2.0e-4]}", 1.2);
  const FirstMode mode = cantilever_first_mode(io::read_case_text(text, "damped_beam.yaml").flexible_bodies[0].model);
  const History run = run_case_text(text);
  // Peak-to-peak swings from the third period on (the second mode, ζ₂ ≈ 3 %, has decayed to a
  // few 1e-4 of the first by then); a period apart, they fall by exp(−ζ ω T_d).
  const std::size_t skip = static_cast<std::size_t>(0.3 / 2e-4);
  const std::vector<std::size_t> maxima = extrema(run.tip_y, skip, true), minima = extrema(run.tip_y, skip, false);
  ASSERT_GE(maxima.size(), 6u);
  ASSERT_GE(minima.size(), 6u);
  const auto swing = [&](std::size_t k) { return run.tip_y[maxima[k]] - run.tip_y[minima[k]]; };
  const std::size_t periods = std::min(maxima.size(), minima.size()) - 1;
  const double decrement = std::log(swing(0) / swing(periods)) / static_cast<double>(periods);
  const double period = (run.t[maxima[periods]] - run.t[maxima[0]]) / static_cast<double>(periods);
  const double zeta = decrement / std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + decrement * decrement);
  const double omega = 2.0 * std::numbers::pi / period / std::sqrt(1.0 - zeta * zeta);
  const double expected = mode.kappa * alpha / (2.0 * omega) + beta * omega / 2.0;
  std::printf("  cantilever: omega %.5f rad/s (FE, lumped mass: %.5f), kappa %.5f, zeta %.6f against %.6f "
              "(alpha part %.6f, beta part %.6f); %ld steps, %ld Newton iterations, %ld matrices, energy %.2e\n",
              omega, mode.omega, mode.kappa, zeta, expected, mode.kappa * alpha / (2.0 * omega), beta * omega / 2.0,
              run.summary.statistics.steps, run.summary.statistics.newton_iterations,
              run.summary.statistics.jacobian_evaluations, run.summary.accuracy.energy_relative);
  // The frequency is the FE model's: gravity's prestress and the 5 mm sag change it by < 1e-3.
  EXPECT_NEAR(omega, mode.omega, 2e-3 * mode.omega);
  // 1 %: at ρ∞ = 1 and 600 steps per period the scheme's own effect on the decrement is
  // O((ωh)²) ≈ 1e-4; the samples' peak timing (h) changes the swings by ~1e-5 of their size;
  // what is left of the second mode and the static sag's nonlinearity stay below 1e-3.
  EXPECT_NEAR(zeta, expected, 0.01 * expected);
  // Both terms count: α's share is not negligible, nor β's; and α is not α/(2ω₁) here (that
  // would be 0.58, against κ α/(2ω₁) ≈ 0.006), so the decrement tells the two forms apart.
  EXPECT_LT(mode.kappa, 0.05);
  EXPECT_GT(mode.kappa * alpha / (2.0 * omega), 0.2 * expected);
  EXPECT_GT(beta * omega / 2.0, 0.2 * expected);
}

TEST(NonlinearDamping, EnergyBalanceClosesWithTheDissipatedWork) {
  const History run = run_case_text(cantilever("{rayleigh: [2.0, 2.0e-4]}", 0.5));
  // The damping removes a large share of the start's vibration energy: it must be counted.
  const double dissipated = run.dissipated.back();
  const double swing_energy = std::abs(run.balance.front() - (run.balance.back() - dissipated));
  std::printf("  energy: dissipated %.6e J; K + V + U + W_d from %.6e to %.6e J; run's balance %.2e\n", dissipated,
              run.balance.front(), run.balance.back(), run.summary.accuracy.energy_relative);
  EXPECT_GT(dissipated, 0.0);
  EXPECT_GT(swing_energy, 0.1 * dissipated);
  // K + V_g + U + W_d stays constant to the integrator's accuracy (1e-3 of the work dissipated).
  for (const double b : run.balance) EXPECT_NEAR(b, run.balance.front(), 1e-3 * dissipated);
  EXPECT_TRUE(run.summary.accurate()) << run.summary.accuracy.energy_relative;
}

TEST(NonlinearDamping, TumblingFreeBeamKeepsItsMomentum) {
  // The free beam turning at 20 rad/s about a transverse axis and 3 rad/s about its own, no
  // gravity: the spin stretches and bends it, α = 50/s and β damp that. α M v would take
  // 1 − exp(−α t) = 92 % of its momentum in 0.05 s.
  std::string text = beam_case("{rayleigh: [50, 2.0e-4]}",
                               "gravity: [0, 0, 0]\n"
                               "run: {integrator: galpha, step: 2.0e-4, rho_inf: 0.8, t_end: 0.05, sample_interval: 1.0e-3}\n");
  text.insert(text.find("    damping:"), "    angular_velocity: [3, 0, 20]\n");
  const History run = run_case_text(text);
  const Eigen::Matrix<double, 6, 1>& start = run.momentum.front();
  double largest_change = 0.0;
  for (const auto& m : run.momentum) largest_change = std::max(largest_change, (m - start).norm());
  std::printf("  tumbling: |p| %.6e kg m/s, |L| %.6e kg m^2/s, largest change %.3e; dissipated %.3e J; "
              "energy balance %.2e\n",
              start.head<3>().norm(), start.tail<3>().norm(), largest_change, run.dissipated.back(),
              run.summary.accuracy.energy_relative);
  EXPECT_GT(run.dissipated.back(), 0.0);
  // No external force or moment and a damping without net force or moment: the momentum is the
  // integrator's to keep; 1e-4 of |L| (the undamped standalone beam drifts 4e-5 in 0.5 s at
  // 4e-4 s, docs/nonlinear-beams.md), against the 0.92 plain mass damping would take.
  // The linear momentum to Newton's tolerance (α's Newton matrix leaves the projection out).
  EXPECT_LT((run.momentum.back().head<3>() - start.head<3>()).norm(), 1e-7 * start.head<3>().norm());
  EXPECT_LT(largest_change, 1e-4 * start.norm());
  EXPECT_TRUE(run.summary.accurate()) << run.summary.accuracy.energy_relative;
}

}  // namespace
}  // namespace limber::run
