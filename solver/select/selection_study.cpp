#include "select/selection_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include <fmt/format.h>

#include "core/error.h"
#include "results/results_writer.h"
#include "select/job_queue.h"
#include "select/series_error.h"

namespace limber::select {

namespace {

constexpr const char* kAxisNames = "xyz";

// Bodies (model indices) with a deflection probe, in model order.
std::vector<int> probed_bodies(const multibody::Model& model) {
  std::vector<int> bodies;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const multibody::Body& body = model.bodies[b];
    if (body.flexible && body.flexible->deflection_probe) bodies.push_back(static_cast<int>(b));
  }
  return bodies;
}

// Rows of `rows` (each a vector of equal length) as a matrix.
Eigen::MatrixXd stack(const std::vector<Eigen::VectorXd>& rows, Eigen::Index columns) {
  Eigen::MatrixXd matrix(static_cast<Eigen::Index>(rows.size()), columns);
  for (std::size_t r = 0; r < rows.size(); ++r) matrix.row(static_cast<Eigen::Index>(r)) = rows[r].transpose();
  return matrix;
}

// This thread's CPU time [s]. A run is single-threaded, so the difference over it is its own cost
// while other runs share the cores (a wall time then says more about the load than the run).
double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

io::RunSettings candidate_settings(const io::Mechanism& mechanism, const SettingsAdjustment& adjust,
                                   const StepPolicy& policy, StepChoice& step) {
  io::RunSettings settings = adjust ? adjust(mechanism.run) : mechanism.run;
  // Event peaks always (peak_comparison.h).
  if (settings.peak_window == 0.0) settings.peak_window = kSelectPeakWindow;
  // The step that resolves the set's highest frequency (step_choice.h).
  step = choose_step(highest_frequency(mechanism.model), settings.integrator, policy, settings.peak_window);
  settings.integrator = apply_step(settings.integrator, step);
  run::check_settings(settings);
  return settings;
}

void run_mechanism_recorded(const io::Case& input, const io::Mechanism& mechanism, const io::RunSettings& settings,
                            const std::string& title, const run::RestartPoint* restart,
                            const std::function<void(const integrate::Sample&)>& on_sample, CandidateRun& run,
                            const multibody::Model* columns) {
  const multibody::Model& model = mechanism.model;
  // Every sample's reactions on the flexible bodies and deflections, kept in memory, in the
  // columns of `layout`: its bodies and joints are the recorded ones.
  const multibody::Model& layout = columns ? *columns : model;
  const std::vector<JointOnFlexibleBody> sites = joints_on_flexible_bodies(layout);
  const std::vector<int> probed = probed_bodies(layout);
  run.probed.clear();
  for (const int body : probed) run.probed.push_back(layout.bodies[static_cast<std::size_t>(body)].name);
  run.indeterminate.assign(sites.size(), false);
  std::vector<double> times;
  std::vector<Eigen::VectorXd> reactions, deflections;
  results::ResultsWriter writer(run.directory, input.title + " [" + title + "]", input.file);
  if (input.axis_names.size() == 3) {
    writer.set_axis_names({input.axis_names[0], input.axis_names[1], input.axis_names[2]});
  }
  run::RunHooks hooks;
  hooks.writer = &writer;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    // Sample bodies leave out ground.
    LIMBER_DEMAND(record.bodies.size() + 1 == layout.bodies.size() && record.joints.size() == layout.joints.size());
    times.push_back(record.time);
    Eigen::VectorXd r(6 * static_cast<Eigen::Index>(sites.size()));
    for (std::size_t s = 0; s < sites.size(); ++s) {
      r.segment<6>(6 * static_cast<Eigen::Index>(s)) = reaction_on_body(sites[s], record);
      if (record.joints[static_cast<std::size_t>(sites[s].joint)].indeterminate) run.indeterminate[s] = true;
    }
    reactions.push_back(r);
    Eigen::VectorXd d(3 * static_cast<Eigen::Index>(probed.size()));
    for (std::size_t p = 0; p < probed.size(); ++p) {
      d.segment<3>(3 * static_cast<Eigen::Index>(p)) =
          record.bodies[static_cast<std::size_t>(probed[p] - 1)].deflection;
    }
    deflections.push_back(d);
    if (on_sample) on_sample(sample);
  };
  hooks.on_window = [&](const run::WindowRestart& window) { run.window_restarts.push_back(window); };
  const double cpu_start = thread_cpu_seconds();
  try {
    run.summary = run::run_mechanism(model, mechanism.assembly, settings, hooks, restart);
    run.cpu_seconds = thread_cpu_seconds() - cpu_start;
  } catch (const SelectionInterrupted&) {
    writer.finish(results::RunStatus::kInterrupted, "selection interrupted by a signal");
    throw;
  } catch (const std::exception& error) {
    writer.finish(results::RunStatus::kFailed, error.what());
    throw;
  }
  run.time = Eigen::Map<const Eigen::VectorXd>(times.data(), static_cast<Eigen::Index>(times.size()));
  run.reactions = stack(reactions, 6 * static_cast<Eigen::Index>(sites.size()));
  run.deflections = stack(deflections, 3 * static_cast<Eigen::Index>(probed.size()));
}

CandidateRun prepare_candidate(std::shared_ptr<const io::Case> input, const ModeSetCandidate& candidate,
                               const std::filesystem::path& directory) {
  CandidateRun result;
  result.candidate = candidate;
  result.directory = directory;
  if (!input->mechanism) {
    throw InputError("expected a mechanism (a 'bodies' section), got none", SourceLocation{input->file, 0, 0});
  }
  result.input = input;
  // The set's modes, then its model.
  result.reduction = io::reduce_case(*input, io::ReductionScope::kMechanismBodies, candidate.requests);
  for (const io::BodyReduction& body : result.reduction.bodies) {
    result.reduction_seconds += body.seconds;
    for (const std::string& notice : body.result.notices) result.notices.push_back(body.name + ": " + notice);
  }
  result.mechanism = io::build_mechanism(*input, result.reduction);
  for (const multibody::Body& body : result.mechanism.model.bodies) {
    if (body.flexible) result.modes += static_cast<int>(body.flexible->shapes.cols());
  }
  return result;
}

CandidateRun run_candidate(std::shared_ptr<const io::Case> input, const ModeSetCandidate& candidate,
                           const SettingsAdjustment& adjust, const StepPolicy& policy,
                           const std::filesystem::path& directory,
                           const std::function<void(const integrate::Sample&)>& on_sample,
                           const multibody::Model* columns) {
  CandidateRun result = prepare_candidate(input, candidate, directory);
  const io::RunSettings settings = candidate_settings(result.mechanism, adjust, policy, result.step);
  run_mechanism_recorded(*input, result.mechanism, settings, candidate.name, nullptr, on_sample, result, columns);
  return result;
}

void run_parallel(std::size_t count, int workers, const std::function<void(std::size_t)>& job) {
  JobQueue queue;
  for (std::size_t k = 0; k < count; ++k) queue.push_back([&job, k](JobQueue&) { job(k); });
  queue.run(static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(workers, 1)), std::max<std::size_t>(count, 1))));
}

std::vector<KeyQuantity> key_quantities(const std::vector<RankedComponent>& ranking,
                                        const CandidateRun& reference) {
  std::vector<KeyQuantity> keys;
  for (const RankedComponent& component : ranking) {
    if (component.kept) keys.push_back({component.description(), false, 6 * component.site_index + component.column()});
  }
  const std::vector<std::string>& probed = reference.probed;
  for (std::size_t p = 0; p < probed.size(); ++p) {
    const auto columns = reference.deflections.middleCols(3 * static_cast<Eigen::Index>(p), 3);
    if (columns.rows() == 0) continue;
    const Eigen::Vector3d peaks = columns.cwiseAbs().colwise().maxCoeff().transpose();
    for (int axis = 0; axis < 3; ++axis) {
      if (peaks(axis) > 0.0 && peaks(axis) >= 0.01 * peaks.maxCoeff()) {
        keys.push_back({fmt::format("{} deflection {} [m]", probed[p], kAxisNames[axis]),
                        true, 3 * static_cast<int>(p) + axis});
      }
    }
  }
  return keys;
}

Eigen::VectorXd key_series(const CandidateRun& run, const KeyQuantity& quantity) {
  return quantity.deflection ? Eigen::VectorXd(run.deflections.col(quantity.column))
                             : Eigen::VectorXd(run.reactions.col(quantity.column));
}

ReleaseTimes joint_release_times(const multibody::Model& model, const run::RunSummary& run) {
  ReleaseTimes times;
  for (const multibody::Joint& joint : model.joints) {
    if (std::isfinite(joint.release_time)) times[joint.name] = joint.release_time;
  }
  for (const run::JointRelease& release : run.releases) {
    for (const std::string& joint : release.joints) times.emplace(joint, release.t);
  }
  return times;
}

void compare_runs(std::vector<CandidateRun>& runs, const std::vector<KeyQuantity>& keys) {
  const auto reference = std::find_if(runs.begin(), runs.end(),
                                      [](const CandidateRun& r) { return r.candidate.reference; });
  if (reference == runs.end() || !reference->ok()) return;
  for (CandidateRun& run : runs) {
    if (run.candidate.reference || !run.ok()) continue;
    if (run.time.size() == 0) continue;
    run.peaks = compare_peaks(run.summary.peaks, reference->summary.peaks,
                              joint_release_times(reference->mechanism.model, reference->summary));
    run.error_peak = run.error_rms = 0.0;
    double worst = -1.0;
    for (const KeyQuantity& key : keys) {
      // On the reference's samples (the same times: both runs share the case's settings).
      const SeriesError error = series_error(run.time, key_series(run, key), reference->time,
                                             key_series(*reference, key));
      if (std::isnan(error.peak)) continue;
      const double peak = error.peak;
      const double rms = error.rms;
      run.error_peak = std::max(run.error_peak, peak);
      run.error_rms = std::max(run.error_rms, rms);
      if (std::max(peak, rms) > worst) {
        worst = std::max(peak, rms);
        run.worst_quantity = key.name;
      }
    }
  }
}

std::optional<std::size_t> choose_run(const std::vector<CandidateRun>& runs,
                                      std::optional<double> target, ErrorNorm norm) {
  std::optional<std::size_t> chosen;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const CandidateRun& run = runs[k];
    if (!target) {
      if (run.candidate.name == "kept") return k;
      continue;
    }
    // A set whose own accuracy check failed is never the answer.
    if (run.candidate.reference || !run.summary.accurate() || !run.step.resolved || !(run.error(norm) <= *target)) {
      continue;
    }
    if (!chosen || run.modes < runs[*chosen].modes ||
        (run.modes == runs[*chosen].modes && run.summary.wall_seconds < runs[*chosen].summary.wall_seconds)) {
      chosen = k;
    }
  }
  return chosen;
}

}  // namespace limber::select
