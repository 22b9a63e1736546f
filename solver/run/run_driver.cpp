#include "run/run_driver.h"

#include <algorithm>

#include <fmt/format.h>
#include <chrono>
#include <optional>
#include <set>

#include "core/error.h"
#include "integrate/simulate.h"
#include "io/acceleration_probe_reader.h"
#include "multibody/clearance.h"
#include "multibody/linear_range.h"
#include "multibody/multibody_system.h"
#include "run/event_peaks.h"
#include "run/probe_step_record.h"
#include "run/redundant_row_watch.h"
#include "run/run_outcome.h"
#include "run/sample_record.h"
#include "run/singular_passage.h"

namespace limber::run {

void check_settings(const io::RunSettings& settings) {
  settings.integrator.validate();
  // Below these IDA asks for more digits than its Newton corrector (a finite-difference matrix,
  // double precision) delivers on a mechanism: it fails mid-run instead of finishing (the rigid
  // slider-crank fails at rtol 1e-12 and runs at 1e-11, docs/integrators.md).
  if (settings.integrator.method == integrate::Method::kIda) {
    if (settings.integrator.rtol < kMinimumRtol) {
      throw InputError(fmt::format("expected rtol >= {:g} for IDA on a mechanism (tighter asks for more "
                                   "digits than double precision delivers), got {:g}",
                                   kMinimumRtol, settings.integrator.rtol));
    }
    if (settings.integrator.atol < kMinimumAtol) {
      throw InputError(fmt::format("expected atol >= {:g} for IDA on a mechanism (tighter asks for more "
                                   "digits than double precision delivers), got {:g}",
                                   kMinimumAtol, settings.integrator.atol));
    }
  }
  integrate::check_sample_times(0.0, settings.t_end, settings.sample_interval);
  if (!(settings.peak_window >= 0.0)) {
    throw InputError(fmt::format("expected a peak window >= 0 s (0: none), got {:g}", settings.peak_window));
  }
}

void check_nonlinear_bodies(const multibody::Model& model, const io::RunSettings& settings) {
  if (model.nonlinear_bodies.empty()) return;
  const std::string& name = model.nonlinear_bodies.front().name;
  // IDA's matrix of differences would take a residual per coordinate of every node (hundreds);
  // its structured matrix carries the beams' coupled stiffness (ggl_equations.h).
  if (settings.integrator.method == integrate::Method::kIda &&
      settings.integrator.ida_newton_matrix != integrate::IdaNewtonMatrix::kStructured) {
    throw InputError(fmt::format("nonlinear body \"{}\": expected 'newton_matrix: structured' with integrator "
                                 "ida (its matrix of differences would take a residual per node coordinate), "
                                 "got differences", name));
  }
}

results::ShockSpectra probe_shock_spectra(const multibody::Model& model, const io::RunSettings& settings,
                                          const Eigen::VectorXd& time,
                                          const std::vector<results::ProbeHistory>& histories,
                                          const std::vector<multibody::HingeEvent>& events) {
  std::vector<results::LatchTime> latches;
  for (const multibody::HingeEvent& event : events) {
    const auto& limit = std::get<multibody::HingeLimit>(model.forces[static_cast<std::size_t>(event.force)]);
    if (limit.kind == multibody::HingeLimitKind::kLatch && event.engaged) latches.push_back({limit.name, event.t});
  }
  return results::shock_spectra(time, io::probe_record_step(settings.integrator, settings.sample_interval), histories,
                                latches, settings.shock_spectrum);
}

namespace {

// The spectra's band against the steps the run promises, before anything is written.
void warn_band_above_modes(const multibody::Model& model, const io::RunSettings& settings,
                           const RunHooks& hooks, double record_step) {
  if (model.acceleration_probes.empty() || !hooks.on_warning) return;
  const std::vector<double> grid = results::shock_frequency_grid(settings.shock_spectrum, record_step);
  if (const std::string warning = band_above_modes_warning(model, grid.back()); !warning.empty()) {
    hooks.on_warning(warning);
  }
}

// The state the integration starts from: the assembled one, an earlier run's (a restart) or the
// static equilibrium at t = 0 with every joint holding (hold-downs included), when asked.
// Without one (assembly, a singular start or the statics failed), summary's failure and message
// say why.
std::optional<multibody::State> initial_state(const multibody::Model& model, const io::RunSettings& settings,
                                              const PreparedStart& start, const RestartPoint* restart,
                                              RunSummary& summary) {
  if (start.assembly.status != multibody::AssemblyStatus::kOk) {
    summary.failure = "assembly";
    summary.message = "assembly failed: " + start.assembly.message;
    return std::nullopt;
  }
  if (!start.lost_at_singular_start.empty()) {
    summary.failure = "singular start";
    summary.message = singular_start_message(start.lost_at_singular_start);
    return std::nullopt;
  }
  multibody::State initial = start.state;
  if (restart) {
    initial.t = restart->t;
    initial.q = restart->q;
    initial.v = restart->v;
  } else if (settings.start == io::StartKind::kStatics) {
    summary.statics = multibody::solve_statics(model, start.partition, start.state);
    if (summary.statics->status != multibody::StaticsStatus::kOk) {
      summary.failure = "statics";
      summary.message = summary.statics->message;
      return std::nullopt;
    }
    initial.q = summary.statics->state.q;
  }
  return initial;
}

// The case's integrator settings as this mechanism needs them, energies accumulated by the
// integrator (on_step is left to the observers).
integrate::IntegratorOptions integrator_options(const multibody::Model& model, const io::RunSettings& settings,
                                                multibody::MultibodySystem& system,
                                                const multibody::State& assembled, double record_step) {
  integrate::IntegratorOptions options = settings.integrator;
  // BDF2 at most when flexible modes are present (integrator_options.h, max_order).
  const bool flexible = std::any_of(model.bodies.begin(), model.bodies.end(), [](const auto& body) {
    return body.kind == multibody::BodyKind::kFlexible;
  });
  if (options.max_order == 0 && flexible) options.max_order = 2;
  // A nonlinear body's node velocities pass through 0 along the rod together: IDA's error
  // weights relative to the mechanism's size and speed (integrator_options.h, IdaErrorWeights).
  if (!model.nonlinear_bodies.empty()) options.ida_error_weights = integrate::IdaErrorWeights::kPerGroup;
  // IDA's steps no longer than the probes' record promises (io::probe_record_step).
  if (!model.acceleration_probes.empty() && options.method == integrate::Method::kIda) {
    options.max_step = record_step;
  }
  options.quadrature = energy_quadrature(model, system.partition(), system.engaged(), assembled,
                                         settings.integrator.rtol, &system.fading_loads(), &system.stiffening_loads());
  return options;
}

// Each hinge limit's index among the model's limits (the events table's numbering), -1 for
// other forces.
std::vector<int> hinge_limit_indices(const multibody::Model& model) {
  std::vector<int> limit_index(model.forces.size(), -1);
  int limits = 0;
  for (std::size_t k = 0; k < model.forces.size(); ++k) {
    if (std::holds_alternative<multibody::HingeLimit>(model.forces[k])) limit_index[k] = limits++;
  }
  return limit_index;
}

// What the run observes along the integration: samples (recorded, written, checked against the
// linear range, the clearances, the redundant rows and singular passages), events, releases,
// and per step the event peaks and the probes' accelerations. Its results go to the summary
// and the hooks as they arrive.
class RunObservers {
 public:
  RunObservers(const multibody::Model& model, const io::RunSettings& settings, const RunHooks& hooks,
               multibody::MultibodySystem& system, const PreparedStart& start, bool restarted,
               RunSummary& summary)
      : model_(model),
        hooks_(hooks),
        system_(system),
        summary_(summary),
        first_event_(system.events().size()),
        // The system's partition, which it may re-select along the motion (multibody_system.h),
        // and its hinge modes, which the integrator switches at events.
        recorder_(model, system.partition(), system.engaged()),
        limit_index_(hinge_limit_indices(model)),
        events_seen_(first_event_),
        clearance_pairs_(multibody::clearance_pairs(model)),
        // A redundant row that comes loose ends the run there (redundant_row_watch.h).
        redundant_rows_(model, system.partition(), start.deformation_redundant) {
    // Event peaks at every integrator step when asked for (event_peaks.h), in windows from the
    // start (t = 0, where hold-downs released at 0 let go), from each later release
    // (apply_release) and from each latch engagement as the integrator locates it. Each window
    // opened after the start goes to on_window with the last restart point before it.
    if (settings.peak_window > 0.0) {
      peaks_.emplace(model, system.partition(), system.engaged(), settings.peak_window);
      if (!restarted) peaks_->open({0.0, "start"});
      if (hooks.on_window && restart_points_supported(model)) restart_points_.emplace(system.engaged());
    }
    // The probes' accelerations at every step, for their spectra (probe_step_record.h).
    if (!model.acceleration_probes.empty()) probe_record_.emplace(model);
    summary.clearance.checked = !clearance_pairs_.empty();
    // Re-made at each release: the rank it watches is that of the joints that remain.
    singular_.emplace(model, system.nc(), system.partition().row_released);
  }

  bool observes_steps() const { return peaks_ || probe_record_; }

  void on_step(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& v_dot,
               const Eigen::VectorXd& lambda) {
    if (probe_record_) probe_record_->observe(t, q, v, v_dot);
    if (!peaks_) return;
    if (restart_points_) restart_points_->observe(t, q, v, system_.events().size());
    for (; events_seen_ < system_.events().size(); ++events_seen_) {
      const std::size_t windows = peaks_->peaks().windows.size();
      peaks_->on_event(system_.events()[events_seen_]);
      if (peaks_->peaks().windows.size() > windows) report_window();
    }
    peaks_->observe(t, q, v, lambda);
  }

  void on_sample(const integrate::Sample& sample);

  // Checked after on_sample, on the residuals its recorder has just evaluated.
  integrate::Status check(const integrate::Sample& sample) const {
    return redundant_rows_.check(sample.t, recorder_.constraint_residuals(), accuracy_.size());
  }

  // A hold-down's release at t: its joints leave the equations (multibody/event_releases.h).
  void apply_release(double t, const integrate::Sample& at);

  // At the end: the events and the singular passage still open.
  void finish() {
    report_events();
    if (singular_->finish()) report_singular();
  }

  const AccuracyMonitor& accuracy() const { return accuracy_; }
  const std::optional<EventPeakTracker>& peaks() const { return peaks_; }
  const std::optional<ProbeStepRecord>& probe_record() const { return probe_record_; }

 private:
  // Events go to the file and the hooks as soon as the integrator has located them.
  void report_events() {
    for (std::size_t e = first_event_ + summary_.events.size(); e < system_.events().size(); ++e) {
      const multibody::HingeEvent& event = system_.events()[e];
      summary_.events.push_back(event);
      if (hooks_.writer) {
        hooks_.writer->append_event({event.t, limit_index_[event.force], event.engaged, event.angle, event.rate});
      }
      if (hooks_.on_event) hooks_.on_event(event);
    }
  }

  void report_window() {
    if (restart_points_ && restart_points_->last()) {
      hooks_.on_window({peaks_->peaks().windows.back().start, *restart_points_->last()});
    }
  }

  void report_singular() {
    summary_.singular_passages.push_back(singular_->last());
    if (hooks_.on_warning) hooks_.on_warning(singular_->last().message());
  }

  void record_clearance(const integrate::Sample& sample, const results::Sample& record);

  const multibody::Model& model_;
  const RunHooks& hooks_;
  multibody::MultibodySystem& system_;
  RunSummary& summary_;
  const std::size_t first_event_;
  SampleRecorder recorder_;
  std::set<int> warned_;  // flexible bodies that left the linear range
  const std::vector<int> limit_index_;
  std::optional<EventPeakTracker> peaks_;
  std::optional<RestartPointRecorder> restart_points_;
  std::size_t events_seen_;
  std::optional<ProbeStepRecord> probe_record_;
  const std::vector<multibody::ClearancePair> clearance_pairs_;
  AccuracyMonitor accuracy_;
  std::optional<SingularPassageMonitor> singular_;
  const RedundantRowWatch redundant_rows_;
};

void RunObservers::on_sample(const integrate::Sample& sample) {
  report_events();
  const results::Sample record = recorder_.record(sample);
  for (const multibody::LinearRangeCheck& check :
       multibody::check_linear_range(model_, {sample.t, sample.q, sample.v})) {
    if (check.warning.empty() || !warned_.insert(check.body).second) continue;
    summary_.warnings.push_back(check.warning);
    if (hooks_.on_warning) hooks_.on_warning(check.warning);
  }
  if (singular_->add({sample.t, sample.q, sample.v}, recorder_.constraint_jacobian())) report_singular();
  if (hooks_.writer) hooks_.writer->append_sample(record);
  accuracy_.add(record);
  summary_.t_reached = sample.t;
  summary_.max_position_violation = std::max(summary_.max_position_violation, record.position_violation);
  summary_.max_velocity_violation = std::max(summary_.max_velocity_violation, record.velocity_violation);
  record_clearance(sample, record);
  if (hooks_.on_sample) hooks_.on_sample(sample, record);
}

// The first time the smallest clearance is reached, with its pair.
void RunObservers::record_clearance(const integrate::Sample& sample, const results::Sample& record) {
  if (record.clearance_pair < 0 || !(record.clearance_minimum < summary_.clearance.distance)) return;
  const multibody::ClearancePair& pair = clearance_pairs_[static_cast<std::size_t>(record.clearance_pair)];
  summary_.clearance.distance = record.clearance_minimum;
  summary_.clearance.time = sample.t;
  summary_.clearance.body_a = model_.bodies[static_cast<std::size_t>(pair.body_a)].name;
  summary_.clearance.body_b = model_.bodies[static_cast<std::size_t>(pair.body_b)].name;
}

void RunObservers::apply_release(double t, const integrate::Sample& at) {
  report_events();
  if (singular_->finish()) report_singular();
  JointRelease release{t, {}};
  for (const int j : system_.release_joints(t, at.q, at.v, at.lambda)) {
    release.joints.push_back(model_.joints[static_cast<std::size_t>(j)].name);
    if (hooks_.writer) hooks_.writer->set_joint_release(j, t);
  }
  singular_.emplace(model_, system_.nc(), system_.partition().row_released);
  summary_.releases.push_back(release);
  if (peaks_ && t > 0.0) {
    peaks_->open({t, "release"});
    report_window();
  }
}

// Hold-downs leave the equations at their release times, and at the events that release them
// (multibody/event_releases.h); the integrator starts afresh there. Those at or before a
// restart are behind it: restore_discrete_state released them.
integrate::Restarts release_schedule(const multibody::Model& model, const RestartPoint* restart,
                                     RunObservers& observers) {
  integrate::Restarts releases;
  for (const double t : model.release_times()) {
    if (!restart || t > restart->t) releases.times.push_back(t);
  }
  releases.apply = [&observers](double t, const integrate::Sample& at) { observers.apply_release(t, at); };
  return releases;
}

// The run's outcome into the summary and the file; a failure keeps every sample (and event)
// written before it.
results::RunStatus record_outcome(const multibody::Model& model, const io::RunSettings& settings,
                                  const RunHooks& hooks, const multibody::MultibodySystem& system,
                                  const integrate::IntegratorOptions& options,
                                  const integrate::SimulationResult& result, RunObservers& observers,
                                  RunSummary& summary) {
  observers.finish();
  if (hooks.on_warning) {
    for (const std::string& warning :
         multibody::unreleased_warnings(model, system.event_releases(), summary.t_reached)) {
      hooks.on_warning(warning);
    }
  }
  summary.samples = result.samples;
  summary.statistics = result.statistics;
  summary.accuracy = observers.accuracy().estimate(result.statistics, options);
  if (observers.peaks()) summary.peaks = observers.peaks()->peaks();
  add_model_warnings(summary);
  // The probes' shock response spectra over the steps taken.
  if (observers.probe_record() && observers.probe_record()->spans_time()) {
    record_shock_spectra(model, settings, *observers.probe_record(), summary, hooks.writer);
  }
  if (hooks.writer) write_run_tables(summary, observers.peaks().has_value(), *hooks.writer);
  if (!result.status.ok()) {
    summary.failure = integrate::to_string(result.status.code);
    summary.message = result.status.message;
    return results::RunStatus::kFailed;
  }
  return summary.accuracy.accurate() ? results::RunStatus::kOk : results::RunStatus::kInaccurate;
}

}  // namespace

RunSummary run_mechanism(const multibody::Model& model,
                         const multibody::AssemblyOptions& assembly,
                         const io::RunSettings& settings, const RunHooks& hooks, const RestartPoint* restart) {
  const auto wall_start = std::chrono::steady_clock::now();
  check_settings(settings);
  check_nonlinear_bodies(model, settings);
  const double record_step = io::probe_record_step(settings.integrator, settings.sample_interval);
  warn_band_above_modes(model, settings, hooks, record_step);
  RunSummary summary;
  summary.integrator = integrate::to_string(settings.integrator.method);
  summary.t_end = settings.t_end;
  const auto finish = [&](results::RunStatus status) {
    if (hooks.writer) hooks.writer->finish(status, summary.message);
    summary.ok = status == results::RunStatus::kOk || status == results::RunStatus::kInaccurate;
    summary.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return summary;
  };

  // Declarations come first so that even a failed assembly leaves a readable file.
  if (hooks.writer) {
    declare_model(model, *hooks.writer);
    hooks.writer->set_integrator(summary.integrator);
  }

  // Assembly and redundancy analysis.
  const PreparedStart start = prepare_start(model, assembly);
  const std::optional<multibody::State> initial = initial_state(model, settings, start, restart, summary);
  if (!initial) return finish(results::RunStatus::kFailed);
  summary.redundant = start.redundant;
  if (hooks.writer) write_redundant_equations(start.redundant, *hooks.writer);
  if (hooks.on_start) hooks.on_start(start);

  // Integration on the independent rows.
  multibody::MultibodySystem system(model, start.partition);
  // A restart: the earlier run's released joints and hinge modes, whose switches are not
  // reported again.
  if (restart) restore_discrete_state(system, *restart);
  if (hooks.on_warning) warn_velocity_jumps(model, settings.t_end, hooks.on_warning);
  integrate::IntegratorOptions options = integrator_options(model, settings, system, start.state, record_step);
  RunObservers observers(model, settings, hooks, system, start, restart != nullptr, summary);
  if (observers.observes_steps()) {
    options.on_step = [&observers](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                   const Eigen::VectorXd& v_dot, const Eigen::VectorXd& lambda) {
      observers.on_step(t, q, v, v_dot, lambda);
    };
  }
  const integrate::Restarts releases = release_schedule(model, restart, observers);
  const integrate::SimulationResult result = integrate::simulate(
      system, options, {initial->t, initial->q, initial->v},
      integrate::SampleTimes::uniform(initial->t, settings.t_end, settings.sample_interval),
      [&observers](const integrate::Sample& sample) { observers.on_sample(sample); },
      [&observers](const integrate::Sample& sample) { return observers.check(sample); }, releases);
  return finish(record_outcome(model, settings, hooks, system, options, result, observers, summary));
}

}  // namespace limber::run
