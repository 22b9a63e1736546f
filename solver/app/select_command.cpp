// `limber select`: the seed paper's procedure for choosing the modes of flexible bodies (its
// Fig. 2) as one command (docs/select.md): run with normal modes only, rank the joint
// reactions on the flexible bodies, keep the large ones as boundary conditions for static
// modes, run the mode sets that follow (its Fig. 6) and name the one to use.
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/command.h"
#include "app/run_progress.h"
#include "app/settings_overrides.h"
#include "app/stop_signal.h"
#include "core/error.h"
#include "io/case_reader.h"
#include "io/formulation_override.h"
#include "select/selection_json.h"
#include "select/selection_procedure.h"
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
  std::optional<int> max_single;
  int reference_normal = 0;
  std::string reference = "modal";
  bool keep_step = false;
  bool whole_run = false;
  int max_refinement = 8;
  int jobs = 2;
  SettingsOverrides overrides;
  bool json = false;
};

using select::percent;
using select::resolution;

// Ranking rows printed (the rest are in ranking.csv): every kept one and this many more.
constexpr std::size_t kExtraRankingRows = 4;

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

void print_reference_check(std::FILE* out, const select::ReferenceCheck& check) {
  if (check.change.rows.empty() && check.change.unmatched.empty()) {
    fmt::print(out, "\nreference check: the run at half its step ({:.3g} s) did not finish ({}): the reference's "
                    "convergence in the step is NOT checked\n", check.half_step, check.half_step_status);
    return;
  }
  fmt::print(out, "\nreference check: at half its step ({:.3g} s instead of {:.3g} s; its event windows re-run in {} "
                  "stretch(es) from its own state) its event peaks change by up to {} ({}): {}\n", check.half_step,
             check.step, check.windows_rerun, percent(check.change.error), check.change.worst,
             check.converged ? fmt::format("converged in the step (< {:g} %)", 100 * select::kConvergedChange)
                             : fmt::format("NOT converged in the step (>= {:g} %): differences to it below that "
                                           "are not measured", 100 * select::kConvergedChange));
}

// The request `limber select`'s options make.
select::SelectionRequest request_of(const SelectOptions& options) {
  select::SelectionRequest request;
  request.root = options.output_dir.empty()
                     ? std::filesystem::path("out") /
                           (std::filesystem::path(options.case_file).stem().string() + "_select")
                     : std::filesystem::path(options.output_dir);
  request.keep = options.keep;
  request.target = options.target;
  request.rank_by = select::rank_by_from(options.rank_by);
  request.norm = select::error_norm_from(options.norm);
  request.candidates.static_kind = select::static_kind_from(options.static_kind);
  request.candidates.max_single = options.max_single;
  request.candidates.reference_normal = options.reference_normal;
  request.nonlinear_reference = io::nonlinear_formulation_requested(options.reference, "--reference");
  request.policy = {options.keep_step, options.max_refinement, 1.0, options.whole_run};
  request.jobs = options.jobs;
  request.adjust = [overrides = options.overrides](const io::RunSettings& settings) {
    return overrides.apply(settings);
  };
  return request;
}

// A finished set: its notices, modes, step and cost.
std::string outcome_lines(const select::CandidateRun& run, const std::string& name) {
  std::string lines;
  for (const std::string& notice : run.notices) lines += fmt::format("      notice: {}\n", notice);
  lines += fmt::format("      {}{} modes, f_max {:.0f} Hz, {}, steps per period {}, reduction {:.3f} s, "
                       "run {:.3f} s (CPU {:.2f} s){}\n",
                       name.empty() ? "" : name + ": ", run.modes, run.step.f_max, select::step_text(run.step),
                       select::resolution(run.step), run.reduction_seconds, run.summary.wall_seconds, run.cpu_seconds,
                       run.status() == results::layout::status::kOk ? "" : ", " + run.status());
  return lines;
}

int select_case(const SelectOptions& options) {
  const select::SelectionRequest request = request_of(options);
  select::check_request(request);
  const auto input = std::make_shared<const io::Case>(io::read_case_file(options.case_file));
  std::FILE* text = options.json ? stderr : stdout;
  fmt::print(text, "limber select: {} ({})\n", input->title, input->file);

  // Each set's lines as it starts and ends (whole lines under one lock: sets run on several
  // threads), the progress line of a run that has the terminal to itself; a signal stops the
  // selection at the next sample.
  const StopSignals stop_signals;
  const double t_end = input->mechanism ? options.overrides.apply(input->mechanism->run).t_end : 0.0;
  std::mutex print_lock;
  const auto print = [&](const std::string& lines) {
    const std::lock_guard guard(print_lock);
    fmt::print(text, "{}", lines);
    std::fflush(text);
  };
  std::optional<RunProgress> progress;
  select::SelectionHooks hooks;
  hooks.on_set_start = [&](const select::SetStart& set) {
    print(set.count == 0 ? fmt::format("[{}] {}: {}\n", set.number, set.folder, set.description)
                         : fmt::format("[{}/{}] {}: {}{}\n", set.number, set.count, set.folder, set.description,
                                       set.scale == 1.0 ? "" : " (at half its step: the reference's check)"));
  };
  hooks.on_sample = [&](const integrate::Sample& sample, bool alone) {
    if (alone) {
      if (!progress) progress.emplace(t_end, true);
      progress->update(sample.t, sample.statistics.steps);
    }
    if (StopSignals::received() != 0) throw select::SelectionInterrupted{};
  };
  hooks.on_set_done = [&](const select::CandidateRun& run, const std::string& label) {
    progress.reset();
    print(outcome_lines(run, label));
  };
  hooks.on_ranking = [&](const std::vector<select::RankedComponent>& ranking) {
    print_ranking(text, ranking, options.keep, options.rank_by);
    fmt::print(text, "\n");
  };

  try {
    const select::Selection selection = select::run_selection(input, request, hooks);
    if (!selection.refusal.empty()) {
      print_comparison(text, selection.runs, std::nullopt);
      throw NumericalError(selection.refusal);
    }
    print_comparison(text, selection.runs, selection.chosen);
    print_peak_table(text, selection.runs);
    print_reference_check(text, selection.check);
    if (selection.chosen) {
      const select::CandidateRun& run = selection.runs[*selection.chosen];
      fmt::print(text, "\nchosen: '{}' ({} modes); its results copied to {}; its modes, to paste into the case ({}):\n{}",
                 run.candidate.name, run.modes, (request.root / results::kResultsFileName).string(),
                 (request.root / "selected_modes.yaml").string(), selection.fragment);
    } else {
      fmt::print(stderr, "limber: warning: no mode set meets the target {:g} ({} error, own accuracy check passed, "
                         "step resolving its modes); the most accurate one short of the reference is in the table "
                         "above\n", options.target.value_or(0.0), options.norm);
    }
    fmt::print(text, "wrote {}\n", (request.root / results::kSelectionFolder).string());
    if (options.json) fmt::print(stdout, "{}\n", select::selection_json(selection, request));
  } catch (const select::SelectionInterrupted&) {
    progress.reset();
    fmt::print(stderr, "limber: selection interrupted by signal {} (finished runs kept in {})\n",
               StopSignals::received(), (request.root / results::kRunsFolder).string());
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
      "and compares the mode sets: normal only, each kept component alone (with --target, or\n"
      "--max-single), all kept together, as many normal modes as that, and a reference\n"
      "(--reference-normal normal modes plus every kept static mode; with --reference nonlinear\n"
      "that set is 'richest', and the reference is the case with every flexible body nonlinear,\n"
      "generalized-alpha at the case's step). Each set runs at a step that resolves its highest\n"
      "natural frequency f_max (20 steps per period; generalized-alpha's step, IDA's max_step),\n"
      "at most --max-refinement times shorter than the case's (longer: marked 'not resolved'); with\n"
      "generalized-alpha only in the event windows (--peak-window after the start and after\n"
      "every event), the case's step between them (--whole-run: throughout);\n"
      "--keep-step runs every set at the case's step. Sets run --jobs at a time, the reference\n"
      "first: a reference whose own accuracy check fails is refused; its event windows run again\n"
      "at half its step, each from the reference's own state before its event and as soon as\n"
      "the reference has run past it, and the change of its event peaks is reported (< 3 %:\n"
      "converged).\n"
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
                  "At most this many one-component sets (the largest kept first; default: 6 with --target, "
                  "where each can be the answer, 0 without)");
  cli->add_option("--reference-normal", options->reference_normal,
                  "Normal modes per body in the reference set (0: four times the case's)")
      ->capture_default_str();
  cli->add_option("--reference", options->reference,
                  "modal (the richest modal set) or nonlinear (the case with every flexible body nonlinear: "
                  "co-rotational FE beams, unreduced; docs/nonlinear-beams.md)")
      ->check(CLI::IsMember({"modal", "nonlinear"}))
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
                "Print one JSON object on stdout: {\"status\", \"reference\" (modal or nonlinear), \"ranking\": [{\"component\", \"body\", "
                "\"joint\", \"node\", \"quantity\", \"axis\", \"peak\", \"rms\", \"relative\", \"kept\", "
                "\"indeterminate\"}], \"comparison\": [{\"set\", \"description\", \"modes\", \"reduction_s\", "
                "\"run_s\", \"status\", \"message\", \"f_max_hz\", \"step\", \"event_window\", "
                "\"step_between_windows\", \"steps_per_period\", \"resolved\", "
                "\"error_event\", \"worst_event\", \"error_peak\", \"error_rms\", \"worst_quantity\", "
                "\"event_peaks\": [{\"window\", \"joint\", \"start\", \"reference_start\", \"force\", "
                "\"reference_force\", \"force_error\", \"torque\", \"reference_torque\", \"torque_error\"}], "
                "\"directory\"}], \"reference_check\": {\"step\", \"half_step\", \"half_step_status\", \"windows_rerun\", "
                "\"peak_change\", \"worst\", \"threshold\", \"converged\"}, \"chosen\", \"target\", \"target_met\", "
                "\"norm\", \"steps_per_period_needed\", \"fragment\", \"directory\"}; the text goes to stderr");
  return {cli, [options] { return select_case(*options); }};
}

}  // namespace limber::app
