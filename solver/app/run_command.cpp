// `limber run`: reads a mechanism case, reduces its flexible bodies and builds the model
// (io: read -> reduce -> build), assembles it, reports its redundant constraint
// equations, integrates it (IDA or generalized-α) and writes DIR/results.h5 sample by sample
// (docs/results-format.md). A numerical failure ends the run with a message saying when and
// why; the samples before it stay in the file (status "failed").
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include "app/command.h"
#include "app/event_peaks_text.h"
#include "app/run_progress.h"
#include "app/settings_overrides.h"
#include "app/stop_signal.h"
#include "core/error.h"
#include "io/case_reader.h"
#include "multibody/joint_placement.h"
#include "io/case_reduction.h"
#include "results/results_writer.h"
#include "run/case_run.h"
#include "run/run_driver.h"
#include "run/run_record.h"
#include "results/results_layout.h"
#include "results/shock_spectra_file.h"

namespace limber::app {

namespace {

struct RunOptions {
  std::string case_file;
  std::string output_dir;
  SettingsOverrides overrides;
  std::optional<int> modes;  // normal modes of every flexible body (--modes)
  bool json = false;
};

std::string describe_integrator(const integrate::IntegratorOptions& options) {
  if (options.method == integrate::Method::kIda) {
    return fmt::format("ida (BDF, GGL index 2), rtol {:g}, atol {:g}", options.rtol, options.atol);
  }
  return fmt::format("galpha (Lie-group generalized-alpha, index 3), step {:g} s, rho_inf {:g}",
                     options.step, options.rho_inf);
}

void print_model(std::FILE* out, const multibody::Model& model) {
  const int joint_rows = model.num_equations() - static_cast<int>(model.drivers.size());
  fmt::print(out, "model: moving bodies {}, joints {}, drivers {}, force elements {}; "
                  "velocities {}, equations {} (joints) + {} (drivers)\n",
             model.bodies.size() - 1, model.joints.size(), model.drivers.size(),
             model.forces.size(), model.nv, joint_rows, model.drivers.size());
}

// "reduction: rod 9 modes 0.112 s, ..." when the mechanism has flexible bodies.
void print_reduction(std::FILE* out, const io::CaseReduction& reduction) {
  if (reduction.bodies.empty()) return;
  std::string line;
  for (const io::BodyReduction& body : reduction.bodies) {
    line += fmt::format("{}{} {} modes {:.3f} s", line.empty() ? "" : ", ", body.name,
                        body.result.mode_set.shapes.cols(), body.seconds);
  }
  fmt::print(out, "reduction: {}\n", line);
}

// "geometric stiffening: rod full (2 load nodes), ..." for the bodies that have it
// (docs/geometric-stiffening.md), with a note on the energy balance of full stiffening.
void print_stiffening(std::FILE* out, const multibody::Model& model) {
  std::string line;
  bool full = false;
  for (const multibody::Body& body : model.bodies) {
    if (body.kind != multibody::BodyKind::kFlexible || body.flexible->stiffening == multibody::GeometricStiffening::kOff) {
      continue;
    }
    full = full || body.flexible->stiffening == multibody::GeometricStiffening::kFull;
    line += fmt::format("{}{} {}", line.empty() ? "" : ", ", body.name, multibody::to_string(body.flexible->stiffening));
    if (body.flexible->stiffening == multibody::GeometricStiffening::kFull) {
      line += fmt::format(" ({} load nodes)", body.flexible->geometric.load_nodes.size());
    }
  }
  if (line.empty()) return;
  fmt::print(out, "geometric stiffening: {}\n", line);
  if (full) {
    fmt::print(out, "  (first order: the geometric forces' work is counted in the energy balance's force_work)\n");
  }
}

void print_start(std::FILE* out, const multibody::Model& model, const run::PreparedStart& start) {
  fmt::print(out,
             "assembly: closed in {} Newton iterations, max residual {:.3g}; velocity "
             "constraints {:.3g} after projection\n",
             start.assembly.iterations, start.assembly.residual, start.velocity_residual);
  if (start.assembly.modes_released || start.velocity_modes_released) {
    fmt::print(out, "assembly: the constraints close only with the flexible bodies deformed{}: "
                    "their initial modal coordinates and rates were changed\n",
               start.assembly.modes_released ? "" : " in velocity");
  }
  const std::size_t independent = start.partition.independent.size();
  if (start.redundant.empty()) {
    fmt::print(out, "redundancy: none ({} independent equations)\n", independent);
    return;
  }
  fmt::print(out,
             "redundancy: {} of {} equations are redundant (rank {}); their reactions are "
             "minimum-norm and flagged indeterminate:\n",
             start.redundant.size(), model.num_equations(), independent);
  for (const run::RedundantEquationReport& r : start.redundant) {
    fmt::print(out, "  {}\n", r.description);
  }
  for (const run::DeformationRedundancy& d : start.deformation_redundant) {
    fmt::print(out, "  note: {}; the run stops if it comes loose. To make it independent, {}\n",
               d.description(model), d.remedy(model));
  }
}

// The run's accuracy estimate on `out`, each warning on stderr.
void print_accuracy(std::FILE* out, const run::AccuracyEstimate& accuracy) {
  fmt::print(out, "accuracy: energy balance {:.2g} of the energy scale, local error {:.2g}, "
                  "constraint drift {:.2g} of the size{}\n",
             accuracy.energy_relative, accuracy.local_error, accuracy.drift_relative,
             accuracy.accurate() ? "" : ": NOT ACCURATE");
  for (const std::string& warning : accuracy.warnings) fmt::print(stderr, "limber: warning: {}\n", warning);
}

// "latch L (joint R1) engaged at t = ... s: angle ..°, rate ..°/s".
std::string describe_event(const multibody::Model& model, const multibody::HingeEvent& event) {
  const auto& limit = std::get<multibody::HingeLimit>(model.forces[event.force]);
  const bool latch = limit.kind == multibody::HingeLimitKind::kLatch;
  const char* what = latch ? "locked" : (event.engaged ? "contact begins" : "contact ends");
  constexpr double kDegrees = 180.0 / std::numbers::pi;
  return fmt::format("{} {} (joint {}) {} at t = {:.9g} s: angle {:.4f} deg, rate {:.4g} deg/s",
                     multibody::to_string(limit.kind), limit.name, model.joints[limit.joint].name,
                     what, event.t, event.angle * kDegrees, event.rate * kDegrees);
}

// The run's minimum clearance on `out`, and a warning on stderr when two bodies interfere.
void print_clearance(std::FILE* out, const run::ClearanceMinimum& clearance) {
  if (!clearance.checked) return;
  if (clearance.body_a.empty()) {
    fmt::print(out, "minimum clearance: none found (every vertex within a joint band)\n");
    return;
  }
  fmt::print(out, "minimum clearance: {:.4g} m between {} and {} at t = {:g} s\n",
             clearance.distance, clearance.body_a, clearance.body_b, clearance.time);
  if (clearance.distance < 0.0) {
    fmt::print(stderr, "limber: warning: {} passes through {} at t = {:g} s (clearance {:.3g} m)\n",
               clearance.body_a, clearance.body_b, clearance.time, clearance.distance);
  }
}

// Per acceleration probe: its largest whole-run SRS value over the axes, where, and its CSV file.
void print_shock_spectra(std::FILE* out, const results::ShockSpectra& spectra, const std::string& directory) {
  if (spectra.windows.empty()) return;
  fmt::print(out, "shock response spectra: Q {:g}, {:g} to {:g} Hz in 1/6 octaves, {} windows (whole run, start, "
                  "latches; {:g} s each)\n",
             spectra.settings.q, spectra.frequency_hz.front(), spectra.frequency_hz.back(), spectra.windows.size(),
             spectra.settings.window_seconds);
  for (const results::ProbeSpectra& probe : spectra.probes) {
    double peak = 0.0, frequency = 0.0;
    int axis = 0;
    for (int a = 0; a < 3; ++a) {
      Eigen::Index j = 0;
      const double value = probe.windows.front()[static_cast<std::size_t>(a)].maximax.maxCoeff(&j);
      if (value > peak) {
        peak = value;
        frequency = spectra.frequency_hz[static_cast<std::size_t>(j)];
        axis = a;
      }
    }
    fmt::print(out, "  {}: peak {:.4g} g ({:.4g} m/s^2) at {:.4g} Hz, ground {}; {}\n", probe.probe,
               peak / results::kStandardGravity, peak, frequency, "xyz"[axis],
               (std::filesystem::path(directory) / results::shock_spectrum_csv_name(probe.probe)).string());
  }
}

// The static start and the releases, on `out`.
void print_start_and_releases(std::FILE* out, const run::RunSummary& summary) {
  if (summary.statics && summary.statics->status == multibody::StaticsStatus::kOk) {
    fmt::print(out, "start: static equilibrium in {} Newton iterations (force residual {:.3g} of {:.3g})\n",
               summary.statics->iterations, summary.statics->force_residual, summary.statics->force_scale);
  }
  for (const run::JointRelease& release : summary.releases) {
    fmt::print(out, "released: {} at t = {:g} s\n", fmt::join(release.joints, ", "), release.t);
  }
}

// The case, its model, the reduction and geometric stiffening on `text`; the decks' notices
// and the distant-joint warnings on stderr.
void print_case(std::FILE* text, const io::Case& input, const run::CaseRun& prepared) {
  const multibody::Model& model = prepared.mechanism.model;
  fmt::print(text, "limber run: {} ({})\n", input.title, input.file);
  print_model(text, model);
  print_reduction(text, prepared.reduction);
  print_stiffening(text, model);
  // Notes from reading bulk-data decks (cards ignored, approximations).
  for (const io::FlexibleBodyCase& body : input.flexible_bodies) {
    for (const std::string& notice : body.notices) {
      fmt::print(stderr, "limber: notice: body '{}': {}\n", body.name, notice);
    }
  }
  for (const std::string& warning : multibody::distant_joint_warnings(model)) {
    fmt::print(stderr, "limber: warning: {}\n", warning);
  }
}

// The run's callbacks: the start and the events on `text`, warnings on stderr, a progress line
// on a terminal (in `progress`, from the start on), and a stop when a signal was received.
run::RunHooks run_hooks(std::FILE* text, const run::CaseRun& prepared,
                        std::optional<RunProgress>& progress) {
  const multibody::Model& model = prepared.mechanism.model;
  const io::RunSettings& settings = prepared.settings;
  run::RunHooks hooks;
  hooks.on_start = [text, &model, &settings, &progress](const run::PreparedStart& start) {
    print_start(text, model, start);
    fmt::print(text, "integrator: {}; t_end {:g} s, output every {:g} s\n",
               describe_integrator(settings.integrator), settings.t_end, settings.sample_interval);
    std::fflush(text);
    progress.emplace(settings.t_end, true);
  };
  hooks.on_sample = [&progress](const integrate::Sample& sample, const results::Sample&) {
    if (progress) progress->update(sample.t, sample.statistics.steps);
    if (StopSignals::received() != 0) {
      throw run::RunStopped{fmt::format("interrupted by signal {} after t = {:g} s", StopSignals::received(), sample.t)};
    }
  };
  hooks.on_warning = [&progress](const std::string& warning) {
    if (progress) progress->clear();
    fmt::print(stderr, "limber: warning: {}\n", warning);
  };
  hooks.on_event = [text, &model, &progress](const multibody::HingeEvent& event) {
    if (progress) progress->clear();
    fmt::print(text, "event: {}\n", describe_event(model, event));
  };
  return hooks;
}

// Summary on `text`, the run record on stdout with --json, and the exit code: a numerical
// failure (2) or an inaccurate answer (5) said on stderr.
int report_outcome(std::FILE* text, const RunOptions& options, const multibody::Model& model,
                   const run::RunSummary& summary, const std::filesystem::path& directory,
                   const std::string& results_path) {
  const integrate::Statistics& s = summary.statistics;
  print_start_and_releases(text, summary);
  if (summary.failure != "assembly" && summary.failure != "statics") {
    fmt::print(text,
               "{}: t = {:g} s, {} samples, {} steps ({} rejected, {} Newton iterations), "
               "{:.3f} s wall\n",
               summary.ok ? "finished" : "stopped", summary.t_reached, summary.samples, s.steps,
               s.rejected_steps, s.newton_iterations, summary.wall_seconds);
    fmt::print(text, "max constraint violation: position {:.3g}, velocity {:.3g}\n",
               summary.max_position_violation, summary.max_velocity_violation);
    if (summary.ok) print_accuracy(text, summary.accuracy);
    print_clearance(text, summary.clearance);
    print_event_peaks(text, summary.peaks);
    if (summary.shock_spectra) print_shock_spectra(text, *summary.shock_spectra, directory.string());
  }
  fmt::print(text, "wrote {}\n", results_path);
  if (options.json) fmt::print(stdout, "{}\n", run::run_record_json(model, summary, results_path));
  if (!summary.ok) {
    fmt::print(stderr, "limber: error: run failed: {} ({} samples kept in {})\n", summary.message,
               summary.samples, results_path);
    return kExitNumerical;
  }
  if (!summary.accurate()) {
    fmt::print(stderr, "limber: the run finished, but its accuracy estimate says the answer is off "
                       "(status \"ok_inaccurate\" in {}); see the warnings above\n", results_path);
    return kExitInaccurate;
  }
  return kExitOk;
}

int run_case(const RunOptions& options) {
  const io::Case input = io::read_case_file(options.case_file);
  const run::CaseRun prepared = run::prepare_case_run(input, options.overrides, options.modes);

  // Human-readable text on stdout, or on stderr when stdout carries JSON.
  std::FILE* text = options.json ? stderr : stdout;
  print_case(text, input, prepared);

  // Results file, written while the run goes.
  const std::filesystem::path directory =
      options.output_dir.empty()
          ? std::filesystem::path("out") / std::filesystem::path(options.case_file).stem()
          : std::filesystem::path(options.output_dir);
  // Signals are caught from before the file exists, so a stop at any moment closes it.
  const StopSignals stop_signals;
  const std::unique_ptr<results::ResultsWriter> writer = run::open_case_results(directory, input);
  const std::string results_path = writer->path().string();

  // The run, with a progress line on a terminal. A signal or an error mid-run still closes the
  // file, as "interrupted" or "failed".
  std::optional<RunProgress> progress;
  const run::RunHooks hooks = run_hooks(text, prepared, progress);
  run::RunSummary summary;
  try {
    summary = run::run_case(prepared, *writer, hooks);
  } catch (const run::RunStopped& stop) {
    progress.reset();
    fmt::print(stderr, "limber: {} ({} samples kept in {})\n", stop.message, writer->sample_count(),
               results_path);
    return kExitInterrupted;
  } catch (const std::exception&) {
    progress.reset();
    throw;
  }
  progress.reset();
  return report_outcome(text, options, prepared.mechanism.model, summary, directory, results_path);
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cli = app.add_subcommand(
      "run", "Simulate a mechanism (assembly, redundancy, integration); results.h5");
  cli->footer(
      "Prints the model size, the assembly, every redundant constraint equation with the\n"
      "equations it depends on, and a summary; a progress line on a terminal. Writes\n"
      "DIR/results.h5 in blocks of samples, flushed at least every 256 samples or 1 s of wall\n"
      "time (a SIGKILL loses at most those; docs/results-format.md): poses, joint reactions,\n"
      "driver efforts, energies, constraint violations, steps, hinge latch and stop torques and\n"
      "their located events (each also printed as 'event: ...'), and the minimum clearance between\n"
      "bodies' surfaces (shell quads, shapes) when two or more have one: printed at the end,\n"
      "with a warning when it is negative (one body passes through another); flexible bodies\n"
      "with a 'stress' entry get their recovered element stresses (docs/stress-recovery.md);\n"
      "acceleration probes get their accelerations and shock response spectra, also in\n"
      "DIR/srs_<probe>.csv (docs/shock-response-spectrum.md).\n"
      "With --start statics (or 'start: statics' in 'run') the run starts from the static\n"
      "equilibrium (docs/statics.md); joints with a 'release' time (hold-downs) leave the mechanism\n"
      "then, each release printed as 'released: ...'.\n"
      "Settings come from the case's 'run' section (docs/case-format.md); the options below\n"
      "override them.\n"
      "Exit codes: 0 success, 1 bad input (message 'limber: error: case.yaml:LINE:COL: ...'),\n"
      "2 the run failed (assembly did not close, no static equilibrium for a static start, or the\n"
      "integrator stopped; the samples before\n"
      "are kept and the file's status is \"failed\"), 3 internal error, 4 interrupted by SIGINT or\n"
      "SIGTERM (the run stops at its next sample and closes the file as \"interrupted\"; a second\n"
      "signal ends it at once), 5 finished but not accurate: the run's own accuracy estimate\n"
      "('accuracy:' line: energy balance against the energy scale, generalized-alpha's local error,\n"
      "constraint drift; docs/integrators.md) exceeds its threshold; each warning names the option\n"
      "that would fix it, and the file's status is \"ok_inaccurate\".");
  cli->add_option("case", options->case_file, "Case file (YAML, docs/case-format.md)")->required();
  cli->add_option("-o,--output", options->output_dir,
                  "Output directory, created when missing (default: out/<case file stem>)");
  options->overrides.add_options(*cli);
  cli->add_option("--modes", options->modes,
                  "Normal modes of every flexible body (N >= 0) in place of the case's; its static "
                  "modes are kept (limber sweep varies this)");
  cli->add_option("--formulation", options->overrides.formulation,
                  "nonlinear: every flexible body's FE beams unreduced and co-rotational, as if each "
                  "said 'formulation: nonlinear' (docs/nonlinear-beams.md; limber sweep --reference "
                  "nonlinear runs it); modal: the case's own")
      ->check(CLI::IsMember({"modal", "nonlinear"}));
  cli->add_flag("--json", options->json,
                "Print exactly one JSON object on stdout: {\"status\", \"message\", \"integrator\", "
                "\"t_end\", \"t_reached\", \"samples\", \"steps\", \"rejected_steps\", \"newton_failures\", "
                "\"newton_iterations\", \"jacobian_evaluations\", \"residual_evaluations\", \"wall_s\", "
                "\"max_constraint_violation\", "
                "\"max_velocity_violation\", \"redundant\": [equation names], "
                "\"redundant_details\", \"events\": [{\"t\", \"name\", \"kind\", \"joint\", "
                "\"engaged\", \"angle\", \"rate\"} per latch/stop switch], \"statics\": "
                "{\"iterations\", \"force_residual\", \"force_scale\", \"unstable_directions\"} of "
                "a static start or null, \"releases\": [{\"t\", \"joints\"}], \"clearance\": "
                "{\"minimum\", \"time\", \"pair\": [body, body]} or null, \"accuracy\": "
                "{\"energy_relative\", \"energy_residual\", \"energy_scale\", \"local_error\", "
                "\"drift_relative\", \"warnings\"}, \"event_peaks\": {\"window\", \"windows\": [{\"label\", "
                "\"start\", \"end\", \"states\", \"joints\": [{\"joint\", \"force\", \"force_time\", \"torque\", "
                "\"torque_time\", \"force_component\", ...}]}]}, \"results\"}; status is \"ok\", "
                "\"ok_inaccurate\" or \"failed\"; the text goes to stderr");
  return {cli, [options] { return run_case(*options); }};
}

}  // namespace limber::app
