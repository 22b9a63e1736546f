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

RunSummary run_mechanism(const multibody::Model& model,
                         const multibody::AssemblyOptions& assembly,
                         const io::RunSettings& settings, const RunHooks& hooks, const RestartPoint* restart) {
  const auto wall_start = std::chrono::steady_clock::now();
  check_settings(settings);
  check_nonlinear_bodies(model, settings);
  // The spectra's band against the steps the run promises, before anything is written.
  const bool probes = !model.acceleration_probes.empty();
  const double record_step = io::probe_record_step(settings.integrator, settings.sample_interval);
  if (probes) {
    const std::vector<double> grid = results::shock_frequency_grid(settings.shock_spectrum, record_step);
    if (hooks.on_warning) {
      if (const std::string warning = band_above_modes_warning(model, grid.back()); !warning.empty()) {
        hooks.on_warning(warning);
      }
    }
  }
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
  if (start.assembly.status != multibody::AssemblyStatus::kOk) {
    summary.failure = "assembly";
    summary.message = "assembly failed: " + start.assembly.message;
    return finish(results::RunStatus::kFailed);
  }
  if (!start.lost_at_singular_start.empty()) {
    summary.failure = "singular start";
    summary.message = singular_start_message(start.lost_at_singular_start);
    return finish(results::RunStatus::kFailed);
  }
  // The static equilibrium at t = 0, every joint holding (hold-downs included), when asked;
  // or the earlier run's state to restart from.
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
      return finish(results::RunStatus::kFailed);
    }
    initial.q = summary.statics->state.q;
  }
  summary.redundant = start.redundant;
  if (hooks.writer) write_redundant_equations(start.redundant, *hooks.writer);
  if (hooks.on_start) hooks.on_start(start);

  // Integration on the independent rows, energies accumulated by the integrator.
  multibody::MultibodySystem system(model, start.partition);
  // A restart: the earlier run's released joints and hinge modes, whose switches are not
  // reported again.
  if (restart) restore_discrete_state(system, *restart);
  const std::size_t first_event = system.events().size();
  if (hooks.on_warning) warn_velocity_jumps(model, settings.t_end, hooks.on_warning);
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
  if (probes && options.method == integrate::Method::kIda) options.max_step = record_step;
  options.quadrature = energy_quadrature(model, system.partition(), system.engaged(), start.state,
                                         settings.integrator.rtol, &system.fading_loads(), &system.stiffening_loads());
  // The system's partition, which it may re-select along the motion (multibody_system.h), and
  // its hinge modes, which the integrator switches at events.
  SampleRecorder recorder(model, system.partition(), system.engaged());
  std::set<int> warned;  // flexible bodies that left the linear range
  // Events go to the file and the hooks as soon as the integrator has located them.
  std::vector<int> limit_index(model.forces.size(), -1);
  int limits = 0;
  for (std::size_t k = 0; k < model.forces.size(); ++k) {
    if (std::holds_alternative<multibody::HingeLimit>(model.forces[k])) limit_index[k] = limits++;
  }
  const auto report_events = [&] {
    for (std::size_t e = first_event + summary.events.size(); e < system.events().size(); ++e) {
      const multibody::HingeEvent& event = system.events()[e];
      summary.events.push_back(event);
      if (hooks.writer) {
        hooks.writer->append_event(
            {event.t, limit_index[event.force], event.engaged, event.angle, event.rate});
      }
      if (hooks.on_event) hooks.on_event(event);
    }
  };
  // Event peaks at every integrator step when asked for (event_peaks.h), in windows from the
  // start (t = 0, where hold-downs released at 0 let go), from each later release
  // (releases.apply below) and from each latch engagement as the integrator locates it.
  // Each window opened after the start goes to on_window with the last restart point before it.
  std::optional<EventPeakTracker> peaks;
  std::optional<RestartPointRecorder> restart_points;
  const auto report_window = [&] {
    if (restart_points && restart_points->last()) {
      hooks.on_window({peaks->peaks().windows.back().start, *restart_points->last()});
    }
  };
  std::size_t events_seen = first_event;
  if (settings.peak_window > 0.0) {
    peaks.emplace(model, system.partition(), system.engaged(), settings.peak_window);
    if (!restart) peaks->open({0.0, "start"});
    if (hooks.on_window && restart_points_supported(model)) restart_points.emplace(system.engaged());
  }
  // The probes' accelerations at every step, for their spectra (probe_step_record.h).
  std::optional<ProbeStepRecord> probe_record;
  if (probes) probe_record.emplace(model);
  if (peaks || probe_record) {
    options.on_step = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& v_dot,
                          const Eigen::VectorXd& lambda) {
      if (probe_record) probe_record->observe(t, q, v, v_dot);
      if (!peaks) return;
      if (restart_points) restart_points->observe(t, q, v, system.events().size());
      for (; events_seen < system.events().size(); ++events_seen) {
        const std::size_t windows = peaks->peaks().windows.size();
        peaks->on_event(system.events()[events_seen]);
        if (peaks->peaks().windows.size() > windows) report_window();
      }
      peaks->observe(t, q, v, lambda);
    };
  }
  const std::vector<multibody::ClearancePair> clearance_pairs = multibody::clearance_pairs(model);
  summary.clearance.checked = !clearance_pairs.empty();
  AccuracyMonitor accuracy;
  // Re-made at each release: the rank it watches is that of the joints that remain.
  std::optional<SingularPassageMonitor> singular;
  singular.emplace(model, system.nc(), system.partition().row_released);
  const auto report_singular = [&] {
    summary.singular_passages.push_back(singular->last());
    if (hooks.on_warning) hooks.on_warning(singular->last().message());
  };
  const auto on_sample = [&](const integrate::Sample& sample) {
    report_events();
    const results::Sample record = recorder.record(sample);
    for (const multibody::LinearRangeCheck& check :
         multibody::check_linear_range(model, {sample.t, sample.q, sample.v})) {
      if (check.warning.empty() || !warned.insert(check.body).second) continue;
      summary.warnings.push_back(check.warning);
      if (hooks.on_warning) hooks.on_warning(check.warning);
    }
    if (singular->add({sample.t, sample.q, sample.v}, recorder.constraint_jacobian())) report_singular();
    if (hooks.writer) hooks.writer->append_sample(record);
    accuracy.add(record);
    summary.t_reached = sample.t;
    summary.max_position_violation =
        std::max(summary.max_position_violation, record.position_violation);
    summary.max_velocity_violation =
        std::max(summary.max_velocity_violation, record.velocity_violation);
    // The first time the smallest clearance is reached, with its pair.
    if (record.clearance_pair >= 0 && record.clearance_minimum < summary.clearance.distance) {
      const multibody::ClearancePair& pair = clearance_pairs[static_cast<std::size_t>(record.clearance_pair)];
      summary.clearance.distance = record.clearance_minimum;
      summary.clearance.time = sample.t;
      summary.clearance.body_a = model.bodies[static_cast<std::size_t>(pair.body_a)].name;
      summary.clearance.body_b = model.bodies[static_cast<std::size_t>(pair.body_b)].name;
    }
    if (hooks.on_sample) hooks.on_sample(sample, record);
  };
  // A redundant row that comes loose ends the run there (redundant_row_watch.h).
  // Checked after on_sample, on the residuals its recorder has just evaluated.
  const RedundantRowWatch redundant_rows(model, system.partition(), start.deformation_redundant);
  const auto check = [&](const integrate::Sample& sample) {
    return redundant_rows.check(sample.t, recorder.constraint_residuals(), accuracy.size());
  };
  // Hold-downs leave the equations at their release times, and at the events that release
  // them (multibody/event_releases.h); the integrator starts afresh there.
  integrate::Restarts releases;
  // (Those at or before a restart are behind it: restore_discrete_state released them.)
  for (const double t : model.release_times()) {
    if (!restart || t > restart->t) releases.times.push_back(t);
  }
  releases.apply = [&](double t, const integrate::Sample& at) {
    report_events();
    if (singular->finish()) report_singular();
    JointRelease release{t, {}};
    for (const int j : system.release_joints(t, at.q, at.v, at.lambda)) {
      release.joints.push_back(model.joints[static_cast<std::size_t>(j)].name);
      if (hooks.writer) hooks.writer->set_joint_release(j, t);
    }
    singular.emplace(model, system.nc(), system.partition().row_released);
    summary.releases.push_back(release);
    if (peaks && t > 0.0) {
      peaks->open({t, "release"});
      report_window();
    }
  };
  const integrate::SimulationResult result = integrate::simulate(
      system, options, {initial.t, initial.q, initial.v},
      integrate::SampleTimes::uniform(initial.t, settings.t_end, settings.sample_interval), on_sample, check,
      releases);

  // Outcome: a failure keeps every sample (and event) written before it.
  report_events();
  if (singular->finish()) report_singular();
  if (hooks.on_warning) {
    for (const std::string& warning : multibody::unreleased_warnings(model, system.event_releases(), summary.t_reached)) {
      hooks.on_warning(warning);
    }
  }
  summary.samples = result.samples;
  summary.statistics = result.statistics;
  summary.accuracy = accuracy.estimate(result.statistics, options);
  if (peaks) summary.peaks = peaks->peaks();
  add_model_warnings(summary);
  // The probes' shock response spectra over the steps taken.
  if (probe_record && probe_record->spans_time()) {
    record_shock_spectra(model, settings, *probe_record, summary, hooks.writer);
  }
  if (hooks.writer) write_run_tables(summary, peaks.has_value(), *hooks.writer);
  if (!result.status.ok()) {
    summary.failure = integrate::to_string(result.status.code);
    summary.message = result.status.message;
    return finish(results::RunStatus::kFailed);
  }
  return finish(summary.accuracy.accurate() ? results::RunStatus::kOk : results::RunStatus::kInaccurate);
}

}  // namespace limber::run
