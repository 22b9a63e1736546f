// The run's accuracy estimate (run/accuracy_check.h) on samples with known energies and
// violations: each measure against its closed form, and the warnings that name the fix.
#include <gtest/gtest.h>

#include "run/accuracy_check.h"

namespace limber::run {
namespace {

// A sample with energies (kinetic, gravity, spring, strain, dissipated, driver work, force work),
// a position violation and joint points spanning `size` along x.
results::Sample sample(std::vector<double> energies, double violation, double size = 2.0) {
  results::Sample s;
  s.energies = std::move(energies);
  s.position_violation = violation;
  s.joints.resize(2);
  s.joints[1].position = Eigen::Vector3d(size, 0.0, 0.0);
  return s;
}

integrate::IntegratorOptions galpha(double step) { return integrate::IntegratorOptions::generalized_alpha(step, 0.8); }

TEST(AccuracyCheck, ExactBalanceIsAccurate) {
  // A driven, damped run whose work balances exactly: T + D − W = 0 at every sample.
  AccuracyMonitor monitor;
  monitor.add(sample({0, 0, 0, 0, 0, 0, 0}, 0.0));
  monitor.add(sample({10, 0, 0, 0, 2, 12, 0}, 1e-9));
  monitor.add(sample({5, 0, 0, 0, 9, 14, 0}, 2e-9));
  const AccuracyEstimate estimate = monitor.estimate({}, galpha(1e-3));
  EXPECT_DOUBLE_EQ(estimate.energy_residual, 0.0);
  // Scale: the largest magnitude of each term, 10 + 9 + 14 J.
  EXPECT_DOUBLE_EQ(estimate.energy_scale, 33.0);
  EXPECT_DOUBLE_EQ(estimate.position_violation, 2e-9);
  EXPECT_DOUBLE_EQ(estimate.size, 2.0);
  EXPECT_TRUE(estimate.accurate());
}

TEST(AccuracyCheck, EachMeasureAboveItsThresholdWarnsWithTheFix) {
  // Energy: 1 J created out of nothing against a scale of 10 + 1 (gravity's change) = 11 J, 9 %.
  AccuracyMonitor monitor;
  monitor.add(sample({0, 5, 0, 0, 0, 0, 0}, 0.0));
  monitor.add(sample({10, 4, 0, 0, 0, 8, 0}, 0.004));  // balance 14 − 8 = 6 against 5 at the start
  integrate::Statistics statistics;
  statistics.max_local_error = 0.03;
  const AccuracyEstimate estimate = monitor.estimate(statistics, galpha(1e-3));
  EXPECT_DOUBLE_EQ(estimate.energy_residual, 1.0);
  EXPECT_DOUBLE_EQ(estimate.energy_scale, 19.0);  // 10 + |4 − 5| + 8
  EXPECT_NEAR(estimate.energy_relative, 1.0 / 19.0, 1e-15);
  EXPECT_DOUBLE_EQ(estimate.drift_relative, 0.002);
  ASSERT_EQ(estimate.warnings.size(), 3u);
  EXPECT_NE(estimate.warnings[0].find("energy balance is off by 1 J"), std::string::npos) << estimate.warnings[0];
  EXPECT_NE(estimate.warnings[0].find("--step 0.00025"), std::string::npos) << estimate.warnings[0];
  EXPECT_NE(estimate.warnings[1].find("local error estimate reaches 3 %"), std::string::npos) << estimate.warnings[1];
  EXPECT_NE(estimate.warnings[2].find("joints come apart by 0.004"), std::string::npos) << estimate.warnings[2];
  EXPECT_FALSE(estimate.accurate());
  // IDA's fix is a tolerance.
  const AccuracyEstimate ida = monitor.estimate({}, integrate::IntegratorOptions::ida(1e-4, 1e-6));
  EXPECT_NE(ida.warnings[0].find("--rtol 1e-05 --atol 1e-07"), std::string::npos) << ida.warnings[0];
}

}  // namespace
}  // namespace limber::run
