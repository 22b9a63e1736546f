#include "integrate/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "integrate/combined_statistics.h"

namespace limber::integrate {

SimulationResult simulate(MechanicalSystem& system, const IntegratorOptions& options,
                          const InitialState& start, const SampleTimes& sample_times,
                          const std::function<void(const Sample&)>& on_sample) {
  return simulate(system, options, start, sample_times, on_sample,
                  [](const Sample& sample) { return Status::success(sample.t); });
}

namespace {

double time_tolerance(double t) { return 1e-12 * std::max(1.0, std::abs(t)); }

}  // namespace

SimulationResult simulate(MechanicalSystem& system, const IntegratorOptions& options,
                          const InitialState& start, const SampleTimes& sample_times,
                          const std::function<void(const Sample&)>& on_sample,
                          const std::function<Status(const Sample&)>& check,
                          const Restarts& restarts) {
  const auto wall_start = std::chrono::steady_clock::now();
  // Sample times: from the start on (a SampleTimes is non-empty and increasing).
  if (sample_times.front() < start.t) {
    throw InputError(fmt::format("first sample time: expected ≥ {} (the start), got {}", start.t,
                                 sample_times.front()));
  }
  // Stretches end at the restarts within the run, the last at the last sample.
  std::vector<double> ends;
  for (const double t : restarts.times) {
    if (t >= start.t && t < sample_times.back() - time_tolerance(t)) ends.push_back(t);
  }
  ends.push_back(sample_times.back());

  SimulationResult result;
  InitialState from = start;
  Statistics before;
  Eigen::VectorXd integrals_before = Eigen::VectorXd::Zero(options.quadrature.size);
  Sample sample;
  std::size_t i = 0;  // next sample
  std::size_t stretch = 0;
  while (true) {
    // Integrate no further than the stretch's end.
    IntegratorOptions run_options = options;
    run_options.t_stop = ends[stretch];
    auto integrator = make_integrator(run_options.method);
    result.status = integrator->init(system, from, run_options);
    // The state at time t, with the integrals and work of the stretches before.
    const auto add_before = [&] {
      sample.integrals += integrals_before;
      sample.statistics = combined(before, sample.statistics);
    };
    const auto advance = [&](double t) {
      result.status = integrator->advance_to(t, sample);
      if (result.status.code == StatusCode::kRestartDue) add_before();
      if (!result.status.ok()) return false;
      add_before();
      return true;
    };
    // Deliver every sample of the stretch until its end, a restart at an event or the first
    // failure.
    bool at_end = false;
    for (; result.status.ok() && i < sample_times.size() &&
           sample_times[i] <= ends[stretch] + time_tolerance(ends[stretch]);
         ++i) {
      if (!advance(sample_times[i])) break;
      on_sample(sample);
      ++result.samples;
      at_end = sample_times[i] >= ends[stretch] - time_tolerance(ends[stretch]);
      result.status = check(sample);
    }
    result.statistics = combined(before, integrator->statistics());
    // An event changed the equations (MechanicalSystem::restart_due): restart there, in the
    // same stretch.
    const bool at_event = result.status.code == StatusCode::kRestartDue;
    LIMBER_DEMAND(!at_event || restarts.apply);
    if (!at_event && (!result.status.ok() || stretch + 1 == ends.size())) break;
    // The restart: the state there (served already when it is a sample time), changed.
    if (!at_event && !at_end && !advance(ends[stretch])) break;
    const double t_restart = at_event ? sample.t : ends[stretch];
    restarts.apply(t_restart, sample);
    LIMBER_DEMAND(!system.restart_due());  // or the next integrator would stop at once
    from = {t_restart, sample.q, sample.v};
    integrals_before = sample.integrals;
    before = result.statistics;
    result.status = Status::success(t_restart);
    if (!at_event) ++stretch;
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return result;
}

}  // namespace limber::integrate
