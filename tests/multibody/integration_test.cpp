// The multibody model driven by the time integrators of solver/integrate through the
// MechanicalSystem interface: pendulum period, energy and rod tension along the run,
// double pendulum energy, and the redundant slider-crank (closed form and energy balance
// with the driver's work).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "integrate/simulate.h"
#include "multibody/assembly.h"
#include "multibody/dynamics.h"
#include "multibody/energy_rates.h"
#include "multibody/multibody_system.h"
#include "multibody/reactions.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;

constexpr double kG = 9.81;

// A chain of `n` bobs (mass m, central inertia J about the joint axis) on massless-like
// arms of length L, revolutes about ground y, bob k starting at angle theta0 from the
// downward vertical (all in line). Body frames at the bobs; joint k at the previous bob.
Model pendulum_chain(int n, double m, double L, double J, double theta0) {
  ModelBuilder builder;
  builder.set_gravity(Eigen::Vector3d(0, 0, -kG));
  const Eigen::Vector3d e(std::sin(theta0), 0, -std::cos(theta0));
  const Eigen::Matrix3d R_axis = frame_from_axes(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
  std::string previous = "ground";
  for (int k = 1; k <= n; ++k) {
    const std::string name = "bob" + std::to_string(k);
    const Eigen::Vector3d pivot = (k - 1) * L * e, position = k * L * e;
    builder.add_rigid_body(body_spec(name, m, Eigen::Vector3d(J, J, J), position));
    std::string joint = "J";  // built by appending: GCC 12 warns falsely on "J" + to_string(k)
    joint += std::to_string(k);
    builder.add_marker_at(joint + ".i", previous, pivot, R_axis);
    builder.add_marker_at(joint + ".j", name, pivot, R_axis);
    builder.add_joint(joint, JointType::kRevolute, joint + ".i", joint + ".j");
    previous = name;
  }
  return builder.build();
}

// Assembled start, its partition, and the system the integrators see.
struct PreparedRun {
  State start;
  ConstraintPartition partition;
};

PreparedRun prepare(const Model& model, double t0 = 0.0) {
  Workspace ws(model);
  PreparedRun run;
  run.start = initial_state(model);
  run.start.t = t0;
  LIMBER_DEMAND(assemble_positions(model, run.start, ws, {1e-12, 50, {}}).status == AssemblyStatus::kOk);
  assemble_velocities(model, run.start, ws);
  run.partition = analyse_redundancy(model, run.start, ws);
  return run;
}

// Angle from the downward vertical of the bob at body b (θ grows from −z towards +x).
double swing_angle(const Model& model, const Eigen::VectorXd& q, int b, const Eigen::Vector3d& pivot) {
  const Eigen::Vector3d r = q.segment<3>(model.bodies[b].q_offset) - pivot;
  return std::atan2(r.x(), -r.z());
}

TEST(Integration, PendulumSmallAmplitudePeriodAndTension) {
  // Period of small oscillations 2π sqrt((J + m L²) / (m g L)) (1 + θ0²/16); the amplitude
  // term is 6e-6 here. IDA at rtol 1e-9; zero crossings of θ found by linear
  // interpolation between 1 ms samples (θ is nearly linear there: error < 1e-9 s).
  const double m = 1.3, L = 0.8, J = 1e-5, theta0 = 0.01;
  const Model model = pendulum_chain(1, m, L, J, theta0);
  const PreparedRun run = prepare(model);
  MultibodySystem system(model, run.partition);
  Workspace ws(model);
  const double period = 2 * std::numbers::pi * std::sqrt((J + m * L * L) / (m * kG * L)) * (1 + theta0 * theta0 / 16);
  std::vector<double> crossings;
  double previous_t = 0.0, previous_theta = theta0, max_tension_error = 0.0;
  const auto on_sample = [&](const integrate::Sample& s) {
    const double theta = swing_angle(model, s.q, 1, Eigen::Vector3d::Zero());
    if (previous_theta > 0 && theta <= 0) {
      crossings.push_back(previous_t + (s.t - previous_t) * previous_theta / (previous_theta - theta));
    }
    previous_t = s.t;
    previous_theta = theta;
    // Rod tension from the reactions vs m (g cos θ + L θ̇²), θ̇ = −ω_y.
    const State state{s.t, s.q, s.v};
    const Reactions r = compute_reactions(model, state, s.vdot, run.partition, ws);
    const Eigen::Vector3d e(std::sin(theta), 0, -std::cos(theta));
    const double theta_dot = -s.v(4);
    const double tension = m * (kG * std::cos(theta) + L * theta_dot * theta_dot);
    max_tension_error = std::max(max_tension_error, std::abs(-r.joints[0].force_j_W.dot(e) - tension));
  };
  const auto result = integrate::simulate(system, integrate::IntegratorOptions::ida(1e-9, 1e-11),
                                          {0.0, run.start.q, run.start.v},
                                          integrate::uniform_sample_times(0.0, 2.2 * period, 1e-3), on_sample);
  ASSERT_TRUE(result.status.ok()) << result.status.message;
  ASSERT_GE(crossings.size(), 2u);
  // IDA's global error at rtol 1e-9 over two periods: ~1e-8 relative in phase.
  EXPECT_NEAR((crossings[1] - crossings[0]) / period, 1.0, 1e-6);
  // Tension: the reactions use the integrator's v̇, interpolated between steps (IDAGetDky):
  // its error ~ rtol-scaled, far below 1e-6 m g.
  EXPECT_LT(max_tension_error, 1e-6 * m * kG);
}

// Total energy T + V over a run sampled every 10 ms; returns the largest deviation.
double energy_drift(const Model& model, const integrate::IntegratorOptions& options, double t_end,
                    integrate::SimulationResult& result) {
  const PreparedRun run = prepare(model);
  MultibodySystem system(model, run.partition);
  Workspace ws(model);
  double e0 = 0.0, drift = 0.0;
  bool first = true;
  const auto on_sample = [&](const integrate::Sample& s) {
    const EnergyTerms e = energies(model, State{s.t, s.q, s.v}, ws);
    const double total = e.kinetic + e.gravity + e.spring;
    if (first) e0 = total, first = false;
    drift = std::max(drift, std::abs(total - e0));
  };
  result = integrate::simulate(system, options, {0.0, run.start.q, run.start.v},
                               integrate::uniform_sample_times(0.0, t_end, 1e-2), on_sample);
  return drift;
}

TEST(Integration, DoublePendulumKeepsItsEnergy) {
  // Chaotic double pendulum released at 1 rad, 10 s. Reference energy scale m g L.
  // IDA at rtol 1e-8: energy error of the order of the tolerance times the energy scale
  // accumulated over ~1e3 steps: bound 1e-5 m g L; an error in M or Q drifts O(1).
  const double m = 1.0, L = 0.5;
  const Model model = pendulum_chain(2, m, L, 1e-4, 1.0);
  integrate::SimulationResult result;
  const double drift = energy_drift(model, integrate::IntegratorOptions::ida(1e-8, 1e-10), 10.0, result);
  ASSERT_TRUE(result.status.ok()) << result.status.message;
  EXPECT_LT(drift, 1e-5 * m * kG * L) << "drift " << drift << " J";
}

TEST(Integration, DoublePendulumGeneralizedAlpha) {
  // ρ∞ = 0.95, h = 1 ms: the scheme is second order with dissipation O(1 − ρ∞) only at
  // high frequencies; at the pendulum's ωh ≈ 5e-3 the energy error over 10 s stays
  // O((ωh)²) ≈ 3e-5 relative: bound 1e-4 m g L. (ρ∞ = 1, the trapezoidal rule, is
  // known to be only marginally stable on index-3 constraints and is not used here.)
  const double m = 1.0, L = 0.5;
  const Model model = pendulum_chain(2, m, L, 1e-4, 1.0);
  integrate::SimulationResult result;
  const double drift =
      energy_drift(model, integrate::IntegratorOptions::generalized_alpha(1e-3, 0.95), 10.0, result);
  ASSERT_TRUE(result.status.ok()) << result.status.message;
  EXPECT_LT(drift, 1e-4 * m * kG * L) << "drift " << drift << " J";
}

// work_tolerance: bound on the difference of the two driver-work integrals relative to
// the kinetic energy scale, or ≤ 0 when the integrator's (v̇, λ) are not consistent to a
// known bound (IDA hands its quadrature Newton iterates, converged to its own weights).
void check_slider_crank(integrate::IntegratorOptions options, double x_tolerance, double balance_tolerance,
                        double work_tolerance) {
  // Redundant seed slider-crank through IDA (only its 18 independent rows): slider x vs
  // a cos θ + sqrt(b² − a² sin² θ) over 2 crank turns, and T + V − W_driver constant,
  // W_driver = ∫ effort · ḟ dt accumulated by the integrator's quadrature.
  const testing::SliderCrankParameters p;
  const Model model = testing::slider_crank(p);
  const PreparedRun run = prepare(model);
  ASSERT_EQ(run.partition.redundant.size(), 3u);
  MultibodySystem system(model, run.partition);
  EXPECT_EQ(system.nc(), 18);
  Workspace ws(model), ws_power(model);
  options.quadrature.size = 2;
  options.quadrature.integrand = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                     const Eigen::VectorXd& v_dot, const Eigen::VectorXd& lambda, Eigen::VectorXd& f) {
    // Driver power from the integrator's multipliers, and from the minimum-norm reactions.
    f(0) = energy_rates(model, run.partition, State{t, q, v}, v_dot, lambda, ws_power).driver;
    f(1) = compute_reactions(model, State{t, q, v}, v_dot, run.partition, ws_power).driver_power;
  };
  const int slider = model.find_body("slider");
  double max_x_error = 0.0, e0 = 0.0, max_balance_error = 0.0, max_kinetic = 0.0, max_work_difference = 0.0;
  bool first = true;
  const auto on_sample = [&](const integrate::Sample& s) {
    const double th = p.speed * s.t;
    const double x = p.a * std::cos(th) + std::sqrt(p.b * p.b - p.a * p.a * std::sin(th) * std::sin(th));
    max_x_error = std::max(max_x_error, std::abs(s.q(model.bodies[slider].q_offset) - x));
    const EnergyTerms e = energies(model, State{s.t, s.q, s.v}, ws);
    const double balance = e.kinetic + e.gravity - s.integrals(0);
    if (first) e0 = balance, first = false;
    max_balance_error = std::max(max_balance_error, std::abs(balance - e0));
    max_kinetic = std::max(max_kinetic, e.kinetic);
    max_work_difference = std::max(max_work_difference, std::abs(s.integrals(0) - s.integrals(1)));
  };
  const auto result = integrate::simulate(system, options, {0.0, run.start.q, run.start.v},
                                          integrate::uniform_sample_times(0.0, 0.1, 5e-4), on_sample);
  ASSERT_TRUE(result.status.ok()) << result.status.message;
  // Positions are held on g = 0 by the index-2 stabilisation: error ~ rtol · a.
  EXPECT_LT(max_x_error, x_tolerance);
  // Driver work balances the mechanical energy to the integration tolerance (relative
  // to the largest kinetic energy, ~40 J).
  EXPECT_LT(max_balance_error, balance_tolerance * max_kinetic) << max_balance_error << " J of " << max_kinetic;
  // Both ways to the driver effort agree (the driver row is determinate) up to the
  // consistency of the integrator's (v̇, λ).
  if (work_tolerance > 0.0) {
    EXPECT_LT(max_work_difference, work_tolerance * max_kinetic);
  }
}

TEST(Integration, SliderCrankIda) {
  // IDA at rtol 1e-8: positions held on g = 0 by the index-2 stabilisation (error
  // ~ rtol · a ~ 1e-9 m); energy balance to ~1e-5 of the largest kinetic energy.
  check_slider_crank(integrate::IntegratorOptions::ida(1e-8, 1e-10), 1e-7, 1e-5, 0.0);
}

TEST(Integration, SliderCrankGeneralizedAlpha) {
  // Generalized-α, h = 20 µs (2500 steps per crank turn), ρ∞ = 0.9: positions satisfy
  // g = 0 at every step (index 3) to the Newton tolerance; the energy balance carries the
  // O(h²) error of the scheme, (ωh)² ≈ 6e-6 relative: bound 1e-4. Its (v̇, λ) satisfy the
  // equations to the Newton tolerance 1e-10: on driver powers of ~1e4 W over 0.1 s the two
  // work integrals differ by ~1e-7 J; bound 1e-8 of the kinetic energy scale (~5e-6 J).
  check_slider_crank(integrate::IntegratorOptions::generalized_alpha(2e-5, 0.9), 1e-7, 1e-4, 1e-8);
}

}  // namespace
}  // namespace limber::multibody
