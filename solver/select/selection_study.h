// Runs the mode sets of a selection (mode_set_candidates.h) and measures each against the
// richest one, as the seed paper's Fig. 6 compares mode sets (docs/select.md).
//
// Every run reduces the case (read once) with its mode requests (io::ModeOverrides) and builds
// its model, so the modal reduction and its wall time are part of what a set costs; each
// writes DIR/results.h5 like `limber run`. A set whose run fails is a row with its message,
// never a lost selection.
#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"
#include "select/mode_set_candidates.h"
#include "select/peak_comparison.h"
#include "select/step_choice.h"
#include "select/reaction_ranking.h"
#include "results/results_layout.h"

namespace limber::select {

// How a set's difference to the reference is measured: event: the largest relative difference
// of its event peaks (peak_comparison.h); per quantity x over the samples, peak: max |x − x_ref|
// / max |x_ref|; rms: rms(x − x_ref) / rms(x_ref) (series_error.h, the measure `limber sweep`
// uses too).
enum class ErrorNorm { kEvent, kPeak, kRms };

// One mode set's run: what it cost and the series the comparison measures.
struct CandidateRun {
  ModeSetCandidate candidate;
  std::shared_ptr<const io::Case> input;  // the case as read (shared by every run)
  io::CaseReduction reduction;            // the set's modes
  io::Mechanism mechanism;                // the model built with them
  int modes = 0;                   // modes of all flexible bodies together
  double reduction_seconds = 0.0;  // wall time of their modal reductions [s]
  std::vector<std::string> notices;  // the reduction's, e.g. a static mode dropped as dependent
  StepChoice step;                   // the step it ran at and whether it resolves its modes
  run::RunSummary summary;
  double cpu_seconds = 0.0;          // CPU time of its run on its own thread [s] (what it costs beside the others)
  std::filesystem::path directory;   // holds its results.h5
  Eigen::VectorXd time;              // samples [s]
  Eigen::MatrixXd reactions;         // samples x 6 · sites (reaction_ranking.h)
  std::vector<bool> indeterminate;   // per site, set when any sample had it
  Eigen::MatrixXd deflections;       // samples x 3 · probed bodies (body axes) [m]
  std::vector<std::string> probed;   // the probed bodies' names, in the order of `deflections`
  // Against the reference (compare_runs); NaN when not measured.
  double error_peak = std::numeric_limits<double>::quiet_NaN();
  double error_rms = std::numeric_limits<double>::quiet_NaN();
  std::string worst_quantity;      // the quantity of the larger of the two errors
  PeakComparison peaks;            // its event peaks against the reference's
  // Each event window opened after the start, with the last state before it a run can restart
  // from (run/window_restart.h): where the reference's check re-runs its windows.
  std::vector<run::WindowRestart> window_restarts;

  bool ok() const { return summary.ok; }
  // "ok", "ok_inaccurate" (its own accuracy check failed) or "failed: <why>".
  std::string status() const {
    return !summary.ok ? std::string(results::layout::status::kFailed) + ": " + summary.message
         : summary.accurate() ? results::layout::status::kOk
                              : results::layout::status::kInaccurate;
  }
  double error(ErrorNorm norm) const {
    return norm == ErrorNorm::kEvent ? peaks.error : norm == ErrorNorm::kPeak ? error_peak : error_rms;
  }
};

// Settings of every run: the case's, adjusted (e.g. by command-line options).
using SettingsAdjustment = std::function<io::RunSettings(const io::RunSettings&)>;

// What `on_sample` throws to stop a selection (a signal): the run's file is closed as
// "interrupted" before it leaves run_candidate.
struct SelectionInterrupted {};

// Runs one set of `input` (which must hold a mechanism) into `directory` (created; locked while
// written), at the step `policy` chooses for its highest frequency (step_choice.h), tracking
// event peaks (over kSelectPeakWindow unless the settings give a window).
// `on_sample` sees every sample
// (progress; it may throw SelectionInterrupted). Throws InputError on bad input; a numerical
// failure is in the returned summary. Any exception closes the results file first
// ("interrupted" or "failed"). Runs of different sets may run on different threads at once.
// `columns` is the model whose joints on flexible bodies and deflection probes give the columns
// of `reactions` and `deflections` (null: the run's own). A nonlinear set (`--reference
// nonlinear`) passes the ranking run's modal model: its node bodies are recorded as the one body
// of the case at that body's place (run/sample_record.h), so the recorded bodies and joints are
// the modal model's, and a reaction "in the body's axes" is in the recorded body frame, the
// nonlinear body's chord frame (docs/select.md, "The nonlinear reference").
CandidateRun run_candidate(std::shared_ptr<const io::Case> input, const ModeSetCandidate& candidate,
                           const SettingsAdjustment& adjust, const StepPolicy& policy,
                           const std::filesystem::path& directory,
                           const std::function<void(const integrate::Sample&)>& on_sample = {},
                           const multibody::Model* columns = nullptr);

// run_candidate's first half: the set's modes and model (reduction, mechanism, modes, notices),
// ready for candidate_settings and run_mechanism_recorded, for a caller that watches the run.
// Throws as run_candidate.
CandidateRun prepare_candidate(std::shared_ptr<const io::Case> input, const ModeSetCandidate& candidate,
                               const std::filesystem::path& directory);

// The settings a set of `mechanism` runs with: the case's, adjusted, with event peaks (over
// kSelectPeakWindow unless the settings give a window) and the step `policy` chooses for the
// model's highest frequency, which goes to `step`. Throws InputError when they cannot run.
io::RunSettings candidate_settings(const io::Mechanism& mechanism, const SettingsAdjustment& adjust,
                                   const StepPolicy& policy, StepChoice& step);

// Runs `mechanism` (a set's model, built from `input`) with `settings` into `run.directory`,
// from `restart` when given (else from t = 0), and keeps in `run` what the comparison measures:
// the summary, every sample's reactions on the flexible bodies and deflections, the windows'
// restart points, in the columns of `columns` (run_candidate's). The file is titled
// "<case title> [<title>]". Exceptions as run_candidate's.
void run_mechanism_recorded(const io::Case& input, const io::Mechanism& mechanism, const io::RunSettings& settings,
                            const std::string& title, const run::RestartPoint* restart,
                            const std::function<void(const integrate::Sample&)>& on_sample, CandidateRun& run,
                            const multibody::Model* columns = nullptr);

// Calls job(k) for k in [0, count) on `workers` threads (1: in order on this one). After the
// first exception a job throws, no further job starts; it is rethrown once the running ones end.
void run_parallel(std::size_t count, int workers, const std::function<void(std::size_t)>& job);

// A series the comparison measures: a kept reaction component or a deflection probe's axis.
struct KeyQuantity {
  std::string name;  // "R3 force z on rod [N]", "rod deflection z [m]"
  bool deflection = false;
  int column = 0;    // in CandidateRun::reactions or ::deflections
};

// The kept components of `ranking`, then every probed body's deflection axes (`reference.probed`)
// whose peak in `reference` is at least 1 % of its largest axis (a smaller axis is noise on a
// relative scale).
std::vector<KeyQuantity> key_quantities(const std::vector<RankedComponent>& ranking,
                                        const CandidateRun& reference);

// The quantity's series in a run.
Eigen::VectorXd key_series(const CandidateRun& run, const KeyQuantity& quantity);

// The release times of the model's joints that have one (Joint::release_time) and of those
// `run` released at an event (`release: {after: <latch>, delay: s}`, at the time the run located
// it: RunSummary::releases): the joints compare_peaks leaves out of the windows their release
// opens (and of later ones).
ReleaseTimes joint_release_times(const multibody::Model& model, const run::RunSummary& run);

// Fills error_peak, error_rms and worst_quantity of every finished run against the run marked
// reference (largest error over `keys`), on their common samples, and peaks (their event peaks
// against the reference's).
void compare_runs(std::vector<CandidateRun>& runs, const std::vector<KeyQuantity>& keys);

// The set to use: with a target, the finished, accurate (its own accuracy check passed),
// resolved (its step resolves its highest frequency) non-reference set with the fewest modes
// (then the shortest run) whose error is at most `target`, or none; without one, the
// procedure's answer ("kept"). Returns an index into `runs`, or nullopt.
std::optional<std::size_t> choose_run(const std::vector<CandidateRun>& runs,
                                      std::optional<double> target, ErrorNorm norm);

}  // namespace limber::select
