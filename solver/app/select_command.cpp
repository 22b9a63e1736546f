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
  std::string norm = "peak";
  std::string static_kind = "attachment";
  int max_single = 6;
  int reference_normal = 0;
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

void print_comparison(std::FILE* out, const std::vector<select::CandidateRun>& runs,
                      std::optional<std::size_t> chosen) {
  fmt::print(out, "\nmode sets against 'reference' (error: largest over the key quantities):\n");
  fmt::print(out, "  {:<22} {:>5} {:>10} {:>9} {:>11} {:>11}  {}\n", "set", "modes", "reduction", "run",
             "peak error", "rms error", "");
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const select::CandidateRun& run = runs[k];
    const std::string role = run.candidate.reference ? "reference" : (chosen && *chosen == k ? "chosen" : "");
    fmt::print(out, "  {:<22} {:>5} {:>8.3f} s {:>7.3f} s {:>11} {:>11}  {}{}\n", run.candidate.name, run.modes,
               run.reduction_seconds, run.summary.wall_seconds, percent(run.error_peak),
               percent(run.error_rms), role, run.status() == results::layout::status::kOk ? "" : " " + run.status());
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

std::string json_comparison(const std::vector<select::CandidateRun>& runs, const std::filesystem::path& root) {
  std::string text = "[";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const select::CandidateRun& run = runs[k];
    text += fmt::format(
        "{}{{\"set\": {}, \"description\": {}, \"modes\": {}, \"reduction_s\": {}, \"run_s\": {}, "
        "\"status\": {}, \"message\": {}, \"error_peak\": {}, \"error_rms\": {}, \"worst_quantity\": {}, "
        "\"directory\": {}}}",
        k ? ", " : "", json_string(run.candidate.name), json_string(run.candidate.description), run.modes,
        json_number(run.reduction_seconds), json_number(run.summary.wall_seconds),
        json_string(run.status().substr(0, run.status().find(':'))), json_string(run.summary.message),
        json_number(run.error_peak),
        json_number(run.error_rms), json_string(run.worst_quantity),
        json_string(run.directory.lexically_relative(root).generic_string()));
  }
  return text + "]";
}

int select_case(const SelectOptions& options) {
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
  const auto shared_input = std::make_shared<const io::Case>(io::read_case_file(options.case_file));
  const io::Case& input = *shared_input;
  if (!input.mechanism || input.mechanism->flexible_components.empty()) {
    throw InputError("expected a mechanism with at least one flexible body, got none",
                     SourceLocation{options.case_file, 0, 0});
  }
  const select::RankBy rank_by = options.rank_by == "rms" ? select::RankBy::kRms : select::RankBy::kPeak;
  const select::ErrorNorm norm = options.norm == "rms" ? select::ErrorNorm::kRms : select::ErrorNorm::kPeak;
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

  // Each set's run, with a progress line; a signal stops the selection at the next sample.
  const StopSignals stop_signals;
  const auto adjust = [&](const io::RunSettings& settings) { return options.overrides.apply(settings); };
  int counter = 0;
  const auto run_set = [&](const select::ModeSetCandidate& candidate, std::size_t total) {
    ++counter;
    // The number of sets is known once the ranking is: the first run shows its number alone.
    const std::string of = total > 1 ? fmt::format("/{}", total) : "";
    fmt::print(text, "[{}{}] {}: {}\n", counter, of, candidate.name, candidate.description);
    std::fflush(text);
    std::optional<RunProgress> progress;
    select::CandidateRun run = select::run_candidate(
        shared_input, candidate, adjust, root / results::kRunsFolder / folder_name(candidate.name),
        [&](const integrate::Sample& sample) {
          if (!progress) progress.emplace(adjust(input.mechanism->run).t_end, true);
          progress->update(sample.t, sample.statistics.steps);
          if (StopSignals::received() != 0) throw select::SelectionInterrupted{};
        });
    progress.reset();
    for (const std::string& notice : run.notices) fmt::print(text, "      notice: {}\n", notice);
    fmt::print(text, "      {} modes, reduction {:.3f} s, run {:.3f} s{}\n", run.modes, run.reduction_seconds,
               run.summary.wall_seconds, run.status() == results::layout::status::kOk ? "" : ", " + run.status());
    return run;
  };

  try {
    // Steps 1-3: normal modes only, then the ranking.
    select::ModeSetCandidate normal{"normal", "normal modes only", select::normal_only(input), false};
    std::vector<select::CandidateRun> runs;
    runs.push_back(run_set(normal, 1));
    if (!runs.front().ok()) {
      throw NumericalError("the normal-mode run failed, so there is nothing to rank: " +
                           runs.front().summary.message);
    }
    const std::vector<select::RankedComponent> ranking = select::rank_reactions(
        runs.front().mechanism.model, runs.front().reactions, runs.front().indeterminate, rank_by,
        options.keep);
    print_ranking(text, ranking, options.keep, options.rank_by);

    // Step 4: the other sets, then the comparison.
    const std::vector<select::ModeSetCandidate> candidates =
        select::mode_set_candidates(input, runs.front().reduction, ranking, candidate_options);
    fmt::print(text, "\n");
    for (std::size_t k = 1; k < candidates.size(); ++k) runs.push_back(run_set(candidates[k], candidates.size()));
    const select::CandidateRun& reference = runs.back().ok() ? runs.back() : runs.front();
    const std::vector<select::KeyQuantity> keys = select::key_quantities(ranking, reference);
    select::compare_runs(runs, keys);
    const std::optional<std::size_t> chosen = select::choose_run(runs, options.target, norm);
    print_comparison(text, runs, chosen);

    // Step 5: files for the user and the report.
    const std::filesystem::path folder = root / results::kSelectionFolder;
    select::write_ranking_csv(folder / results::kRankingFileName, ranking);
    select::write_comparison_csv(folder / results::kComparisonFileName, runs, chosen, root);
    select::write_key_series_csv(folder / results::kKeySeriesFileName, runs, keys);
    std::string fragment;
    if (chosen) {
      const select::CandidateRun& run = runs[*chosen];
      const std::string why =
          options.target ? fmt::format("The fewest modes whose {} error against 'reference' is at most {:g} ({}).",
                                       options.norm, *options.target, percent(run.error(norm)))
                         : fmt::format("The procedure's answer: static modes where the reactions are large ({} {} "
                                       "error against 'reference').", percent(run.error(norm)), options.norm);
      fragment = select::selected_modes_yaml(run, why);
      std::ofstream(root / "selected_modes.yaml", std::ios::binary) << fragment;
      std::filesystem::copy_file(run.directory / results::kResultsFileName, root / results::kResultsFileName,
                                 std::filesystem::copy_options::overwrite_existing);
      fmt::print(text, "\nchosen: '{}' ({} modes); its results copied to {}; its modes, to paste into the "
                       "case ({}):\n{}", run.candidate.name, run.modes, (root / results::kResultsFileName).string(),
                 (root / "selected_modes.yaml").string(), fragment);
    } else {
      fmt::print(stderr, "limber: warning: no mode set meets the target {:g} ({} error); the most accurate one "
                         "short of the reference is in the table above\n", options.target.value_or(0.0), options.norm);
    }
    fmt::print(text, "wrote {}\n", folder.string());
    if (options.json) {
      fmt::print(stdout, "{{\"status\": \"ok\", \"ranking\": {}, \"comparison\": {}, \"chosen\": {}, \"target\": {}, "
                         "\"target_met\": {}, \"norm\": {}, \"fragment\": {}, \"directory\": {}}}\n",
                 json_ranking(ranking), json_comparison(runs, root),
                 chosen ? json_string(runs[*chosen].candidate.name) : std::string("null"),
                 options.target ? json_number(*options.target) : std::string("null"),
                 chosen ? "true" : "false", json_string(options.norm), json_string(fragment),
                 json_string(root.string()));
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
      "select", "Choose the modes of the flexible bodies by the seed paper's procedure: normal modes, "
                "reaction ranking, static modes where the reactions are large, compared mode sets");
  cli->footer(
      "Runs the case with normal modes only on every flexible body; ranks every joint-reaction\n"
      "component acting on a flexible body (peak and rms, in the body's own axes); keeps those at\n"
      "or above --keep of the body's largest as boundary conditions for static modes; then runs\n"
      "and compares the mode sets: normal only, each kept component alone, all kept together,\n"
      "as many normal modes as that, and a reference (--reference-normal normal modes plus every\n"
      "kept static mode). Errors are those of the kept reactions and the deflection probes against\n"
      "the reference. Without --target the answer is 'kept' (the procedure's); with it, the set\n"
      "with the fewest modes whose error is at most the target.\n"
      "Writes DIR/runs/<set>/results.h5 for every set, DIR/selection/{ranking,comparison,\n"
      "key_series}.csv, DIR/selected_modes.yaml (the chosen modes, to paste into the case) and\n"
      "DIR/results.h5 (the chosen set's run), so that 'limber report DIR' shows the ranking,\n"
      "the comparison and the key quantities of every set (docs/select.md).\n"
      "Exit codes: 0 done (also when no set meets --target: a warning says so, and --json's\n"
      "target_met is false), 1 bad input, 2 the normal-mode run failed, 3 internal error,\n"
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
  cli->add_option("--norm", options->norm, "Error measure for --target: peak or rms (relative)")
      ->check(CLI::IsMember({"peak", "rms"}))
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
  options->overrides.add_options(*cli);
  cli->add_flag("--json", options->json,
                "Print one JSON object on stdout: {\"status\", \"ranking\": [{\"component\", \"body\", "
                "\"joint\", \"node\", \"quantity\", \"axis\", \"peak\", \"rms\", \"relative\", \"kept\", "
                "\"indeterminate\"}], \"comparison\": [{\"set\", \"description\", \"modes\", \"reduction_s\", "
                "\"run_s\", \"status\", \"message\", \"error_peak\", \"error_rms\", \"worst_quantity\", "
                "\"directory\"}], \"chosen\", \"target\", \"target_met\", \"norm\", \"fragment\", "
                "\"directory\"}; the text goes to stderr");
  return {cli, [options] { return select_case(*options); }};
}

}  // namespace limber::app
