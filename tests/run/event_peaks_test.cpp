// Event peaks tracked at every integrator step (run/event_peaks.h) on a deploying wing with a
// latch (tests/run/data/deployment_one_wing.yaml: the root hinge latches at 2.92 s): a run
// sampled every 20 steps tracks peaks at least as large as its samples show, and equal to
// round-off to those of the same run sampled at every step (generalized-α's samples on its step
// grid are its step ends: a second, independent route to the same numbers). The peaks go to
// results.h5 and read back unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "results/event_peaks.h"
#include "results/results_writer.h"
#include "run/run_driver.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

const std::string kWing = std::string(LIMBER_TEST_DATA_DIR) + "/deployment_one_wing.yaml";

struct SampledRun {
  RunSummary summary;
  std::vector<results::Sample> samples;
};

// The wing at h = 1 ms to 3.25 s (the root latch-up at 2.92 s and its 0.3 s window), samples
// every `interval`, event peaks over `window` (0: none), written to `directory` when given.
SampledRun run_wing(double interval, const std::filesystem::path& directory = {}, double window = 0.3) {
  const io::Case input = io::read_case_text(test::read_text(kWing), kWing);
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;
  settings.integrator = integrate::IntegratorOptions::generalized_alpha(1e-3, 0.8);
  settings.t_end = 3.25;
  settings.sample_interval = interval;
  settings.peak_window = window;
  SampledRun run;
  std::optional<results::ResultsWriter> writer;
  RunHooks hooks;
  if (!directory.empty()) {
    writer.emplace(directory, "wing", kWing);
    hooks.writer = &*writer;
  }
  hooks.on_sample = [&](const integrate::Sample&, const results::Sample& record) { run.samples.push_back(record); };
  run.summary = run_mechanism(built.model, built.assembly, settings, hooks);
  return run;
}

// The largest |F| and |T| (joint frame, on body j) of joint j over the samples in a window.
results::JointPeak sampled_peak(const SampledRun& run, const results::PeakWindow& window, std::size_t j) {
  results::JointPeak peak;
  for (const results::Sample& s : run.samples) {
    if (s.time < window.start.t || s.time > window.end) continue;
    peak.force = std::max(peak.force, s.joints[j].force_joint.norm());
    peak.torque = std::max(peak.torque, s.joints[j].torque_joint.norm());
  }
  return peak;
}

TEST(EventPeaks, StepTrackedPeaksBoundTheSamplesAndEqualARunSampledAtEveryStep) {
  const SampledRun coarse = run_wing(20e-3);
  const SampledRun every_step = run_wing(1e-3);
  ASSERT_TRUE(coarse.summary.ok) << coarse.summary.message;
  ASSERT_TRUE(every_step.summary.ok) << every_step.summary.message;
  // Windows: the start and the root latch (0.3 s each, the default).
  const results::EventPeaks& peaks = coarse.summary.peaks;
  ASSERT_EQ(peaks.windows.size(), 2u);
  EXPECT_EQ(peaks.windows[0].start.label, "start");
  EXPECT_EQ(peaks.windows[1].start.label, "latch latch_root");
  EXPECT_NEAR(peaks.windows[1].start.t, coarse.summary.events.front().t, 1e-12);
  EXPECT_DOUBLE_EQ(peaks.window, 0.3);
  const std::vector<std::string>& joints = peaks.joints;
  ASSERT_EQ(joints.size(), 4u);
  bool coarse_sampling_missed_a_peak = false;
  for (const results::PeakWindow& window : peaks.windows) {
    // About 300 steps of 1 ms in each window (the latch's step is cut back to the event).
    EXPECT_GE(window.states, 299);
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const results::JointPeak& tracked = window.joints[j];
      const results::JointPeak sampled = sampled_peak(coarse, window, j);
      const results::JointPeak exact = sampled_peak(every_step, window, j);
      // Samples on the step grid are step ends: the tracked peak is never below them. The
      // tracked reactions come from the integrator's multipliers, the samples' from Q − M v̇ at
      // the same state: equal to Newton's convergence of the equations of motion (tolerance
      // 1e-8 of the constraint forces; 6e-9 relative measured), bounded here at 1e-7.
      const double scale = std::max(tracked.force, 1.0);
      EXPECT_GE(tracked.force, sampled.force - 1e-7 * scale) << joints[j] << ", " << window.start.label;
      EXPECT_NEAR(tracked.force, exact.force, 1e-7 * scale) << joints[j] << ", " << window.start.label;
      EXPECT_NEAR(tracked.torque, exact.torque, 1e-7 * std::max(tracked.torque, 1.0)) << joints[j];
      // The largest component is at most the magnitude, and the magnitude at most their norm.
      EXPECT_LE(tracked.force_component.maxCoeff(), tracked.force * (1 + 1e-12));
      EXPECT_LE(tracked.force, tracked.force_component.norm() * (1 + 1e-12));
      EXPECT_GE(tracked.force_time, window.start.t);
      EXPECT_LE(tracked.force_time, window.end);
      if (tracked.force > sampled.force * 1.01) coarse_sampling_missed_a_peak = true;
    }
  }
  // 20 ms samples miss a latch-up peak by more than 1 % somewhere (that is the point).
  EXPECT_TRUE(coarse_sampling_missed_a_peak);
}

TEST(EventPeaks, ResultsFileHoldsThePeaksOfTheSummary) {
  const std::filesystem::path directory = test::fresh_directory("event_peaks");
  const SampledRun run = run_wing(20e-3, directory);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const results::EventPeaks read = results::read_event_peaks(directory / results::kResultsFileName);
  const results::EventPeaks& peaks = run.summary.peaks;
  EXPECT_EQ(read.joints, peaks.joints);
  EXPECT_EQ(read.window, peaks.window);
  ASSERT_EQ(read.windows.size(), peaks.windows.size());
  for (std::size_t w = 0; w < peaks.windows.size(); ++w) {
    EXPECT_EQ(read.windows[w].start.label, peaks.windows[w].start.label);
    EXPECT_EQ(read.windows[w].start.t, peaks.windows[w].start.t);
    EXPECT_EQ(read.windows[w].states, peaks.windows[w].states);
    for (std::size_t j = 0; j < peaks.joints.size(); ++j) {
      const results::JointPeak& a = read.windows[w].joints[j];
      const results::JointPeak& b = peaks.windows[w].joints[j];
      EXPECT_EQ(a.force, b.force);
      EXPECT_EQ(a.torque_time, b.torque_time);
      EXPECT_EQ(a.force_component, b.force_component);
      EXPECT_EQ(a.torque_component_time, b.torque_component_time);
    }
  }
  std::filesystem::remove_all(directory);
}

TEST(EventPeaks, NotTrackedUnlessAskedFor) {
  // peak_window 0 (`limber run`'s default): no windows, and no /event_peaks in the file.
  const std::filesystem::path directory = test::fresh_directory("no_event_peaks");
  const SampledRun run = run_wing(20e-3, directory, 0.0);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_TRUE(run.summary.peaks.windows.empty());
  const results::EventPeaks read = results::read_event_peaks(directory / results::kResultsFileName);
  EXPECT_TRUE(read.windows.empty());
  EXPECT_TRUE(read.joints.empty());
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace limber::run
