// SUNDIALS IDA on the GGL index-2 form: error against tolerance, energy, constraints, the
// quaternion invariant on a spinning body.
#include "integrate/ida_integrator.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "integrate/simulate.h"
#include "test_systems.h"

namespace limber::integrate {
namespace {

using testing::CartesianPendulum;

constexpr double kMass = 1.0, kLength = 1.0, kGravity = 9.81, kTheta0 = 1.0;

// Largest position error of an IDA pendulum run over samples every 0.05 s up to t_end.
double ida_pendulum_error(double tol, double t_end, Statistics* stats = nullptr,
                          IdaNewtonMatrix matrix = IdaNewtonMatrix::kDifferences) {
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  const std::vector<double> times = uniform_sample_times(0.0, t_end, 0.05);
  const auto reference = pendulum.reference(kTheta0, 0.0, times);
  const InitialState start{0.0, pendulum.position(kTheta0), Eigen::VectorXd::Zero(2)};
  double error = 0.0;
  int i = 0;
  IntegratorOptions options = IntegratorOptions::ida(tol, tol);
  options.ida_newton_matrix = matrix;
  const auto result =
      simulate(pendulum, options, start, times, [&](const Sample& s) {
        error = std::max(error,
                         (s.q - pendulum.position(reference[i++](0))).lpNorm<Eigen::Infinity>());
      });
  EXPECT_TRUE(result.status.ok()) << result.status.message;
  if (stats != nullptr) *stats = result.statistics;
  return error;
}

TEST(IdaIntegrator, ErrorFallsWithTheTolerance) {
  // rtol = atol from 1e-5 to 1e-10 every quarter decade on the θ0 = 1 rad pendulum over 2 s
  // (about one period), with either Newton matrix. IDA controls the local error, so the global
  // error is proportional to the tolerance only on average: order and step changes scatter
  // error/tol from point to point (measured 3.8–20 over these 21 tolerances with the difference
  // quotient, 2.8–26 with the structured matrix, and up to 36 with variants tried; geometric
  // means 8–10), so single points are bounded loosely and the trend tightly. Bounds: each error
  // within 50 tol; geometric mean of error/tol within 20; the least-squares slope of log error
  // against log tol (measured 0.89–0.93) within 0.75–1.1.
  for (const IdaNewtonMatrix matrix : {IdaNewtonMatrix::kDifferences, IdaNewtonMatrix::kStructured}) {
    double sum_x = 0.0, sum_y = 0.0, sum_xx = 0.0, sum_xy = 0.0;
    const int count = 21;
    for (int k = 0; k < count; ++k) {
      const double log_tol = -5.0 - 0.25 * k;
      const double tol = std::pow(10.0, log_tol);
      Statistics stats;
      const double error = ida_pendulum_error(tol, 2.0, &stats, matrix);
      std::printf("tol %.2e: error %.3e (%.1f tol), steps %ld\n", tol, error, error / tol,
                  stats.steps);
      EXPECT_LT(error, 50.0 * tol);
      const double log_error = std::log10(error);
      sum_x += log_tol;
      sum_y += log_error;
      sum_xx += log_tol * log_tol;
      sum_xy += log_tol * log_error;
    }
    const double slope = (count * sum_xy - sum_x * sum_y) / (count * sum_xx - sum_x * sum_x);
    const double mean_ratio = std::pow(10.0, (sum_y - sum_x) / count);
    std::printf("%s matrix: slope %.3f, geometric mean error/tol %.2f\n",
                matrix == IdaNewtonMatrix::kStructured ? "structured" : "differences", slope,
                mean_ratio);
    EXPECT_LT(mean_ratio, 20.0);
    EXPECT_GT(slope, 0.75);
    EXPECT_LT(slope, 1.1);
  }
}

TEST(IdaIntegrator, UndampedPendulumKeepsEnergyAndConstraint) {
  // 10 s (about 5 periods) at rtol = atol = 1e-8: the energy error, relative to m g L, and
  // the constraint residual |g| = ½|x² + y² − L²| are of the order of the tolerance (bounds:
  // 100 tol for the energy, which accumulates the local errors of ~2000 steps; 10 tol for g,
  // which IDA solves as an algebraic equation to its Newton tolerance).
  const double tol = 1e-8;
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  const InitialState start{0.0, pendulum.position(kTheta0), Eigen::VectorXd::Zero(2)};
  const double e0 = pendulum.energy(start.q, start.v);
  double energy_error = 0.0, constraint_error = 0.0;
  Eigen::VectorXd g;
  const auto result = simulate(pendulum, IntegratorOptions::ida(tol, tol), start,
                               uniform_sample_times(0.0, 10.0, 0.01), [&](const Sample& s) {
                                 energy_error = std::max(
                                     energy_error, std::abs(pendulum.energy(s.q, s.v) - e0));
                                 pendulum.constraints(s.t, s.q, g);
                                 constraint_error = std::max(constraint_error, std::abs(g(0)));
                               });
  ASSERT_TRUE(result.status.ok()) << result.status.message;
  const double energy_scale = kMass * kGravity * kLength;
  std::printf("energy error %.3e (relative), |g| %.3e, steps %ld\n", energy_error / energy_scale,
              constraint_error, result.statistics.steps);
  EXPECT_LT(energy_error / energy_scale, 100.0 * tol);
  EXPECT_LT(constraint_error, 10.0 * tol);
}

// The oscillator with twin events: e_0 rises through 0 at t = 0.3 s, e_1 1e-10 s later, within
// the event tolerance (1e-9 s) but far beyond IDA's root location (~100 ε (|t| + |h|) ~ 1e-14 s),
// as a symmetric mechanism's twin latches do. An applied event switches its mode, whose event
// function stays at −1 (as an engaged latch's). It records where each is applied.
class OscillatorWithTwinEvents final : public testing::ForwardingSystem {
 public:
  using ForwardingSystem::ForwardingSystem;
  std::vector<std::pair<int, double>> applied;
  int num_events() const override { return 2; }
  void event_functions(double t, const Eigen::VectorXd&, const Eigen::VectorXd&, Eigen::VectorXd& e) override {
    e.resize(2);
    e << t - 0.3, t - 0.3 - 1e-10;
    for (const auto& event : applied) e(event.first) = -1.0;
  }
  void apply_event(int k, double t, const Eigen::VectorXd&, const Eigen::VectorXd&) override {
    applied.emplace_back(k, t);
  }
};

TEST(IdaIntegrator, SwitchesTwinEventsTogether) {
  const double omega = 2.0 * std::numbers::pi;
  testing::Oscillator oscillator(1.0, omega * omega);
  OscillatorWithTwinEvents system(oscillator);
  const InitialState start{0.0, Eigen::VectorXd::Ones(1), Eigen::VectorXd::Zero(1)};
  const auto result = simulate(system, IntegratorOptions::ida(1e-8, 1e-10), start, {0.0, 0.5},
                               [](const Sample&) {});
  ASSERT_TRUE(result.status.ok()) << result.status.message;
  // Each once, at one instant: the root of e_0 to IDA's location (1e-12 s is 100 times that).
  ASSERT_EQ(system.applied.size(), 2u);
  EXPECT_EQ(system.applied[0].second, system.applied[1].second);
  EXPECT_NEAR(system.applied[0].second, 0.3, 1e-12);
}

TEST(IdaIntegrator, GroupErrorWeightsHoldTheErrorRelativeToTheLargestCoordinate) {
  // IdaErrorWeights::kPerGroup weighs each coordinate relative to the largest |q| (here L) and
  // each velocity relative to the largest |v|, so x and ẋ, which pass through 0 every swing, are
  // no longer held to atol (1e-14 here, so that only rtol acts). The θ0 = 1 rad pendulum over
  // 2 s against its closed form: the error stays within 50 rtol L, the bound ErrorFallsWith-
  // TheTolerance measures for per-component weights (3.8–26 tol), and the looser weights take
  // fewer steps than IDA's per-component ones.
  const double rtol = 1e-6;
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  const std::vector<double> times = uniform_sample_times(0.0, 2.0, 0.05);
  const auto reference = pendulum.reference(kTheta0, 0.0, times);
  const InitialState start{0.0, pendulum.position(kTheta0), Eigen::VectorXd::Zero(2)};
  long steps[2] = {0, 0};
  for (const IdaErrorWeights weights : {IdaErrorWeights::kPerComponent, IdaErrorWeights::kPerGroup}) {
    IntegratorOptions options = IntegratorOptions::ida(rtol, 1e-14);
    options.ida_error_weights = weights;
    double error = 0.0;
    int i = 0;
    const auto result = simulate(pendulum, options, start, times, [&](const Sample& s) {
      error = std::max(error, (s.q - pendulum.position(reference[i++](0))).lpNorm<Eigen::Infinity>());
    });
    ASSERT_TRUE(result.status.ok()) << result.status.message;
    const bool grouped = weights == IdaErrorWeights::kPerGroup;
    steps[grouped ? 1 : 0] = result.statistics.steps;
    std::printf("%s weights: error %.3e (%.1f rtol L), steps %ld\n", grouped ? "group" : "component", error,
                error / (rtol * kLength), result.statistics.steps);
    EXPECT_LT(error, 50.0 * rtol * kLength);
  }
  EXPECT_LT(steps[1], steps[0]);
}

}  // namespace
}  // namespace limber::integrate
