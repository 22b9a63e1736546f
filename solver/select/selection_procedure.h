// The seed paper's procedure for choosing the modes of flexible bodies (its Fig. 2) as one
// call, shared by `limber select` and Python's `limber.select` (docs/select.md): run with
// normal modes only, rank the joint reactions on the flexible bodies, keep the large ones as
// boundary conditions for static modes, run the mode sets that follow (its Fig. 6) with the
// reference's event windows again at half its step, compare them and name the one to use.
//
// Files under the request's root (selection_files.h): runs/<set>/results.h5, selection/*.csv,
// selected_modes.yaml and results.h5 (the chosen set's). The caller prints: the hooks report
// each set as it starts and ends, the returned Selection holds the rest.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "select/mode_set_candidates.h"
#include "select/peak_comparison.h"
#include "select/reaction_ranking.h"
#include "select/selection_study.h"
#include "select/step_choice.h"

namespace limber::select {

// What a selection is asked for (`limber select`'s options; docs/select.md).
struct SelectionRequest {
  std::filesystem::path root;        // DIR: created and locked while the selection runs
  double keep = 0.1;                 // kept: components >= keep × the body's largest, 0 < keep <= 1
  std::optional<double> target;      // error target (fraction): the fewest modes that meet it
  RankBy rank_by = RankBy::kPeak;
  ErrorNorm norm = ErrorNorm::kEvent;
  CandidateOptions candidates;
  StepPolicy policy;                 // its `scale` is set per run (0.5: the reference's check)
  int jobs = 2;                      // sets run at a time (threads)
  SettingsAdjustment adjust;         // the runs' settings from the case's; empty: the case's
  // `--reference nonlinear`: the sets are measured against the case with every flexible body
  // nonlinear (io/formulation_override.h; generalized-α at the case's step), and the richest
  // modal set runs as a set of its own ("richest"). Default: against the richest modal set.
  bool nonlinear_reference = false;
};

// "event", "peak" or "rms".
std::string to_string(ErrorNorm norm);

// The options' words as values: "peak" | "rms"; "event" | "peak" | "rms"; "attachment" |
// "constraint". Throw InputError naming `option` for another word.
RankBy rank_by_from(const std::string& word, const std::string& option = "--rank-by");
ErrorNorm error_norm_from(const std::string& word, const std::string& option = "--norm");
StaticModeKind static_kind_from(const std::string& word, const std::string& option = "--static-modes");

// Throws InputError (naming the option as `limber select` spells it) for a value out of range.
void check_request(const SelectionRequest& request);

// A set about to run: "[number/count] folder: description"; count 0 for the ranking run (the
// count is known after the ranking).
struct SetStart {
  std::size_t number = 1, count = 0;
  std::string folder;
  std::string description;
  double scale = 1.0;  // 0.5: the reference at half its step
};

struct SelectionHooks {
  std::function<void(const SetStart&)> on_set_start;
  // A set finished; `label` is its folder ("" for the ranking run).
  std::function<void(const CandidateRun&, const std::string& label)> on_set_done;
  std::function<void(const std::vector<RankedComponent>&)> on_ranking;
  // Every sample of every run, `alone` when that run is the only one running (runs on several
  // threads call it at once). It may throw SelectionInterrupted to stop the selection.
  std::function<void(const integrate::Sample&, bool alone)> on_sample;
};

// The reference's convergence in the step: its event peaks at half its step, each event window
// re-run from the reference's own state before its event (windowed_twin.h).
inline constexpr double kConvergedChange = 0.03;
struct ReferenceCheck {
  double step = 0.0, half_step = 0.0;  // [s]
  std::string half_step_status;        // the worst status of the re-runs ("ok" when all are)
  std::size_t windows_rerun = 0;       // stretches re-run (windows that overlap share one)
  PeakComparison change;               // its event peaks against the reference's
  bool converged = false;              // finished and every compared peak moved < kConvergedChange
};

struct Selection {
  std::vector<RankedComponent> ranking;
  std::vector<CandidateRun> runs;      // the ranking run ("normal") first, the reference last
  // Non-empty: the reference failed or its own accuracy check did, so the sets are not compared
  // (why, and what to change); `check`, `chosen` and `fragment` stay empty.
  std::string refusal;
  ReferenceCheck check;
  std::optional<std::size_t> chosen;   // index into `runs`
  std::string fragment;                // selected_modes.yaml's text ("" when none is chosen)
};

// Runs the procedure on `input` (read from a case file) and writes its files. Throws
// InputError for bad input (check_request, a case without flexible bodies; with a nonlinear
// reference, before any run: a flexible body that cannot be nonlinear, at its entry's
// file:line:col, and an integrator other than generalized-α or a static start), NumericalError when
// the ranking run fails, and lets SelectionInterrupted from a hook through (the finished runs'
// files stay, each closed).
Selection run_selection(std::shared_ptr<const io::Case> input, const SelectionRequest& request,
                        const SelectionHooks& hooks);

// Text shared by `limber select` and the refusal message: a fraction as "1.23 %" ("-": NaN);
// "20.0" steps per period or "20.0 (not resolved)"; "step 6.25e-05 s" or "step 6.25e-05 s in the
// 0.3 s event windows (5e-04 s between)".
std::string percent(double fraction);
std::string resolution(const StepChoice& step);
std::string step_text(const StepChoice& step);

}  // namespace limber::select
