// The run of a mechanism (`limber run`, issue 3): assemble, analyse redundancy, integrate with
// output at a fixed sample interval, and hand every sample to the results file as it comes
// (written in blocks; a failure or a signal writes the rest, a kill loses at most the last block:
// results_writer.h).
//
// The run starts from the assembled initial poses, or from the static equilibrium there
// (settings.start); joints with a release time (hold-downs) leave the equations at that time,
// where the integrator stops and starts afresh with the joints that remain
// (integrate::Restarts).
//
// Failures are returned, never thrown (house style §11): an assembly that does not close, a
// static equilibrium not found, or an integrator failure ("at t = … s: why"), ends the run with
// status "failed" and that message in the summary and in results.h5. Bad settings throw
// InputError before anything is written.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "integrate/integrator.h"
#include "io/mechanism_reader.h"
#include "multibody/hinge_limit.h"
#include "multibody/model.h"
#include "multibody/statics.h"
#include "results/results_writer.h"
#include "results/shock_spectra.h"
#include "run/accuracy_check.h"
#include "run/singular_passage.h"
#include "run/prepared_start.h"
#include "run/window_restart.h"

namespace limber::run {

// The smallest clearance over the samples (multibody/clearance.h), its first time and pair.
struct ClearanceMinimum {
  bool checked = false;  // the model has two or more bodies with surfaces
  double distance = std::numeric_limits<double>::infinity();  // [m], negative: interference
  double time = 0.0;                                          // [s]
  std::string body_a, body_b;                                 // "" while none was found
};

// Joints released together (hold-downs: Joint::release_time), and when [s].
struct JointRelease {
  double t = 0.0;
  std::vector<std::string> joints;
};

struct RunSummary {
  bool ok = false;              // the run reached t_end (accurate or not: see `accuracy`)
  std::string message;          // why the run failed ("" when ok)
  std::string failure;          // "assembly", an integrate::StatusCode name, or ""
  std::string integrator;       // "ida" / "galpha"
  double t_end = 0.0;           // requested end time [s]
  double t_reached = 0.0;       // time of the last sample written [s]
  int samples = 0;
  integrate::Statistics statistics;
  double wall_seconds = 0.0;    // assembly, analysis, integration and output
  double max_position_violation = 0.0;  // max over samples of max |g| [m or rad]
  double max_velocity_violation = 0.0;  // max over samples of max |G v + g_t|
  std::vector<RedundantEquationReport> redundant;
  // Linear-range warnings (multibody/linear_range.h), the first per flexible body.
  std::vector<std::string> warnings;
  // Singular configurations passed (singular_passage.h), in order; each also went to
  // on_warning. They do not change the status: the run went on, on one branch.
  std::vector<SingularPassage> singular_passages;
  // Mode switches of hinge latches and stops, in order (located events).
  std::vector<multibody::HingeEvent> events;
  // The static equilibrium the run started from (run.start: statics); empty otherwise.
  std::optional<multibody::StaticsResult> statics;
  // Hold-downs released along the run, in order.
  std::vector<JointRelease> releases;
  ClearanceMinimum clearance;
  // The run's own accuracy estimate (accuracy_check.h), from every sample written.
  AccuracyEstimate accuracy;
  // Per joint, the largest reactions after the start and each latch engagement, tracked at
  // every integrator step (event_peaks.h); empty when not asked for (RunSettings::peak_window
  // 0) or the run did not integrate.
  results::EventPeaks peaks;
  // The acceleration probes' shock response spectra over their record at every integrator step
  // (none without probes or without a step); also in results.h5 and DIR/srs_<probe>.csv.
  std::optional<results::ShockSpectra> shock_spectra;

  // Reached t_end and its accuracy estimate holds.
  bool accurate() const { return ok && accuracy.accurate(); }
};

// Optional observers; all may be empty.
struct RunHooks {
  results::ResultsWriter* writer = nullptr;  // declared, filled and finished by the run
  // After assembly and redundancy analysis, before integration (e.g. to print the redundancy).
  std::function<void(const PreparedStart&)> on_start;
  // Every sample, after it is written.
  std::function<void(const integrate::Sample&, const results::Sample&)> on_sample;
  // A flexible body left the linear range (its first time only), or the run passed a
  // singular configuration (RunSummary::singular_passages).
  std::function<void(const std::string&)> on_warning;
  // A hinge latch or stop switched (reported once its time has been passed by a sample).
  std::function<void(const multibody::HingeEvent&)> on_event;
  // An event-peak window opened after the start (RunSettings::peak_window > 0), with the last
  // state before its event that a run can restart from (window_restart.h).
  std::function<void(const WindowRestart&)> on_window;
};

// The tightest IDA tolerances `limber run` accepts (check_settings).
inline constexpr double kMinimumRtol = 1e-11;
inline constexpr double kMinimumAtol = 1e-14;

// Throws InputError when the settings cannot run (integrator options out of range, sample
// interval not positive, peak window negative, IDA tolerances below kMinimumRtol / kMinimumAtol).
void check_settings(const io::RunSettings& settings);

// Throws InputError when `model` has a nonlinear body and the settings ask for what its path
// does not offer yet: IDA, or a start from static equilibrium.
void check_nonlinear_bodies(const multibody::Model& model, const io::RunSettings& settings);

// The spectra of the probes' accelerations `histories` (one row per point at `time`) over the
// whole run and the windows from t = 0 and from each latch that locked (results/shock_spectra.h).
results::ShockSpectra probe_shock_spectra(const multibody::Model& model, const io::RunSettings& settings,
                                          const Eigen::VectorXd& time,
                                          const std::vector<results::ProbeHistory>& histories,
                                          const std::vector<multibody::HingeEvent>& events);

// Runs `model` from t = 0 to settings.t_end. Throws InputError on bad settings (a shock-spectrum
// band the run's steps do not support included, io::probe_record_step) or held coordinates (before writing any
// sample).
// With `restart` (a state of an earlier run of the same model, window_restart.h) the run starts
// there instead, in its discrete state, with samples every settings.sample_interval from its
// time: no statics, no "start" window; the events before it are not reported again.
RunSummary run_mechanism(const multibody::Model& model,
                         const multibody::AssemblyOptions& assembly,
                         const io::RunSettings& settings, const RunHooks& hooks = {},
                         const RestartPoint* restart = nullptr);

}  // namespace limber::run
