// Second-method checks: IDA against generalized-α on the constrained pendulum, and the
// accumulated quadratures against the energy balance of a damped pendulum.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "integrate/simulate.h"
#include "test_systems.h"

namespace limber::integrate {
namespace {

using testing::CartesianPendulum;

constexpr double kMass = 1.0, kLength = 1.0, kGravity = 9.81, kTheta0 = 1.0;

std::vector<Sample> run(MechanicalSystem& system, const IntegratorOptions& options,
                        const InitialState& start, const std::vector<double>& times) {
  std::vector<Sample> samples;
  const auto result =
      simulate(system, options, start, times, [&](const Sample& s) { samples.push_back(s); });
  EXPECT_TRUE(result.status.ok()) << result.status.message;
  return samples;
}

TEST(CrossCheck, IdaAndGeneralizedAlphaAgreeOnThePendulum) {
  // θ0 = 1 rad over 2 s, samples every 0.05 s (on the step grids). IDA at rtol = atol = 1e-10
  // (error ~1e-9, see IdaIntegrator.ErrorFallsWithTheTolerance) against generalized-α at
  // h = 0.5 ms and h/2. Order 2 means e(h) ≈ C h², so the Richardson value
  // R = (4 y_{h/2} − y_h)/3 removes the leading error: IDA must be ≥ 10 times closer to R than
  // to y_h, for q, v, v̇ and λ alike. Two different solutions would give a ratio ~1, and a
  // first-order error (e = C h, R off by C h/3) a ratio of 3.
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  const InitialState start{0.0, pendulum.position(kTheta0), Eigen::VectorXd::Zero(2)};
  const auto times = uniform_sample_times(0.0, 2.0, 0.05);
  const auto ida = run(pendulum, IntegratorOptions::ida(1e-10, 1e-10), start, times);
  // Tight Newton tolerance so that only the discretisation error is compared.
  IntegratorOptions galpha = IntegratorOptions::generalized_alpha(5e-4, 0.8);
  galpha.newton_tolerance = 1e-12;
  const auto coarse = run(pendulum, galpha, start, times);
  galpha.step = 2.5e-4;
  const auto fine = run(pendulum, galpha, start, times);
  ASSERT_EQ(ida.size(), times.size());
  ASSERT_EQ(coarse.size(), times.size());
  ASSERT_EQ(fine.size(), times.size());
  // Largest |IDA − y_h| and |IDA − R| of one quantity over the samples.
  const auto differences = [&](auto field) {
    double to_coarse = 0.0, to_richardson = 0.0;
    for (size_t i = 0; i < times.size(); ++i) {
      const Eigen::VectorXd richardson = (4.0 * field(fine[i]) - field(coarse[i])) / 3.0;
      to_coarse = std::max(to_coarse, (field(ida[i]) - field(coarse[i])).template lpNorm<Eigen::Infinity>());
      to_richardson = std::max(to_richardson, (field(ida[i]) - richardson).template lpNorm<Eigen::Infinity>());
    }
    return std::pair{to_coarse, to_richardson};
  };
  const auto q = differences([](const Sample& s) { return s.q; });
  const auto v = differences([](const Sample& s) { return s.v; });
  const auto vdot = differences([](const Sample& s) { return s.vdot; });
  const auto lambda = differences([](const Sample& s) { return s.lambda; });
  std::printf("|IDA - galpha(h)| / |IDA - Richardson|: q %.2e / %.2e, v %.2e / %.2e, "
              "vdot %.2e / %.2e, lambda %.2e / %.2e\n",
              q.first, q.second, v.first, v.second, vdot.first, vdot.second, lambda.first,
              lambda.second);
  for (const auto& [to_coarse, to_richardson] : {q, v, vdot, lambda}) {
    EXPECT_LT(to_richardson, to_coarse / 10.0);
  }
}

// Largest |E(t) + W(t) − E(0)| / (m g L) of a damped pendulum, W = ∫ c |v|² dt the energy the
// damper dissipated, accumulated as a quadrature.
double energy_balance_error(const IntegratorOptions& base) {
  CartesianPendulum pendulum(kMass, kLength, kGravity, 0.3);
  const InitialState start{0.0, pendulum.position(kTheta0), Eigen::VectorXd::Zero(2)};
  IntegratorOptions options = base;
  options.quadrature.size = 1;
  options.quadrature.integrand = [&](double, const Eigen::VectorXd&, const Eigen::VectorXd& v,
                                     const Eigen::VectorXd&, const Eigen::VectorXd&,
                                     Eigen::VectorXd& f) { f(0) = pendulum.damping() * v.squaredNorm(); };
  const double e0 = pendulum.energy(start.q, start.v);
  double error = 0.0, dissipated = 0.0;
  const auto result = simulate(pendulum, options, start, uniform_sample_times(0.0, 3.0, 0.01),
                               [&](const Sample& s) {
                                 dissipated = s.integrals(0);
                                 error = std::max(error, std::abs(pendulum.energy(s.q, s.v) +
                                                                  s.integrals(0) - e0));
                               });
  EXPECT_TRUE(result.status.ok()) << result.status.message;
  // The damper must have taken a sizeable share of the energy for the check to mean anything.
  EXPECT_GT(dissipated, 0.3 * (e0 + kMass * kGravity * kLength));
  return error / (kMass * kGravity * kLength);
}

TEST(CrossCheck, QuadratureClosesTheEnergyBalance) {
  // IDA at 1e-8: balance within 100 tol (same argument as the undamped energy test).
  // Generalized-α at h = 1 ms: trapezoidal quadrature and the state are both O(h²); bound
  // 10 h² / s² = 1e-5 (measured errors of the order test are ~4 h² in q).
  const double ida_error = energy_balance_error(IntegratorOptions::ida(1e-8, 1e-8));
  const double galpha_error = energy_balance_error(IntegratorOptions::generalized_alpha(1e-3, 0.8));
  std::printf("energy balance: IDA %.3e, gen-alpha %.3e\n", ida_error, galpha_error);
  EXPECT_LT(ida_error, 100.0 * 1e-8);
  EXPECT_LT(galpha_error, 1e-5);
}

}  // namespace
}  // namespace limber::integrate
