// SUNDIALS IDA on the GGL index-2 form: error against tolerance, energy, constraints, the
// quaternion invariant on a spinning body.
#include "integrate/ida_integrator.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "integrate/simulate.h"
#include "test_systems.h"

namespace limber::integrate {
namespace {

using testing::CartesianPendulum;

constexpr double kMass = 1.0, kLength = 1.0, kGravity = 9.81, kTheta0 = 1.0;

// Largest position error of an IDA pendulum run over samples every 0.05 s up to t_end.
double ida_pendulum_error(double tol, double t_end, Statistics* stats = nullptr) {
  const CartesianPendulum pendulum(kMass, kLength, kGravity);
  const std::vector<double> times = uniform_sample_times(0.0, t_end, 0.05);
  const auto reference = pendulum.reference(kTheta0, 0.0, times);
  const InitialState start{0.0, pendulum.position(kTheta0), Eigen::VectorXd::Zero(2)};
  double error = 0.0;
  int i = 0;
  const auto result =
      simulate(pendulum, IntegratorOptions::ida(tol, tol), start, times, [&](const Sample& s) {
        error = std::max(error,
                         (s.q - pendulum.position(reference[i++](0))).lpNorm<Eigen::Infinity>());
      });
  EXPECT_TRUE(result.status.ok()) << result.status.message;
  if (stats != nullptr) *stats = result.statistics;
  return error;
}

TEST(IdaIntegrator, ErrorFallsWithTheTolerance) {
  // rtol = atol = 1e-5 ... 1e-9 on the θ0 = 1 rad pendulum over 2 s (about one period).
  // IDA controls the local error, so the global error is proportional to the tolerance only
  // on average (order and step changes make the factor vary): each decade must cut the error
  // at least 3-fold, four decades at least 1000-fold, and the error must stay within 30 tol
  // (measured: 7–15 tol over one period).
  const std::vector<double> tolerances{1e-5, 1e-6, 1e-7, 1e-8, 1e-9};
  std::vector<double> errors;
  for (const double tol : tolerances) {
    Statistics stats;
    errors.push_back(ida_pendulum_error(tol, 2.0, &stats));
    std::printf("tol %.0e: error %.3e, steps %ld\n", tol, errors.back(), stats.steps);
    EXPECT_LT(errors.back(), 30.0 * tol);
  }
  for (size_t i = 1; i < errors.size(); ++i) EXPECT_GT(errors[i - 1] / errors[i], 3.0);
  EXPECT_GT(errors.front() / errors.back(), 1000.0);
}

TEST(IdaIntegrator, UndampedPendulumKeepsEnergyAndConstraint) {
  // 10 s (about 5 periods) at rtol = atol = 1e-8: the energy error, relative to m g L, and
  // the constraint residual |g| = ½|x² + y² − L²| are of the order of the tolerance (bounds:
  // 100 tol for the energy, which accumulates the local errors of ~2000 steps; 10 tol for g,
  // which IDA solves as an algebraic equation to its Newton tolerance).
  const double tol = 1e-8;
  const CartesianPendulum pendulum(kMass, kLength, kGravity);
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

}  // namespace
}  // namespace limber::integrate
