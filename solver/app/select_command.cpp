// `limber select`: the seed paper's procedure for choosing the modes of flexible bodies (its
// Fig. 2) as one command (docs/select.md): run with normal modes only, rank the joint
// reactions on the flexible bodies, keep the large ones as boundary conditions for static
// modes, run the mode sets that follow (its Fig. 6) and name the one to use.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/command.h"
#include "app/json_text.h"
#include "app/run_progress.h"
#include "app/settings_overrides.h"
#include "app/stop_signal.h"
#include "core/error.h"
#include "io/case_reader.h"
#include "results/directory_lock.h"
#include "results/results_writer.h"
#include "select/mode_set_candidates.h"
#include "select/reaction_ranking.h"
#include "select/selection_files.h"
#include "select/selection_study.h"
#include "results/file_names.h"
#include "results/results_layout.h"

namespace limber::app {

namespace {

struct SelectOptions {
  std::string case_file;
  std::string output_dir;
  double keep = 0.1;
  std::optional<double> target;
  std::string rank_by = "peak";
  std::string norm = "event";
  std::string static_kind = "attachment";
  int max_single = 6;
  int reference_normal = 0;
  bool keep_step = false;
  bool whole_run = false;
  int max_refinement = 8;
  int jobs = 2;
  SettingsOverrides overrides;
  bool json = false;
};

// Ranking rows printed (the rest are in ranking.csv): every kept one and this many more.
constexpr std::size_t kExtraRankingRows = 4;

// A mode set's name as a folder name: letters, digits, '.', '+', '-', '_' kept.
std::string folder_name(const std::string& name) {
  std::string folder;
  for (char c : name) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-' || c == '_';
    folder += plain ? c : '_';
  }
  return folder;
}

std::string percent(double fraction) {
  return std::isnan(fraction) ? std::string("-") : fmt::format("{:.3g} %", 100.0 * fraction);
}

void print_ranking(std::FILE* out, const std::vector<select::RankedComponent>& ranking, double keep,
                   const std::string& rank_by) {
  fmt::print(out, "\nreaction components on the flexible bodies (body axes), by {}; kept: >= {:g} of "
                  "the body's largest (torques as T/L):\n", rank_by, keep);
  fmt::print(out, "  {:<14} {:<10} {:>6} {:<9} {:>12} {:>12} {:>9}  {}\n", "component", "body", "node",
             "quantity", "peak", "rms", "relative", "");
  std::size_t shown = 0, kept = 0;
  for (const select::RankedComponent& c : ranking) kept += c.kept ? 1 : 0;
  for (const select::RankedComponent& c : ranking) {
    if (shown >= kept + kExtraRankingRows) break;
    ++shown;
    const char* unit = c.load == select::Load::kForce ? "N" : "N m";
    fmt::print(out, "  {:<14} {:<10} {:>6} {:<9} {:>10.4g} {:<3}{:>10.4g} {:<3}{:>7.4f}  {}{}\n", c.label(), c.body,
               c.node_id, c.load == select::Load::kForce ? "force" : "torque", c.peak, unit, c.rms, unit,
               c.relative, c.kept ? "kept" : "", c.indeterminate ? " (indeterminate)" : "");
  }
  if (shown < ranking.size()) fmt::print(out, "  ... {} more in selection/ranking.csv\n", ranking.size() - shown);
}

// "20.0" steps per period, or "20.0 (not resolved)".
std::string resolution(const select::StepChoice& step) {
  if (!std::isfinite(step.steps_per_period)) return "-";
  return fmt::format("{:.1f}{}", step.steps_per_period, step.resolved ? "" : " (not resolved)");
}

// "step 6.25e-05 s", or "step 6.25e-05 s in the 0.3 s event windows (5e-04 s between)".
std::string step_text(const select::StepChoice& step) {
  if (step.window == 0.0) return fmt::format("step {:.3g} s", step.step);
  return fmt::format("step {:.3g} s in the {:g} s event windows ({:.3g} s between)", step.step, step.window,
                     step.outside_step);
}

void print_comparison(std::FILE* out, const std::vector<select::CandidateRun>& runs,
                      std::optional<std::size_t> chosen) {
  fmt::print(out, "\nmode sets against 'reference' (event: largest event-peak difference; peak, rms: sample by "
                  "sample, largest over the key quantities; steps per period at f_max, {} needed):\n",
             select::kStepsPerPeriod);
  fmt::print(out, "  {:<22} {:>5} {:>9} {:>10} {:>22} {:>9} {:>9} {:>10} {:>10}  {}\n", "set", "modes", "f_max",
             "step", "steps/period", "run", "event", "peak", "rms", "");
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const select::CandidateRun& run = runs[k];
    const std::string role = run.candidate.reference ? "reference" : (chosen && *chosen == k ? "chosen" : "");
    fmt::print(out, "  {:<22} {:>5} {:>6.0f} Hz {:>10.3g} {:>22} {:>7.2f} s {:>9} {:>10} {:>10}  {}{}\n",
               run.candidate.name, run.modes, run.step.f_max, run.step.step, resolution(run.step),
               run.summary.wall_seconds, percent(run.peaks.error), percent(run.error_peak), percent(run.error_rms),
               role, run.status() == results::layout::status::kOk ? "" : " " + run.status());
  }
}

// Per window and joint: the reference's peak |F| and |T|, and every set's difference to them.
void print_peak_table(std::FILE* out, const std::vector<select::CandidateRun>& runs) {
  const auto reference = std::find_if(runs.begin(), runs.end(), [](const auto& r) { return r.candidate.reference; });
  if (reference == runs.end() || reference->summary.peaks.windows.empty()) return;
  fmt::print(out, "\nevent peaks (largest |F| and |T| at every step, {:g} s after each event): reference, then each "
                  "set's difference F / T\n  {:<22} {:<8} {:>10} {:>10}",
             reference->summary.peaks.window, "window", "joint", "F [N]", "T [N m]");
  for (const select::CandidateRun& run : runs) {
    if (!run.candidate.reference) fmt::print(out, " {:>17}", run.candidate.name.substr(0, 17));
  }
  fmt::print(out, "\n");
  // The reference against itself: its own peaks, one row per window and joint.
  const select::PeakComparison own = select::compare_peaks(reference->summary.peaks, reference->summary.peaks);
  for (const select::PeakDifference& row : own.rows) {
    fmt::print(out, "  {:<22} {:<8} {:>10.4g} {:>10.4g}", row.window.substr(0, 22), row.joint, row.reference_force,
               row.reference_torque);
    for (const select::CandidateRun& run : runs) {
      if (run.candidate.reference) continue;
      const auto mine = std::find_if(run.peaks.rows.begin(), run.peaks.rows.end(), [&](const auto& r) {
        return r.window == row.window && r.joint == row.joint;
      });
      const std::string cell = mine == run.peaks.rows.end()
                                   ? "-"
                                   : fmt::format("{} / {}", percent(mine->force_error), percent(mine->torque_error));
      fmt::print(out, " {:>17}", cell);
    }
    fmt::print(out, "\n");
  }
}

std::string json_ranking(const std::vector<select::RankedComponent>& ranking) {
  std::string text = "[";
  for (std::size_t k = 0; k < ranking.size(); ++k) {
    const select::RankedComponent& c = ranking[k];
    text += fmt::format(
        "{}{{\"component\": {}, \"body\": {}, \"joint\": {}, \"node\": {}, \"quantity\": {}, \"axis\": {}, "
        "\"peak\": {}, \"rms\": {}, \"relative\": {}, \"kept\": {}, \"indeterminate\": {}}}",
        k ? ", " : "", json_string(c.label()), json_string(c.body), json_string(c.joint), c.node_id,
        json_string(c.load == select::Load::kForce ? "force" : "torque"), json_string(std::string(1, "xyz"[c.axis])),
        json_number(c.peak), json_number(c.rms), json_number(c.relative), c.kept ? "true" : "false",
        c.indeterminate ? "true" : "false");
  }
  return text + "]";
}

// A set's event peaks against the reference's, one object per window and joint.
std::string json_peak_rows(const select::PeakComparison& peaks) {
  std::string text = "[";
  for (std::size_t k = 0; k < peaks.rows.size(); ++k) {
    const select::PeakDifference& r = peaks.rows[k];
    text += fmt::format("{}{{\"window\": {}, \"joint\": {}, \"start\": {}, \"reference_start\": {}, \"force\": {}, "
                        "\"reference_force\": {}, \"force_error\": {}, \"torque\": {}, \"reference_torque\": {}, "
                        "\"torque_error\": {}}}",
                        k ? ", " : "", json_string(r.window), json_string(r.joint), json_number(r.start),
                        json_number(r.reference_start), json_number(r.force), json_number(r.reference_force),
                        json_number(r.force_error), json_number(r.torque), json_number(r.reference_torque),
                        json_number(r.torque_error));
  }
  return text + "]";
}

std::string json_comparison(const std::vector<select::CandidateRun>& runs, const std::filesystem::path& root) {
  std::string text = "[";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const select::CandidateRun& run = runs[k];
    text += fmt::format(
        "{}{{\"set\": {}, \"description\": {}, \"modes\": {}, \"reduction_s\": {}, \"run_s\": {}, "
        "\"status\": {}, \"message\": {}, \"f_max_hz\": {}, \"step\": {}, \"event_window\": {}, "
        "\"step_between_windows\": {}, \"steps_per_period\": {}, "
        "\"resolved\": {}, \"error_event\": {}, \"worst_event\": {}, \"error_peak\": {}, \"error_rms\": {}, "
        "\"worst_quantity\": {}, \"event_peaks\": {}, \"directory\": {}}}",
        k ? ", " : "", json_string(run.candidate.name), json_string(run.candidate.description), run.modes,
        json_number(run.reduction_seconds), json_number(run.summary.wall_seconds),
        json_string(run.status().substr(0, run.status().find(':'))), json_string(run.summary.message),
        json_number(run.step.f_max), json_number(run.step.step), json_number(run.step.window),
        json_number(run.step.window > 0.0 ? run.step.outside_step : run.step.step),
        json_number(run.step.steps_per_period),
        run.step.resolved ? "true" : "false", json_number(run.peaks.error), json_string(run.peaks.worst),
        json_number(run.error_peak), json_number(run.error_rms), json_string(run.worst_quantity),
        json_peak_rows(run.peaks), json_string(run.directory.lexically_relative(root).generic_string()));
  }
  return text + "]";
}

// What every set's run shares, and its lines on the terminal (runs on two threads print whole
// lines under one lock).
struct SetRunner {
  std::shared_ptr<const io::Case> input;
  select::SettingsAdjustment adjust;
  select::StepPolicy policy;
  std::filesystem::path root;
  std::FILE* text = nullptr;
  double t_end = 0.0;
  std::mutex print_lock;

  // One set into DIR/runs/<folder>, its step scaled by `scale`; `progress_line` draws the
  // progress of a run that has the terminal to itself.
  select::CandidateRun run(const select::ModeSetCandidate& candidate, const std::string& folder, double scale,
                           bool progress_line) {
    select::StepPolicy scaled = policy;
    scaled.scale = scale;
    std::optional<RunProgress> progress;
    select::CandidateRun outcome = select::run_candidate(
        input, candidate, adjust, scaled, root / results::kRunsFolder / folder_name(folder),
        [&](const integrate::Sample& sample) {
          if (progress_line) {
            if (!progress) progress.emplace(t_end, true);
            progress->update(sample.t, sample.statistics.steps);
          }
          if (StopSignals::received() != 0) throw select::SelectionInterrupted{};
        });
    progress.reset();
    return outcome;
  }

  void print(const std::string& line) {
    const std::lock_guard lock(print_lock);
    fmt::print(text, "{}", line);
    std::fflush(text);
  }

  // A finished set: its notices, modes, step and cost.
  void print_outcome(const select::CandidateRun& run, const std::string& name = "") {
    std::string lines;
    for (const std::string& notice : run.notices) lines += fmt::format("      notice: {}\n", notice);
    lines += fmt::format("      {}{} modes, f_max {:.0f} Hz, {}, steps per period {}, reduction {:.3f} s, "
                         "run {:.3f} s{}\n",
                         name.empty() ? "" : name + ": ", run.modes, run.step.f_max, step_text(run.step),
                         resolution(run.step), run.reduction_seconds, run.summary.wall_seconds,
                         run.status() == results::layout::status::kOk ? "" : ", " + run.status());
    print(lines);
  }
};

// The sets after `normal` (candidates[0]) and the reference at half its step, `jobs` at a
// time, the longest first (the reference, then its twin); appended to `runs` in the candidates'
// order. Returns the halved-step reference run.
std::optional<select::CandidateRun> run_sets(SetRunner& runner, const std::vector<select::ModeSetCandidate>& candidates,
                                             int jobs, std::vector<select::CandidateRun>& runs) {
  struct Job {
    std::size_t candidate;
    std::string folder;
    double scale;
  };
  std::vector<Job> order;
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    if (candidates[k].reference) {
      order.insert(order.begin(), {{k, candidates[k].name, 1.0}, {k, candidates[k].name + "_half_step", 0.5}});
    } else {
      order.push_back({k, candidates[k].name, 1.0});
    }
  }
  std::vector<std::optional<select::CandidateRun>> done(order.size());
  select::run_parallel(order.size(), jobs, [&](std::size_t j) {
    const select::ModeSetCandidate& candidate = candidates[order[j].candidate];
    runner.print(fmt::format("[{}/{}] {}: {}{}\n", j + 2, order.size() + 1, order[j].folder, candidate.description,
                             order[j].scale == 1.0 ? "" : " (at half its step: the reference's check)"));
    done[j] = runner.run(candidate, order[j].folder, order[j].scale, jobs <= 1);
    runner.print_outcome(*done[j], order[j].folder);
  });
  std::optional<select::CandidateRun> half_step;
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    for (std::size_t j = 0; j < order.size(); ++j) {
      if (order[j].candidate != k) continue;
      if (order[j].scale == 1.0) runs.push_back(std::move(*done[j]));
      else half_step = std::move(done[j]);
    }
  }
  return half_step;
}

// Why a reference is refused, and what to change.
std::string refusal(const select::CandidateRun& reference, int max_refinement, const std::filesystem::path& root) {
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

// The reference's convergence in the step: its event peaks at half its step.
struct ReferenceCheck {
  double step = 0.0, half_step = 0.0;  // [s]
  std::string half_step_status;        // the halved-step run's status
  select::PeakComparison change;       // its event peaks against the reference's
  bool converged = false;              // finished and every compared peak moved < kConvergedChange
};
constexpr double kConvergedChange = 0.03;

ReferenceCheck check_reference(const select::CandidateRun& reference, const select::CandidateRun& half_step) {
  ReferenceCheck check{reference.step.step, half_step.step.step, half_step.status(), {}, false};
  if (!half_step.ok()) return check;
  check.change = select::compare_peaks(half_step.summary.peaks, reference.summary.peaks,
                                       select::joint_release_times(reference.mechanism.model));
  check.converged = check.change.error < kConvergedChange;
  return check;
}

void print_reference_check(std::FILE* out, const ReferenceCheck& check) {
  if (check.change.rows.empty() && check.change.unmatched.empty()) {
    fmt::print(out, "\nreference check: the run at half its step ({:.3g} s) did not finish ({}): the reference's "
                    "convergence in the step is NOT checked\n", check.half_step, check.half_step_status);
    return;
  }
  fmt::print(out, "\nreference check: at half its step ({:.3g} s instead of {:.3g} s) its event peaks change by up "
                  "to {} ({}): {}\n", check.half_step, check.step, percent(check.change.error), check.change.worst,
             check.converged ? fmt::format("converged in the step (< {:g} %)", 100 * kConvergedChange)
                             : fmt::format("NOT converged in the step (>= {:g} %): differences to it below that "
                                           "are not measured", 100 * kConvergedChange));
}

std::string json_reference_check(const ReferenceCheck& check) {
  return fmt::format("{{\"step\": {}, \"half_step\": {}, \"half_step_status\": {}, \"peak_change\": {}, "
                     "\"worst\": {}, \"threshold\": {}, \"converged\": {}}}",
                     json_number(check.step), json_number(check.half_step),
                     json_string(check.half_step_status.substr(0, check.half_step_status.find(':'))),
                     json_number(check.change.error), json_string(check.change.worst), json_number(kConvergedChange),
                     check.converged ? "true" : "false");
}

// The chosen set's fragment and results, or a warning that none meets the target. Returns the
// fragment ("" when none).
std::string write_choice(std::FILE* text, const SelectOptions& options, const std::vector<select::CandidateRun>& runs,
                         std::optional<std::size_t> chosen, select::ErrorNorm norm, const std::filesystem::path& root) {
  if (!chosen) {
    fmt::print(stderr, "limber: warning: no mode set meets the target {:g} ({} error, own accuracy check passed, "
                       "step resolving its modes); the most accurate one short of the reference is in the table "
                       "above\n", options.target.value_or(0.0), options.norm);
    return "";
  }
  const select::CandidateRun& run = runs[*chosen];
  const std::string why =
      options.target ? fmt::format("The fewest modes whose {} error against 'reference' is at most {:g} ({}).",
                                   options.norm, *options.target, percent(run.error(norm)))
                     : fmt::format("The procedure's answer: static modes where the reactions are large ({} {} "
                                   "error against 'reference').", percent(run.error(norm)), options.norm);
  const std::string fragment = select::selected_modes_yaml(run, why);
  std::ofstream(root / "selected_modes.yaml", std::ios::binary) << fragment;
  std::filesystem::copy_file(run.directory / results::kResultsFileName, root / results::kResultsFileName,
                             std::filesystem::copy_options::overwrite_existing);
  fmt::print(text, "\nchosen: '{}' ({} modes); its results copied to {}; its modes, to paste into the case ({}):\n{}",
             run.candidate.name, run.modes, (root / results::kResultsFileName).string(),
             (root / "selected_modes.yaml").string(), fragment);
  return fragment;
}

// Throws InputError for an option out of range.
void check_options(const SelectOptions& options) {
  if (!(options.keep > 0.0 && options.keep <= 1.0)) {
    throw InputError(fmt::format("expected --keep in (0, 1], got {:g}", options.keep));
  }
  if (options.target && !(*options.target > 0.0)) {
    throw InputError(fmt::format("expected --target > 0 (a fraction, 0.02 = 2 %), got {:g}", *options.target));
  }
  if (options.max_single < 0) throw InputError(fmt::format("expected --max-single >= 0, got {}", options.max_single));
  if (options.reference_normal < 0) {
    throw InputError(fmt::format("expected --reference-normal >= 0, got {}", options.reference_normal));
  }
  if (options.max_refinement < 1) {
    throw InputError(fmt::format("expected --max-refinement >= 1, got {}", options.max_refinement));
  }
  if (options.jobs < 1) throw InputError(fmt::format("expected --jobs >= 1, got {}", options.jobs));
}

int select_case(const SelectOptions& options) {
  check_options(options);
  const auto shared_input = std::make_shared<const io::Case>(io::read_case_file(options.case_file));
  const io::Case& input = *shared_input;
  if (!input.mechanism || input.mechanism->flexible_components.empty()) {
    throw InputError("expected a mechanism with at least one flexible body, got none",
                     SourceLocation{options.case_file, 0, 0});
  }
  const select::RankBy rank_by = options.rank_by == "rms" ? select::RankBy::kRms : select::RankBy::kPeak;
  const select::ErrorNorm norm = options.norm == "rms"    ? select::ErrorNorm::kRms
                                : options.norm == "peak" ? select::ErrorNorm::kPeak
                                                         : select::ErrorNorm::kEvent;
  select::CandidateOptions candidate_options;
  candidate_options.static_kind =
      options.static_kind == "constraint" ? select::StaticModeKind::kConstraint : select::StaticModeKind::kAttachment;
  candidate_options.max_single = options.max_single;
  candidate_options.reference_normal = options.reference_normal;

  std::FILE* text = options.json ? stderr : stdout;
  const std::filesystem::path root =
      options.output_dir.empty()
          ? std::filesystem::path("out") / (std::filesystem::path(options.case_file).stem().string() + "_select")
          : std::filesystem::path(options.output_dir);
  std::filesystem::create_directories(root);
  const results::DirectoryLock lock(root);
  fmt::print(text, "limber select: {} ({})\n", input.title, input.file);

  // Every set's run: the case's settings with the command line's, at the step that resolves
  // the set's highest frequency; a signal stops the selection at the next sample.
  const StopSignals stop_signals;
  SetRunner runner{shared_input,
                   [&](const io::RunSettings& settings) { return options.overrides.apply(settings); },
                   {options.keep_step, options.max_refinement, 1.0, options.whole_run},
                   root,
                   text,
                   options.overrides.apply(input.mechanism->run).t_end,
                   {}};

  try {
    // Steps 1-3: normal modes only, then the ranking.
    select::ModeSetCandidate normal{"normal", "normal modes only", select::normal_only(input), false};
    std::vector<select::CandidateRun> runs;
    fmt::print(text, "[1] normal: {}\n", normal.description);
    std::fflush(text);
    runs.push_back(runner.run(normal, "normal", 1.0, true));
    runner.print_outcome(runs.front());
    if (!runs.front().ok()) {
      throw NumericalError("the normal-mode run failed, so there is nothing to rank: " +
                           runs.front().summary.message);
    }
    const std::vector<select::RankedComponent> ranking = select::rank_reactions(
        runs.front().mechanism.model, runs.front().reactions, runs.front().indeterminate, rank_by,
        options.keep);
    print_ranking(text, ranking, options.keep, options.rank_by);

    // Step 4: the other sets and the reference at half its step, then the comparison.
    const std::vector<select::ModeSetCandidate> candidates =
        select::mode_set_candidates(input, runs.front().reduction, ranking, candidate_options);
    fmt::print(text, "\n");
    std::optional<select::CandidateRun> half_step = run_sets(runner, candidates, options.jobs, runs);
    const select::CandidateRun& reference = runs.back();
    const std::vector<select::KeyQuantity> keys = select::key_quantities(ranking, reference.ok() ? reference : runs.front());
    const std::filesystem::path folder = root / results::kSelectionFolder;
    select::write_ranking_csv(folder / results::kRankingFileName, ranking);
    // A reference that failed or whose own accuracy check failed is refused: differences to it
    // mean nothing (the runs and the table stay).
    if (!reference.summary.accurate()) {
      print_comparison(text, runs, std::nullopt);
      select::write_comparison_csv(folder / results::kComparisonFileName, runs, std::nullopt, root);
      throw NumericalError(refusal(reference, options.max_refinement, root));
    }
    const ReferenceCheck check = check_reference(reference, *half_step);
    select::compare_runs(runs, keys);
    const std::optional<std::size_t> chosen = select::choose_run(runs, options.target, norm);
    print_comparison(text, runs, chosen);
    print_peak_table(text, runs);
    print_reference_check(text, check);

    // Step 5: files for the user and the report.
    select::write_comparison_csv(folder / results::kComparisonFileName, runs, chosen, root);
    select::write_key_series_csv(folder / results::kKeySeriesFileName, runs, keys);
    select::write_peaks_csv(folder / results::kEventPeaksFileName, runs);
    const std::string fragment = write_choice(text, options, runs, chosen, norm, root);
    fmt::print(text, "wrote {}\n", folder.string());
    if (options.json) {
      fmt::print(stdout, "{{\"status\": \"ok\", \"ranking\": {}, \"comparison\": {}, \"reference_check\": {}, "
                         "\"chosen\": {}, \"target\": {}, \"target_met\": {}, \"norm\": {}, "
                         "\"steps_per_period_needed\": {}, \"fragment\": {}, \"directory\": {}}}\n",
                 json_ranking(ranking), json_comparison(runs, root), json_reference_check(check),
                 chosen ? json_string(runs[*chosen].candidate.name) : std::string("null"),
                 options.target ? json_number(*options.target) : std::string("null"),
                 chosen ? "true" : "false", json_string(options.norm), select::kStepsPerPeriod,
                 json_string(fragment), json_string(root.string()));
    }
  } catch (const select::SelectionInterrupted&) {
    fmt::print(stderr, "limber: selection interrupted by signal {} (finished runs kept in {})\n",
               StopSignals::received(), (root / results::kRunsFolder).string());
    return kExitInterrupted;
  }
  return kExitOk;
}

}  // namespace

Command add_select_command(CLI::App& app) {
  auto options = std::make_shared<SelectOptions>();
  CLI::App* cli = app.add_subcommand(
      "select", "Choose the modes by the seed paper's procedure, compare mode sets");
  cli->footer(
      "Runs the case with normal modes only on every flexible body; ranks every joint-reaction\n"
      "component acting on a flexible body (peak and rms, in the body's own axes); keeps those at\n"
      "or above --keep of the body's largest as boundary conditions for static modes; then runs\n"
      "and compares the mode sets: normal only, each kept component alone, all kept together,\n"
      "as many normal modes as that, and a reference (--reference-normal normal modes plus every\n"
      "kept static mode). Each set runs at a step that resolves its highest natural frequency\n"
      "f_max (20 steps per period; generalized-alpha's step, IDA's max_step), at most\n"
      "--max-refinement times shorter than the case's (longer: marked 'not resolved'); with\n"
      "generalized-alpha only in the event windows (--peak-window after the start and after\n"
      "every event), the case's step between them (--whole-run: throughout);\n"
      "--keep-step runs every set at the case's step. Sets run --jobs at a time, with the\n"
      "reference a second time at half its step: a reference whose own accuracy check fails is\n"
      "refused, and the change of its event peaks at half the step is reported (< 3 %: converged).\n"
      "Errors: event peaks (per joint, the largest force and torque at every step in --peak-window\n"
      "after the start and each latch engagement, against the reference's) and, sample by sample,\n"
      "the kept reactions and the deflection probes. Without --target the answer is 'kept' (the\n"
      "procedure's); with it, the set with the fewest modes whose --norm error is at most the\n"
      "target, whose own accuracy check passed and whose step resolves its modes.\n"
      "Writes DIR/runs/<set>/results.h5 for every set, DIR/selection/{ranking,comparison,\n"
      "key_series,event_peaks}.csv, DIR/selected_modes.yaml (the chosen modes, to paste into the case) and\n"
      "DIR/results.h5 (the chosen set's run), so that 'limber report DIR' shows the ranking,\n"
      "the comparison and the key quantities of every set (docs/select.md).\n"
      "Exit codes: 0 done (also when no set meets --target: a warning says so, and --json's\n"
      "target_met is false), 1 bad input, 2 the normal-mode run failed or the reference is refused,\n"
      "3 internal error,\n"
      "4 interrupted by SIGINT or SIGTERM (finished runs are kept).");
  cli->add_option("case", options->case_file, "Case file (YAML, docs/case-format.md)")->required();
  cli->add_option("-o,--output", options->output_dir,
                  "Output directory (default: out/<case file stem>_select)");
  cli->add_option("--keep", options->keep,
                  "Keep components at or above this fraction of the body's largest (0 < F <= 1)")
      ->capture_default_str();
  cli->add_option("--target", options->target,
                  "Error target as a fraction (0.02 = 2 %): choose the fewest modes that meet it");
  cli->add_option("--rank-by", options->rank_by, "Rank by the peak or the rms over the run")
      ->check(CLI::IsMember({"peak", "rms"}))
      ->capture_default_str();
  cli->add_option("--norm", options->norm,
                  "Error measure for --target: event (event peaks), peak or rms (sample by sample; relative)")
      ->check(CLI::IsMember({"event", "peak", "rms"}))
      ->capture_default_str();
  cli->add_option("--static-modes", options->static_kind,
                  "attachment (unit loads; inertia relief on free-free bodies) or constraint (unit "
                  "displacements; rigid, and dropped, where the body is otherwise free)")
      ->check(CLI::IsMember({"attachment", "constraint"}))
      ->capture_default_str();
  cli->add_option("--max-single", options->max_single,
                  "At most this many one-component sets (the largest kept first)")
      ->capture_default_str();
  cli->add_option("--reference-normal", options->reference_normal,
                  "Normal modes per body in the reference set (0: four times the case's)")
      ->capture_default_str();
  cli->add_flag("--keep-step", options->keep_step,
                "Run every set at the case's step (or --step) instead of one resolving its highest frequency");
  cli->add_flag("--whole-run", options->whole_run,
                "Generalized-alpha: each set's step throughout the run, not only in the event windows "
                "(--peak-window after the start and after every event) with the case's step between");
  cli->add_option("--max-refinement", options->max_refinement,
                  "A set's step is at least the case's divided by this (IDA: the sample interval's)")
      ->capture_default_str();
  cli->add_option("--jobs", options->jobs, "Sets run at a time (threads)")->capture_default_str();
  options->overrides.add_options(*cli);
  cli->add_flag("--json", options->json,
                "Print one JSON object on stdout: {\"status\", \"ranking\": [{\"component\", \"body\", "
                "\"joint\", \"node\", \"quantity\", \"axis\", \"peak\", \"rms\", \"relative\", \"kept\", "
                "\"indeterminate\"}], \"comparison\": [{\"set\", \"description\", \"modes\", \"reduction_s\", "
                "\"run_s\", \"status\", \"message\", \"f_max_hz\", \"step\", \"event_window\", "
                "\"step_between_windows\", \"steps_per_period\", \"resolved\", "
                "\"error_event\", \"worst_event\", \"error_peak\", \"error_rms\", \"worst_quantity\", "
                "\"event_peaks\": [{\"window\", \"joint\", \"start\", \"reference_start\", \"force\", "
                "\"reference_force\", \"force_error\", \"torque\", \"reference_torque\", \"torque_error\"}], "
                "\"directory\"}], \"reference_check\": {\"step\", \"half_step\", \"half_step_status\", "
                "\"peak_change\", \"worst\", \"threshold\", \"converged\"}, \"chosen\", \"target\", \"target_met\", "
                "\"norm\", \"steps_per_period_needed\", \"fragment\", \"directory\"}; the text goes to stderr");
  return {cli, [options] { return select_case(*options); }};
}

}  // namespace limber::app
