// The reference check's windowed twin (select/windowed_twin.h, run/window_restart.h) on a
// deploying wing with a latch (tests/run/data/deployment_one_wing.yaml: the root hinge latches
// at 2.92 s): its event windows re-run at half the step, each from the reference's own state
// before its event, give the peaks of the twin run whole at half the step in the windows (a
// second route to the same numbers), and a reference whose step does not resolve the latch-up
// is still called not converged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"
#include "run_test_support.h"
#include "select/peak_comparison.h"
#include "select/selection_study.h"
#include "select/windowed_twin.h"

namespace limber::select {
namespace {

const std::string kWing = std::string(LIMBER_TEST_DATA_DIR) + "/deployment_one_wing.yaml";
constexpr double kEnd = 3.3;  // past the root latch-up (2.92 s) and its 0.3 s window

const io::Mechanism& wing() {
  static const io::Mechanism built = [] {
    const io::Case input = io::read_case_text(test::read_text(kWing), kWing);
    return io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  }();
  return built;
}

struct WingRun {
  run::RunSummary summary;
  std::vector<run::WindowRestart> restarts;
};

// The wing with generalized-α at `step` between event windows and `event_step` in them
// (0.3 s after the start and after each event), to `t_end`, from `restart` when given.
WingRun run_wing(double step, double event_step, double t_end, const run::RestartPoint* restart = nullptr) {
  io::RunSettings settings = wing().run;
  settings.integrator = integrate::IntegratorOptions::generalized_alpha(step, 0.8);
  settings.integrator.event_step = event_step;
  settings.integrator.event_window = kSelectPeakWindow;
  settings.peak_window = kSelectPeakWindow;
  settings.t_end = t_end;
  WingRun run;
  run::RunHooks hooks;
  hooks.on_window = [&](const run::WindowRestart& window) { run.restarts.push_back(window); };
  run.summary = run::run_mechanism(wing().model, wing().assembly, settings, hooks, restart);
  return run;
}

// The reference's windows re-run at `event_step` from its own states, merged.
results::EventPeaks windowed_twin(const WingRun& reference, double step, double event_step) {
  const std::vector<TwinStretch> stretches = twin_stretches(reference.summary.peaks, reference.restarts, kEnd);
  std::vector<results::EventPeaks> peaks;
  for (const TwinStretch& stretch : stretches) {
    const WingRun rerun = run_wing(step, event_step, stretch.t_end, stretch.restart ? &*stretch.restart : nullptr);
    EXPECT_TRUE(rerun.summary.ok) << rerun.summary.message;
    peaks.push_back(rerun.summary.peaks);
  }
  return merge_stretch_peaks(reference.summary.peaks, stretches, peaks);
}

// Windows of 0.3 s at the given times and labels.
results::EventPeaks windows_at(const std::vector<std::pair<double, std::string>>& starts) {
  results::EventPeaks peaks;
  peaks.window = 0.3;
  for (const auto& [t, label] : starts) {
    results::PeakWindow window;
    window.start = {t, label};
    window.end = t + 0.3;
    peaks.windows.push_back(window);
  }
  return peaks;
}

// A restart point at t for the window `label` (its state does not matter here).
run::WindowRestart restart_at(double t, const std::string& label) {
  return run::WindowRestart{{t + 1e-3, label}, run::RestartPoint{t, {}, {}, {}}};
}

TEST(WindowedTwin, StretchesStartFromTheStartOrBeforeEachEventAndMergeWhenTheyOverlap) {
  // The start, two latches together at 2.0 s, one at 2.1 s, one at 6.0 s.
  const results::EventPeaks peaks =
      windows_at({{0.0, "start"}, {2.0, "latch A"}, {2.0, "latch B"}, {2.1, "latch C"}, {6.0, "latch E"}});
  const std::vector<run::WindowRestart> restarts{restart_at(1.999, "latch A"), restart_at(1.999, "latch B"),
                                                 restart_at(2.099, "latch C"), restart_at(5.999, "latch E")};
  const std::vector<TwinStretch> stretches = twin_stretches(peaks, restarts, 6.2);
  ASSERT_EQ(stretches.size(), 3u);
  EXPECT_FALSE(stretches[0].restart.has_value());
  EXPECT_EQ(stretches[0].windows, std::vector<std::string>{"start"});
  EXPECT_DOUBLE_EQ(stretches[0].t_end, 0.3 + kStretchMargin * 0.3);
  // A, B and C overlap: one stretch from A's restart point to C's window's end and a margin.
  ASSERT_TRUE(stretches[1].restart.has_value());
  EXPECT_DOUBLE_EQ(stretches[1].t_start(), 1.999);
  EXPECT_EQ(stretches[1].windows, (std::vector<std::string>{"latch A", "latch B", "latch C"}));
  EXPECT_DOUBLE_EQ(stretches[1].t_end, 2.4 + kStretchMargin * 0.3);
  // E ends at the run's end.
  EXPECT_DOUBLE_EQ(stretches[2].t_start(), 5.999);
  EXPECT_EQ(stretches[2].windows, std::vector<std::string>{"latch E"});
  EXPECT_DOUBLE_EQ(stretches[2].t_end, 6.2);
}

TEST(WindowedTwin, AWindowWithoutARestartPointIsReRunFromTheStart) {
  // D's event came before the run had a restart point: the start's stretch runs on to it.
  const std::vector<TwinStretch> stretches =
      twin_stretches(windows_at({{0.0, "start"}, {4.0, "latch D"}}), {}, 6.0);
  ASSERT_EQ(stretches.size(), 1u);
  EXPECT_FALSE(stretches[0].restart.has_value());
  EXPECT_EQ(stretches[0].windows, (std::vector<std::string>{"start", "latch D"}));
  EXPECT_DOUBLE_EQ(stretches[0].t_end, 4.3 + kStretchMargin * 0.3);
}

TEST(WindowedTwin, PeaksEqualThoseOfTheWholeTwin) {
  // Reference: 2 ms between windows, 1 ms in them; its twin at 0.5 ms in the windows, whole
  // (2 ms between, as the windowed twin leaves the motion between windows at the reference's
  // step) and windowed.
  const WingRun reference = run_wing(2e-3, 1e-3, kEnd);
  ASSERT_TRUE(reference.summary.ok) << reference.summary.message;
  ASSERT_EQ(reference.summary.peaks.windows.size(), 2u);
  ASSERT_EQ(reference.restarts.size(), 1u);
  EXPECT_EQ(reference.restarts[0].window.label, "latch latch_root");
  // The restart point lies before the latch-up, at most two steps before it.
  const double latch = reference.summary.peaks.windows[1].start.t;
  EXPECT_LT(reference.restarts[0].before.t, latch);
  EXPECT_GT(reference.restarts[0].before.t, latch - 2 * 2e-3 - 1e-12);
  const WingRun whole = run_wing(2e-3, 0.5e-3, kEnd);
  ASSERT_TRUE(whole.summary.ok) << whole.summary.message;
  const results::EventPeaks windowed = windowed_twin(reference, 2e-3, 0.5e-3);
  ASSERT_EQ(windowed.windows.size(), 2u);
  const PeakComparison twins = compare_peaks(windowed, whole.summary.peaks);
  const PeakComparison halving = compare_peaks(whole.summary.peaks, reference.summary.peaks);
  ASSERT_TRUE(twins.unmatched.empty());
  std::printf("windowed vs whole twin: %.3e (%s); whole twin vs reference: %.3e (%s)\n", twins.error,
              twins.worst.c_str(), halving.error, halving.worst.c_str());
  // The start window is the same run to its end: equal to round-off.
  for (const PeakDifference& row : twins.rows) {
    if (row.window != "start") continue;
    EXPECT_NEAR(row.force, row.reference_force, 1e-9 * row.reference_force) << row.joint;
    EXPECT_NEAR(row.torque, row.reference_torque, 1e-9 * row.reference_torque) << row.joint;
  }
  // The latch window starts from the reference's state instead of the twin's own: the two
  // differ by what halving the start window's step changed, carried over the slow, damped
  // deployment (3.9e-8 measured, while halving moves the peaks by 3.3 %). The check needs it
  // far below its 3 % threshold: a thousandth of it.
  EXPECT_LT(twins.error, 3e-5);
}

TEST(WindowedTwin, AnUnresolvedReferenceIsStillNotConverged) {
  // A reference at 10 ms in its windows does not follow the latch-up's ringing: the whole twin
  // at 5 ms moves its peaks by more than the 3 % that calls it converged, and so does the
  // windowed one.
  const WingRun reference = run_wing(10e-3, 10e-3, kEnd);
  ASSERT_TRUE(reference.summary.ok) << reference.summary.message;
  const WingRun whole = run_wing(10e-3, 5e-3, kEnd);
  ASSERT_TRUE(whole.summary.ok) << whole.summary.message;
  const double whole_change = compare_peaks(whole.summary.peaks, reference.summary.peaks).error;
  const double windowed_change = compare_peaks(windowed_twin(reference, 10e-3, 5e-3), reference.summary.peaks).error;
  std::printf("unresolved: whole twin %.3e, windowed twin %.3e\n", whole_change, windowed_change);
  EXPECT_GT(whole_change, 0.03);
  EXPECT_GT(windowed_change, 0.03);
  // Measured 4.46 % and 4.50 %: the two routes agree to a tenth of a percent.
  EXPECT_NEAR(windowed_change, whole_change, 1e-3);
}

}  // namespace
}  // namespace limber::select
