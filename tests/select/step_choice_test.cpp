// The step each mode set runs at (select/step_choice.h) and the event-peak comparison
// (select/peak_comparison.h), against closed forms; the parallel runner of the sets.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "select/peak_comparison.h"
#include "select/selection_study.h"
#include "select/step_choice.h"

namespace limber::select {
namespace {

TEST(StepChoice, ResolvesTheHighestFrequencyWithTwentyStepsPerPeriod) {
  const integrate::IntegratorOptions galpha = integrate::IntegratorOptions::generalized_alpha(1e-3);
  // 100 Hz needs h ≤ 1 / (20 · 100) = 0.5 ms: half the case's step.
  StepChoice c = choose_step(100.0, galpha, {}, 0.0);
  EXPECT_DOUBLE_EQ(c.needed, 5e-4);
  EXPECT_DOUBLE_EQ(c.step, 5e-4);
  EXPECT_DOUBLE_EQ(c.steps_per_period, 20.0);
  EXPECT_TRUE(c.resolved);
  EXPECT_DOUBLE_EQ(apply_step(galpha, c).step, 5e-4);
  // 10 Hz: the case's step already resolves it and is never made longer.
  c = choose_step(10.0, galpha, {}, 0.0);
  EXPECT_DOUBLE_EQ(c.step, 1e-3);
  EXPECT_DOUBLE_EQ(c.steps_per_period, 100.0);
  EXPECT_TRUE(c.resolved);
  // 10 kHz would need 5 µs: the floor, 1 ms / 8, leaves 0.8 steps per period, not resolved.
  c = choose_step(1e4, galpha, {}, 0.0);
  EXPECT_DOUBLE_EQ(c.step, 1.25e-4);
  EXPECT_DOUBLE_EQ(c.steps_per_period, 0.8);
  EXPECT_FALSE(c.resolved);
  // Kept: the case's step, and 10 steps per period at 100 Hz is said to be short.
  c = choose_step(100.0, galpha, {true, 8}, 0.0);
  EXPECT_DOUBLE_EQ(c.step, 1e-3);
  EXPECT_FALSE(c.resolved);
  // Halved (the reference's check): half the chosen step, still resolved.
  c = choose_step(100.0, galpha, {false, 8, 0.5}, 0.0);
  EXPECT_DOUBLE_EQ(c.step, 2.5e-4);
  EXPECT_DOUBLE_EQ(c.steps_per_period, 40.0);
  EXPECT_TRUE(c.resolved);
  // No flexible modes: nothing to resolve.
  c = choose_step(0.0, galpha, {}, 0.0);
  EXPECT_DOUBLE_EQ(c.step, 1e-3);
  EXPECT_TRUE(c.resolved);
  EXPECT_TRUE(std::isinf(c.steps_per_period));
}

TEST(StepChoice, RefinesGeneralizedAlphaOnlyInTheEventWindows) {
  const integrate::IntegratorOptions galpha = integrate::IntegratorOptions::generalized_alpha(1e-3);
  // 100 Hz with 0.3 s windows: 0.5 ms in the windows, the case's 1 ms between them.
  StepChoice c = choose_step(100.0, galpha, {}, 0.3);
  EXPECT_DOUBLE_EQ(c.step, 5e-4);
  EXPECT_DOUBLE_EQ(c.window, 0.3);
  EXPECT_DOUBLE_EQ(c.outside_step, 1e-3);
  const integrate::IntegratorOptions applied = apply_step(galpha, c);
  EXPECT_DOUBLE_EQ(applied.step, 1e-3);
  EXPECT_DOUBLE_EQ(applied.event_step, 5e-4);
  EXPECT_DOUBLE_EQ(applied.event_window, 0.3);
  // Halved (the reference's check): both steps halved.
  c = choose_step(100.0, galpha, {false, 8, 0.5}, 0.3);
  EXPECT_DOUBLE_EQ(c.step, 2.5e-4);
  EXPECT_DOUBLE_EQ(c.outside_step, 5e-4);
  // The case's step already resolves 10 Hz: no windows. Asked for the whole run: none either.
  EXPECT_EQ(choose_step(10.0, galpha, {}, 0.3).window, 0.0);
  c = choose_step(100.0, galpha, {false, 8, 1.0, true}, 0.3);
  EXPECT_EQ(c.window, 0.0);
  EXPECT_DOUBLE_EQ(apply_step(galpha, c).step, 5e-4);
  EXPECT_EQ(apply_step(galpha, c).event_step, 0.0);
  // IDA adapts its step itself: its max_step bounds the whole run.
  EXPECT_EQ(choose_step(100.0, integrate::IntegratorOptions::ida(1e-6, 1e-8), {}, 0.3).window, 0.0);
}

TEST(StepChoice, BoundsIdasLargestStep) {
  // IDA without a max_step in the case: 1 / (20 f_max), with no floor.
  const integrate::IntegratorOptions ida = integrate::IntegratorOptions::ida(1e-6, 1e-8);
  StepChoice c = choose_step(100.0, ida, {}, 0.0);
  EXPECT_DOUBLE_EQ(c.step, 5e-4);
  EXPECT_TRUE(c.resolved);
  EXPECT_DOUBLE_EQ(apply_step(ida, c).max_step, 5e-4);
  EXPECT_DOUBLE_EQ(apply_step(ida, c).step, ida.step);
  c = choose_step(1e4, ida, {}, 0.0);
  EXPECT_DOUBLE_EQ(c.step, 5e-6);
  EXPECT_TRUE(c.resolved);
  // With a max_step of 1 ms in the case, floored at 1 ms / 8 like generalized-α's step.
  integrate::IntegratorOptions bounded = ida;
  bounded.max_step = 1e-3;
  c = choose_step(1e4, bounded, {}, 0.0);
  EXPECT_DOUBLE_EQ(c.step, 1.25e-4);
  EXPECT_FALSE(c.resolved);
  // Kept: no max_step, so nothing says the modes are followed.
  c = choose_step(100.0, ida, {true, 8}, 0.0);
  EXPECT_EQ(c.step, 0.0);
  EXPECT_FALSE(c.resolved);
}

// Peaks of one window "w" with two joints A, B.
results::EventPeaks peaks(const std::string& label, double start, double fa, double ta, double fb, double tb) {
  results::EventPeaks p;
  p.window = 0.3;
  p.joints = {"A", "B"};
  results::PeakWindow w{{start, label}, start + 0.3, 100, std::vector<results::JointPeak>(2)};
  w.joints[0].force = fa;
  w.joints[0].torque = ta;
  w.joints[1].force = fb;
  w.joints[1].torque = tb;
  p.windows.push_back(w);
  return p;
}

TEST(PeakComparison, RelativeDifferencesPerJointAndWindowAndTheWorst) {
  // A's force 110 against 100: 10 %; its torque 1.5 against 2: 25 %, the worst; B's force 0.5
  // against 0.8 is below 1 % of the window's largest force (100): not compared.
  const PeakComparison c =
      compare_peaks(peaks("latch L", 2.01, 110.0, 1.5, 0.5, 4.0), peaks("latch L", 2.0, 100.0, 2.0, 0.8, 4.0));
  ASSERT_EQ(c.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(c.rows[0].force_error, 0.1);
  EXPECT_DOUBLE_EQ(c.rows[0].torque_error, 0.25);
  EXPECT_TRUE(std::isnan(c.rows[1].force_error));
  EXPECT_DOUBLE_EQ(c.rows[1].torque_error, 0.0);
  EXPECT_DOUBLE_EQ(c.rows[0].start, 2.01);
  EXPECT_DOUBLE_EQ(c.rows[0].reference_start, 2.0);
  EXPECT_DOUBLE_EQ(c.error, 0.25);
  EXPECT_EQ(c.worst, "A torque, latch L");
  EXPECT_TRUE(c.unmatched.empty());
}

TEST(PeakComparison, AJointReleasedByTheWindowsStartIsNotCompared) {
  // B (a hold-down) released at t = 0: in the window opened at 0 its "peak" is its preload at
  // the instant of release (30 against 10: 200 %), which is not compared; A's 5 % is the error.
  // Released later than the window's start (at 1 s), B is compared like any joint.
  const auto run = peaks("start", 0.0, 105.0, 2.0, 30.0, 1.0);
  const auto reference = peaks("start", 0.0, 100.0, 2.0, 10.0, 1.0);
  const PeakComparison c = compare_peaks(run, reference, {{"B", 0.0}});
  ASSERT_EQ(c.rows.size(), 2u);
  EXPECT_TRUE(std::isnan(c.rows[1].force_error));
  EXPECT_TRUE(std::isnan(c.rows[1].torque_error));
  EXPECT_DOUBLE_EQ(c.error, 0.05);
  EXPECT_EQ(c.worst, "A force, start");
  EXPECT_DOUBLE_EQ(compare_peaks(run, reference, {{"B", 1.0}}).error, 2.0);
}

TEST(PeakComparison, TorquesAtRoundOffBesideTheForcesAreNotCompared) {
  // A planar mechanism against an unreduced rod: the reference's torques are round-off (5e-15
  // N m beside 2 kN, below 1e-6 of the largest peak), a modal run's the minimum-norm split of
  // its redundant joints (1e-4 N m). Not compared: the error is A's force difference, 1 %.
  // At 1e-3 N m (5e-7 of the force) still not; at 0.01 N m (5e-6) they are, by their own scale.
  const auto run = peaks("start", 0.0, 2020.0, 1e-4, 800.0, 2e-4);
  EXPECT_DOUBLE_EQ(compare_peaks(run, peaks("start", 0.0, 2000.0, 5e-15, 800.0, 0.0)).error, 0.01);
  EXPECT_DOUBLE_EQ(compare_peaks(run, peaks("start", 0.0, 2000.0, 1e-3, 800.0, 0.0)).error, 0.01);
  const PeakComparison compared = compare_peaks(run, peaks("start", 0.0, 2000.0, 1e-2, 800.0, 0.0));
  EXPECT_DOUBLE_EQ(compared.rows[0].torque_error, 0.99);
  EXPECT_EQ(compared.worst, "A torque, start");
}

TEST(PeakComparison, AnEventInOneRunOnlyIsAnInfiniteError) {
  const PeakComparison c =
      compare_peaks(peaks("latch M", 2.0, 100.0, 2.0, 1.0, 1.0), peaks("latch L", 2.0, 100.0, 2.0, 1.0, 1.0));
  EXPECT_TRUE(c.rows.empty());
  EXPECT_EQ(c.unmatched, (std::vector<std::string>{"latch M", "latch L"}));
  EXPECT_TRUE(std::isinf(c.error));
  EXPECT_NE(c.worst.find("latch M"), std::string::npos);
}

TEST(RunParallel, EveryJobOnceThenTheFirstFailureRethrown) {
  // Two workers: each of 50 jobs runs exactly once.
  std::vector<std::atomic<int>> runs(50);
  run_parallel(runs.size(), 2, [&](std::size_t k) { ++runs[k]; });
  for (const std::atomic<int>& r : runs) EXPECT_EQ(r.load(), 1);
  // A job that throws: the exception reaches the caller after the running jobs end, and no job
  // starts after it (job 0 throws before any other can finish on one worker).
  std::atomic<int> started{0};
  EXPECT_THROW(run_parallel(50, 1,
                            [&](std::size_t k) {
                              ++started;
                              if (k == 0) throw std::runtime_error("job 0");
                            }),
               std::runtime_error);
  EXPECT_EQ(started.load(), 1);
  EXPECT_THROW(run_parallel(50, 2, [&](std::size_t k) { if (k == 7) throw std::logic_error("job 7"); }),
               std::logic_error);
}

}  // namespace
}  // namespace limber::select
