// The reference check's stretches started while the reference runs (select/half_step_runs.h),
// on the deploying wing of windowed_twin_test.cpp (its root hinge latches at 2.92 s): started
// early or after the reference, the check is the same, to the bit; and the rule that says when
// a stretch can start.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "run_test_support.h"
#include "select/half_step_runs.h"
#include "select/job_queue.h"
#include "select/selection_procedure.h"

namespace limber::select {
namespace {

const std::string kWing = std::string(LIMBER_TEST_DATA_DIR) + "/deployment_one_wing.yaml";

// The wing's reference: its own modes, generalized-α at 2 ms throughout (the case's step kept),
// 0.3 s windows, to 3.3 s (past the latch-up's window).
SelectionRequest wing_request(const std::string& folder) {
  SelectionRequest request;
  request.root = test::fresh_directory(folder);
  request.policy.keep_case_step = true;
  request.adjust = [](const io::RunSettings& case_settings) {
    io::RunSettings settings = case_settings;
    settings.integrator = integrate::IntegratorOptions::generalized_alpha(2e-3, 0.8);
    settings.t_end = 3.3;
    settings.peak_window = 0.3;
    return settings;
  };
  return request;
}

struct Check {
  std::vector<TwinStretch> stretches;
  std::vector<CandidateRun> runs;
  std::size_t started_early = 0;
};

// The reference and its check on a queue of two workers, as run_sets runs them: with `early`,
// through HalfStepRuns::run_reference (stretches start as the reference passes them); without,
// the reference run alone first (every stretch starts after it).
Check run_check(bool early) {
  const auto input = std::make_shared<const io::Case>(io::read_case_file(kWing));
  const SelectionRequest request = wing_request(early ? "half_step_early" : "half_step_late");
  const SelectionHooks hooks;
  const ModeSetCandidate candidate{"reference", "the wing's own modes", {}, true};
  HalfStepRuns half(request, hooks, 2, 1);
  std::optional<CandidateRun> reference;
  JobQueue queue;
  queue.push_back([&](JobQueue& running) {
    if (early) {
      half.run_reference(input, candidate, running, reference);
    } else {
      reference = run_candidate(input, candidate, request.adjust, request.policy,
                                request.root / results::kRunsFolder / "reference");
    }
    EXPECT_TRUE(reference->ok()) << reference->status();
    half.on_reference_done(running, *reference, nullptr);
  });
  queue.run(2);
  half.collect();
  return {half.stretches, std::move(half.runs), half.started_early};
}

TEST(HalfStepRuns, StretchesStartedWhileTheReferenceRunsGiveTheSameCheck) {
  const Check early = run_check(true), late = run_check(false);
  // The start window's stretch (to 0.315 s) is settled once the reference passes 0.615 s; the
  // latch-up's (2.92 s to the run's end) only when the reference has run.
  ASSERT_EQ(early.stretches.size(), 2u);
  EXPECT_EQ(early.started_early, 1u);
  EXPECT_EQ(late.started_early, 0u);
  ASSERT_EQ(late.stretches.size(), early.stretches.size());
  ASSERT_EQ(early.runs.size(), early.stretches.size());
  for (std::size_t k = 0; k < early.stretches.size(); ++k) {
    EXPECT_EQ(early.stretches[k].windows, late.stretches[k].windows);
    EXPECT_EQ(early.stretches[k].t_start(), late.stretches[k].t_start());
    EXPECT_EQ(early.stretches[k].t_end, late.stretches[k].t_end);
    ASSERT_TRUE(early.runs[k].ok()) << early.runs[k].summary.message;
    // The same run from the same state, on another thread beside the reference: the same
    // numbers to the bit (the model is shared read-only).
    const results::EventPeaks& a = early.runs[k].summary.peaks;
    const results::EventPeaks& b = late.runs[k].summary.peaks;
    ASSERT_EQ(a.windows.size(), b.windows.size());
    for (std::size_t w = 0; w < a.windows.size(); ++w) {
      EXPECT_EQ(a.windows[w].start.t, b.windows[w].start.t);
      for (std::size_t j = 0; j < a.windows[w].joints.size(); ++j) {
        EXPECT_EQ(a.windows[w].joints[j].force, b.windows[w].joints[j].force) << a.joints[j];
        EXPECT_EQ(a.windows[w].joints[j].torque, b.windows[w].joints[j].torque) << a.joints[j];
      }
    }
  }
}

TEST(HalfStepRuns, AStretchStartsOnceNoLaterWindowCanJoinIt) {
  // A window's restart point lies a step or two before its event; a stretch ending at 1.0 s
  // could still take a window whose event comes at 1.0 s + a step, not one past 1.3 s.
  TwinStretch stretch;
  stretch.t_end = 1.0;
  EXPECT_FALSE(stretch_settled(stretch, 1.001, 0.3));
  EXPECT_FALSE(stretch_settled(stretch, 1.29, 0.3));
  EXPECT_TRUE(stretch_settled(stretch, 1.3, 0.3));
}

}  // namespace
}  // namespace limber::select
