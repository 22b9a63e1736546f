#include "select/selection_procedure.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "core/error.h"
#include "io/formulation_override.h"
#include "results/directory_lock.h"
#include "results/file_names.h"
#include "select/half_step_runs.h"
#include "select/job_queue.h"
#include "select/selection_files.h"
#include "select/windowed_twin.h"

namespace limber::select {

namespace {

// One set into DIR/runs/<folder>; `columns` as run_candidate's.
CandidateRun run_set(const std::shared_ptr<const io::Case>& input, const SelectionRequest& request,
                     const SelectionHooks& hooks, const ModeSetCandidate& candidate, const std::string& folder,
                     bool alone, const multibody::Model* columns = nullptr) {
  return run_candidate(input, candidate, request.adjust, request.policy,
                       request.root / results::kRunsFolder / folder_name(folder),
                       [&](const integrate::Sample& sample) {
                         if (hooks.on_sample) hooks.on_sample(sample, alone);
                       },
                       columns);
}

// The cases a selection runs: the one read, and with `--reference nonlinear` the same case with
// every flexible body nonlinear, for the reference.
struct SelectionInputs {
  std::shared_ptr<const io::Case> modal;
  std::shared_ptr<const io::Case> nonlinear;  // null without a nonlinear reference
  const multibody::Model* columns = nullptr;  // the ranking run's model (run_candidate's `columns`)
};

// `input` with every flexible body nonlinear. Refuses, before anything runs, what the nonlinear
// body cannot be (at the body's entry) and the settings it cannot run with (run_driver.cpp).
std::shared_ptr<const io::Case> nonlinear_case(const io::Case& input, const SelectionRequest& request) {
  auto nonlinear = std::make_shared<io::Case>(input);
  io::make_flexible_bodies_nonlinear(*nonlinear, "--reference nonlinear");
  const io::RunSettings settings = request.adjust ? request.adjust(input.mechanism->run) : input.mechanism->run;
  if (settings.integrator.method != integrate::Method::kGeneralizedAlpha) {
    throw InputError(fmt::format("--reference nonlinear: expected integrator galpha (a nonlinear body runs with "
                                 "the generalized-α only), got {}; give --integrator galpha --step H",
                                 integrate::to_string(settings.integrator.method)));
  }
  if (settings.start == io::StartKind::kStatics) {
    throw InputError("--reference nonlinear: expected run start: assembly (a static start of a nonlinear body is "
                     "not available), got statics; give --start assembly");
  }
  return nonlinear;
}

// The sets with the nonlinear reference in place of the richest modal set, which stays as a
// set of its own ("richest"): what the modal model reaches with many modes.
std::vector<ModeSetCandidate> with_nonlinear_reference(std::vector<ModeSetCandidate> candidates) {
  LIMBER_DEMAND(!candidates.empty() && candidates.back().reference);
  candidates.back().name = "richest";
  candidates.back().reference = false;
  candidates.push_back({"nonlinear", "every flexible body nonlinear: co-rotational FE beams, unreduced", {}, true,
                        true});
  return candidates;
}

// The sets after `normal` (candidates[0]), `jobs` at a time, the longest (the reference) first,
// appended to `runs` in the candidates' order; and the reference's event windows at half its
// step, each as soon as the reference has run past it (or, a nonlinear reference's, once it has
// run and passed its own accuracy check), ahead of the sets still waiting.
void run_sets(const SelectionInputs& inputs, const SelectionRequest& request, const SelectionHooks& hooks,
              const std::vector<ModeSetCandidate>& candidates, std::vector<CandidateRun>& runs, HalfStepRuns& half) {
  std::vector<std::size_t> order;
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    if (candidates[k].reference) order.insert(order.begin(), k);
    else order.push_back(k);
  }
  std::vector<std::optional<CandidateRun>> done(order.size());
  // The count counts the reference's check as one set until its windows are known.
  JobQueue queue;
  for (std::size_t j = 0; j < order.size(); ++j) {
    queue.push_back([&, j](JobQueue& running) {
      const ModeSetCandidate& candidate = candidates[order[j]];
      if (hooks.on_set_start) hooks.on_set_start({j + 2, order.size() + 2, candidate.name, candidate.description, 1.0});
      if (candidate.nonlinear) {
        done[j] = run_set(inputs.nonlinear, request, hooks, candidate, candidate.name, request.jobs <= 1, inputs.columns);
      } else if (candidate.reference) {
        half.run_reference(inputs.modal, candidate, running, done[j]);
      } else {
        done[j] = run_set(inputs.modal, request, hooks, candidate, candidate.name, request.jobs <= 1);
      }
      if (hooks.on_set_done) hooks.on_set_done(*done[j], candidate.name);
      if (candidate.reference && done[j]->summary.accurate()) {
        half.on_reference_done(running, *done[j], candidate.nonlinear ? inputs.columns : nullptr);
      }
    });
  }
  queue.run(std::max(1, std::min(request.jobs, static_cast<int>(order.size()))));
  half.collect();
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    const auto j = static_cast<std::size_t>(std::find(order.begin(), order.end(), k) - order.begin());
    runs.push_back(std::move(*done[j]));
  }
}

// Why a reference is refused, and what to change.
std::string refusal(const CandidateRun& reference, int max_refinement, const std::filesystem::path& root) {
  std::string why = reference.ok() ? fmt::format("finished, but its own accuracy check failed ({})",
                                                 fmt::join(reference.summary.accuracy.warnings, "; "))
                                   : "failed: " + reference.summary.message;
  return fmt::format(
      "the reference set ({} modes, f_max {:.0f} Hz, {}, steps per period: {}) {}, so differences to it "
      "mean nothing; run select with a shorter step (--max-refinement {} allows one {} times shorter than the "
      "case's, or --step) or fewer reference modes (--reference-normal); its run is in {}",
      reference.modes, reference.step.f_max, step_text(reference.step), resolution(reference.step), why, 2 * max_refinement,
      2 * max_refinement, reference.directory.lexically_relative(root).generic_string());
}

ReferenceCheck check_reference(const CandidateRun& reference, const HalfStepRuns& half) {
  ReferenceCheck check;
  check.step = reference.step.step;
  check.half_step = 0.5 * reference.step.step;
  check.windows_rerun = half.stretches.size();
  // The worst status of the stretches: a failure, else an inaccurate one, else ok.
  check.half_step_status = results::layout::status::kOk;
  for (const CandidateRun& run : half.runs) {
    if (!run.ok()) {
      check.half_step_status = run.status();
      return check;
    }
    if (!run.summary.accurate()) check.half_step_status = run.status();
  }
  if (half.runs.empty()) return check;
  check.half_step = half.runs.front().step.step;
  std::vector<results::EventPeaks> peaks;
  for (const CandidateRun& run : half.runs) peaks.push_back(run.summary.peaks);
  check.change = compare_peaks(merge_stretch_peaks(reference.summary.peaks, half.stretches, peaks),
                               reference.summary.peaks,
                               joint_release_times(reference.mechanism.model, reference.summary));
  check.converged = check.change.error < kConvergedChange;
  return check;
}

// The chosen set's fragment in DIR/selected_modes.yaml and its results as DIR/results.h5.
std::string write_choice(const SelectionRequest& request, const CandidateRun& run) {
  const std::string why =
      request.target ? fmt::format("The fewest modes whose {} error against 'reference' is at most {:g} ({}).",
                                   to_string(request.norm), *request.target, percent(run.error(request.norm)))
                     : fmt::format("The procedure's answer: static modes where the reactions are large ({} {} "
                                   "error against 'reference').", percent(run.error(request.norm)),
                                   to_string(request.norm));
  const std::string fragment = selected_modes_yaml(run, why);
  std::ofstream(request.root / "selected_modes.yaml", std::ios::binary) << fragment;
  std::filesystem::copy_file(run.directory / results::kResultsFileName, request.root / results::kResultsFileName,
                             std::filesystem::copy_options::overwrite_existing);
  return fragment;
}

}  // namespace

std::string to_string(ErrorNorm norm) {
  return norm == ErrorNorm::kRms ? "rms" : norm == ErrorNorm::kPeak ? "peak" : "event";
}

namespace {

[[noreturn]] void refuse(const std::string& option, const std::string& expected, const std::string& word) {
  throw InputError(fmt::format("expected {} {}, got '{}'", option, expected, word));
}

}  // namespace

RankBy rank_by_from(const std::string& word, const std::string& option) {
  if (word != "peak" && word != "rms") refuse(option, "peak or rms", word);
  return word == "rms" ? RankBy::kRms : RankBy::kPeak;
}

ErrorNorm error_norm_from(const std::string& word, const std::string& option) {
  if (word != "event" && word != "peak" && word != "rms") refuse(option, "event, peak or rms", word);
  return word == "rms" ? ErrorNorm::kRms : word == "peak" ? ErrorNorm::kPeak : ErrorNorm::kEvent;
}

StaticModeKind static_kind_from(const std::string& word, const std::string& option) {
  if (word != "attachment" && word != "constraint") refuse(option, "attachment or constraint", word);
  return word == "constraint" ? StaticModeKind::kConstraint : StaticModeKind::kAttachment;
}

void check_request(const SelectionRequest& request) {
  if (!(request.keep > 0.0 && request.keep <= 1.0)) {
    throw InputError(fmt::format("expected --keep in (0, 1], got {:g}", request.keep));
  }
  if (request.target && !(*request.target > 0.0)) {
    throw InputError(fmt::format("expected --target > 0 (a fraction, 0.02 = 2 %), got {:g}", *request.target));
  }
  if (request.candidates.max_single && *request.candidates.max_single < 0) {
    throw InputError(fmt::format("expected --max-single >= 0, got {}", *request.candidates.max_single));
  }
  if (request.candidates.reference_normal < 0) {
    throw InputError(fmt::format("expected --reference-normal >= 0, got {}", request.candidates.reference_normal));
  }
  if (request.policy.max_refinement < 1) {
    throw InputError(fmt::format("expected --max-refinement >= 1, got {}", request.policy.max_refinement));
  }
  if (request.jobs < 1) throw InputError(fmt::format("expected --jobs >= 1, got {}", request.jobs));
}

Selection run_selection(std::shared_ptr<const io::Case> input, const SelectionRequest& request,
                        const SelectionHooks& hooks) {
  check_request(request);
  if (!input->mechanism || input->mechanism->flexible_components.empty()) {
    throw InputError("expected a mechanism with at least one flexible body, got none",
                     SourceLocation{input->file, 0, 0});
  }
  SelectionInputs inputs{input, request.nonlinear_reference ? nonlinear_case(*input, request) : nullptr};
  std::filesystem::create_directories(request.root);
  const results::DirectoryLock lock(request.root);
  Selection selection;

  // Steps 1-3: normal modes only, then the ranking.
  const ModeSetCandidate normal{"normal", "normal modes only", normal_only(*input), false};
  if (hooks.on_set_start) hooks.on_set_start({1, 0, "normal", normal.description, 1.0});
  selection.runs.push_back(run_set(input, request, hooks, normal, "normal", true));
  if (hooks.on_set_done) hooks.on_set_done(selection.runs.front(), "");
  const CandidateRun& first = selection.runs.front();
  if (!first.ok()) {
    throw NumericalError("the normal-mode run failed, so there is nothing to rank: " + first.summary.message);
  }
  selection.ranking =
      rank_reactions(first.mechanism.model, first.reactions, first.indeterminate, request.rank_by, request.keep);
  if (hooks.on_ranking) hooks.on_ranking(selection.ranking);

  // Step 4: the other sets and the reference at half its step, then the comparison.
  CandidateOptions options = request.candidates;
  if (!options.max_single) options.max_single = request.target ? kMaxSingle : 0;
  std::vector<ModeSetCandidate> candidates = mode_set_candidates(*input, first.reduction, selection.ranking, options);
  if (request.nonlinear_reference) candidates = with_nonlinear_reference(std::move(candidates));
  // The ranking run's model lays out the nonlinear reference's columns; `runs` grows only after
  // every set has run, so it stays in place meanwhile.
  inputs.columns = &first.mechanism.model;
  HalfStepRuns half_step(request, hooks, candidates.size() + 1, candidates.size());
  run_sets(inputs, request, hooks, candidates, selection.runs, half_step);
  const CandidateRun& reference = selection.runs.back();
  const std::vector<KeyQuantity> keys =
      key_quantities(selection.ranking, reference.ok() ? reference : selection.runs.front());
  const std::filesystem::path folder = request.root / results::kSelectionFolder;
  write_ranking_csv(folder / results::kRankingFileName, selection.ranking);
  // A reference that failed or whose own accuracy check failed is refused: differences to it
  // mean nothing (the runs and the table stay).
  if (!reference.summary.accurate()) {
    write_comparison_csv(folder / results::kComparisonFileName, selection.runs, std::nullopt, request.root);
    selection.refusal = refusal(reference, request.policy.max_refinement, request.root);
    return selection;
  }
  selection.check = check_reference(reference, half_step);
  compare_runs(selection.runs, keys);
  selection.chosen = choose_run(selection.runs, request.target, request.norm);

  // Step 5: files for the user and the report.
  write_comparison_csv(folder / results::kComparisonFileName, selection.runs, selection.chosen, request.root);
  write_key_series_csv(folder / results::kKeySeriesFileName, selection.runs, keys);
  write_peaks_csv(folder / results::kEventPeaksFileName, selection.runs);
  if (selection.chosen) selection.fragment = write_choice(request, selection.runs[*selection.chosen]);
  return selection;
}

std::string percent(double fraction) {
  return std::isnan(fraction) ? std::string("-") : fmt::format("{:.3g} %", 100.0 * fraction);
}

std::string resolution(const StepChoice& step) {
  if (!std::isfinite(step.steps_per_period)) return "-";
  return fmt::format("{:.1f}{}", step.steps_per_period, step.resolved ? "" : " (not resolved)");
}

std::string step_text(const StepChoice& step) {
  if (step.window == 0.0) return fmt::format("step {:.3g} s", step.step);
  return fmt::format("step {:.3g} s in the {:g} s event windows ({:.3g} s between)", step.step, step.window,
                     step.outside_step);
}

}  // namespace limber::select
