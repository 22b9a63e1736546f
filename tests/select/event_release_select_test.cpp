// `limber select`'s event windows and event peaks around a hold-down released at an event
// (`release: {after: <latch>, delay: s}`), on the small case of tests/run/event_release_run_test.cpp:
// an arm swung by a spring locks in a latch, and a bar held at its tip by HD lets go `delay`
// after that. The release opens a peak window and, with select's step choice, a window at the
// refined step, as the start and a latch-up do; and from its release on the joint is left out of
// the comparison, as a hold-down released at a fixed time is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "arm_and_bar_case.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"
#include "run_test_support.h"
#include "select/peak_comparison.h"
#include "select/selection_study.h"
#include "select/step_choice.h"

namespace limber::select {
namespace {

constexpr double kCaseStep = 1e-3, kWindow = 0.1;

const io::Mechanism& arm_and_bar() {
  static const io::Mechanism built = [] {
    const std::string path = test::write_case(
        "select_event_release",
        test::arm_and_bar_case("{after: lock, delay: 0.1}",
                               "integrator: galpha, step: 1.0e-3, t_end: 0.9, sample_interval: 0.01"));
    const io::Case input = io::read_case_file(path);
    return io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  }();
  return built;
}

// The case at its step between windows and `event_step` in the `kWindow` s after the start and
// after every event, as select's step choice sets a set's integrator (apply_step), event peaks
// over the same windows.
run::RunSummary run_with_event_step(double event_step) {
  StepChoice choice;
  choice.step = event_step;
  choice.window = kWindow;
  choice.outside_step = kCaseStep;
  io::RunSettings settings = arm_and_bar().run;
  settings.integrator = apply_step(settings.integrator, choice);
  settings.peak_window = kWindow;
  return run::run_mechanism(arm_and_bar().model, arm_and_bar().assembly, settings);
}

const results::PeakWindow& window_of(const results::EventPeaks& peaks, const std::string& label) {
  const auto it = std::find_if(peaks.windows.begin(), peaks.windows.end(),
                               [&](const results::PeakWindow& w) { return w.start.label == label; });
  EXPECT_NE(it, peaks.windows.end()) << label;
  return *it;
}

TEST(SelectEventRelease, AReleaseAtAnEventOpensAPeakWindowAtTheRefinedStep) {
  const run::RunSummary run = run_with_event_step(1e-4);
  ASSERT_TRUE(run.ok) << run.message;
  ASSERT_EQ(run.events.size(), 1u);
  ASSERT_EQ(run.releases.size(), 1u);
  EXPECT_NEAR(run.releases[0].t, run.events[0].t + 0.1, 1e-9);  // event_tolerance
  ASSERT_EQ(run.peaks.windows.size(), 3u);
  const results::PeakWindow& release = window_of(run.peaks, "release");
  EXPECT_EQ(release.start.t, run.releases[0].t);
  // The refined step holds for the window after the release as after the start: 0.1 s at
  // 1e-4 s, 1 000 states (100 at the case's step). The release restarts the integrator, which
  // opens its step window there; the states are counted inside [start, end] (one either side
  // at the boundaries: ±1).
  EXPECT_NEAR(static_cast<double>(release.states), kWindow / 1e-4, 1.0);
  EXPECT_NEAR(static_cast<double>(window_of(run.peaks, "start").states), kWindow / 1e-4, 1.0);
}

TEST(SelectEventRelease, AJointReleasedAtAnEventIsNotComparedFromItsRelease) {
  const run::RunSummary reference = run_with_event_step(1e-4), coarser = run_with_event_step(2e-4);
  ASSERT_TRUE(reference.ok && coarser.ok);
  const ReleaseTimes released = joint_release_times(arm_and_bar().model, reference);
  ASSERT_EQ(released.count("HD"), 1u);
  EXPECT_EQ(released.at("HD"), reference.releases[0].t);
  // Without the run's releases the model knows no release time for HD: it would be compared in
  // the release window, where its value is the preload it carried up to the instant of release.
  EXPECT_EQ(joint_release_times(arm_and_bar().model, {}).count("HD"), 0u);
  const PeakComparison comparison = compare_peaks(coarser.peaks, reference.peaks, released);
  ASSERT_TRUE(comparison.unmatched.empty());
  for (const PeakDifference& row : comparison.rows) {
    if (row.joint != "HD") continue;
    // Held (m g / 2 at the tip) in the start and latch-up windows; released when its own opens.
    EXPECT_EQ(std::isnan(row.force_error), row.window == "release") << row.window;
  }
}

}  // namespace
}  // namespace limber::select
