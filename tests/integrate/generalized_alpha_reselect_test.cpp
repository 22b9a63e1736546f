// Generalized-α's restart on new constraint rows (GeneralizedAlpha::reselect_constraints: v̇ and
// λ from the saddle-point system, a = v̇, a fresh iteration matrix), which no case file reached
// (issue 31): a pendulum whose one row is re-selected, rescaled, at given times, run against the
// RK4 reference of the pendulum (test_systems.h) and against the same run without re-selection.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "integrate/simulate.h"
#include "test_systems.h"

namespace limber::integrate {
namespace {

using testing::CartesianPendulum;

// The Cartesian pendulum with its row g = s ½(x² + y² − L²), whose scale s the system switches
// between 1 and 2 at each of `switch_times` (reselect_constraints returns true there): the same
// motion, but λ = rod tension / (s L) changes meaning at each switch, as the multipliers of other
// rows do in a mechanism.
class RowSwitchingPendulum final : public MechanicalSystem {
 public:
  RowSwitchingPendulum(const CartesianPendulum& pendulum, std::vector<double> switch_times)
      : pendulum_(pendulum), switch_times_(std::move(switch_times)) {}
  int nq() const override { return 2; }
  int nv() const override { return 2; }
  int nc() const override { return 1; }
  int nh() const override { return 0; }
  void kinematic_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& N) const override {
    pendulum_.kinematic_matrix(q, N);
  }
  void integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                             Eigen::VectorXd& q_out) const override {
    pendulum_.integrate_coordinates(q, dv, q_out);
  }
  void coordinate_invariants(const Eigen::VectorXd& q, Eigen::VectorXd& h, Eigen::MatrixXd& h_q) const override {
    pendulum_.coordinate_invariants(q, h, h_q);
  }
  void mass_matrix(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& M) override { pendulum_.mass_matrix(t, q, M); }
  void generalized_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& Q) override {
    pendulum_.generalized_forces(t, q, v, Q);
  }
  void constraints(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g) override {
    pendulum_.constraints(t, q, g);
    g *= scale_;
  }
  void constraint_jacobian_q(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& g_q) override {
    pendulum_.constraint_jacobian_q(t, q, g_q);
    g_q *= scale_;
  }
  void constraint_jacobian_v(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& G) override {
    pendulum_.constraint_jacobian_v(t, q, G);
    G *= scale_;
  }
  void constraint_time_derivative(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g_t) override {
    pendulum_.constraint_time_derivative(t, q, g_t);
    g_t *= scale_;
  }
  void acceleration_rhs(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& gamma) override {
    pendulum_.acceleration_rhs(t, q, v, gamma);
    gamma *= scale_;
  }
  bool reselect_constraints(double t, const Eigen::VectorXd&) override {
    if (next_ >= switch_times_.size() || t < switch_times_[next_]) return false;
    ++next_;
    scale_ = scale_ == 1.0 ? 2.0 : 1.0;
    return true;
  }
  double scale() const { return scale_; }
  int switches() const { return static_cast<int>(next_); }

 private:
  CartesianPendulum pendulum_;
  std::vector<double> switch_times_;
  std::size_t next_ = 0;
  double scale_ = 1.0;
};

struct SwitchingRun {
  double q_error = 0.0;       // largest |q − q_ref| over the samples [m]
  double lambda_error = 0.0;  // largest |s λ − λ_ref| over the samples [N/m]
  int switches = 0;
  bool ok = false;
};

// θ0 = 1 rad, 1 s, samples every 0.1 s on the step grid (the switch times lie between them).
SwitchingRun run_switching(const std::vector<double>& switch_times, double h) {
  const double m = 1.0, L = 1.0, g0 = 9.81, theta0 = 1.0;
  const CartesianPendulum pendulum(m, L, g0);
  RowSwitchingPendulum system(pendulum, switch_times);
  const std::vector<double> times = uniform_sample_times(0.0, 1.0, 0.1);
  const auto reference = pendulum.reference(theta0, 0.0, times);
  const InitialState start{0.0, pendulum.position(theta0), Eigen::VectorXd::Zero(2)};
  SwitchingRun run;
  std::size_t i = 0;
  const auto compare = [&](const Sample& s) {
    const double theta = reference[i](0), theta_dot = reference[i](1);
    // λ_ref = rod tension / L; the row's λ is that over its scale.
    const double lambda = m * (g0 * std::cos(theta) + L * theta_dot * theta_dot) / L;
    const double q_error = (s.q - pendulum.position(theta)).lpNorm<Eigen::Infinity>();
    run.q_error = std::max(run.q_error, q_error);
    run.lambda_error = std::max(run.lambda_error, std::abs(system.scale() * s.lambda(0) - lambda));
    ++i;
  };
  const auto result =
      simulate(system, IntegratorOptions::generalized_alpha(h, 0.8), start, times, compare);
  run.ok = result.status.ok() && i == times.size();
  run.switches = system.switches();
  return run;
}

// Three re-selections (0.25, 0.55 and 0.85 s, between samples) against none, h = 1 ms. Each
// restart starts the scheme afresh (a = v̇), so the error stays the scheme's O(h²) with at
// most one start-up's share per restart: the positions within 4 times the run without switches
// of the reference, and λ, rescaled by the row's current scale, too (ρ∞ = 0.8 damps the
// restart's transient within a few steps; the samples are 50 or more steps after it). Measured:
// q 3.68e-6 m against 3.60e-6 m, λ 5.84e-5 against 5.85e-5 N/m. The reference is RK4 with global
// error ~1e-14 rad. What this guards is the restart's state (v̇ and λ solved on the new rows):
// a restart left out is not visible here, since this motion does not depend on the row's scale
// and the next step's Newton solves λ afresh (with reselect_constraints' restart removed the
// errors were 3.60e-6 m and 5.86e-5 N/m).
TEST(GeneralizedAlpha, RestartsOnReselectedRowsWithTheMotionUnchanged) {
  const double h = 1e-3;
  const SwitchingRun plain = run_switching({}, h);
  const SwitchingRun switched = run_switching({0.25, 0.55, 0.85}, h);
  std::printf("  no switch: |q| %.3e m, |lambda| %.3e N/m; three switches: |q| %.3e m, |lambda| %.3e N/m\n",
              plain.q_error, plain.lambda_error, switched.q_error, switched.lambda_error);
  ASSERT_TRUE(plain.ok);
  ASSERT_TRUE(switched.ok);
  EXPECT_EQ(plain.switches, 0);
  EXPECT_EQ(switched.switches, 3);
  // Second order at h = 1 ms (SecondOrderOnTheConstrainedPendulum): errors ~h².
  EXPECT_LT(plain.q_error, 10.0 * h * h);
  EXPECT_LT(switched.q_error, 4.0 * plain.q_error);
  EXPECT_LT(switched.lambda_error, 4.0 * plain.lambda_error);
}

}  // namespace
}  // namespace limber::integrate
