#include "integrate/simulate.h"

#include <chrono>

#include <fmt/format.h>

#include "core/error.h"

namespace limber::integrate {

SimulationResult simulate(const MechanicalSystem& system, const IntegratorOptions& options,
                          const InitialState& start, const SampleTimes& sample_times,
                          const std::function<void(const Sample&)>& on_sample) {
  return simulate(system, options, start, sample_times, on_sample,
                  [](const Sample& sample) { return Status::success(sample.t); });
}

SimulationResult simulate(const MechanicalSystem& system, const IntegratorOptions& options,
                          const InitialState& start, const SampleTimes& sample_times,
                          const std::function<void(const Sample&)>& on_sample,
                          const std::function<Status(const Sample&)>& check) {
  const auto wall_start = std::chrono::steady_clock::now();
  // Sample times: from the start on (a SampleTimes is non-empty and increasing).
  if (sample_times.front() < start.t) {
    throw InputError(fmt::format("first sample time: expected ≥ {} (the start), got {}", start.t,
                                 sample_times.front()));
  }

  // Integrate no further than the last sample.
  IntegratorOptions run_options = options;
  run_options.t_stop = sample_times.back();
  auto integrator = make_integrator(run_options.method);
  SimulationResult result;
  result.status = integrator->init(system, start, run_options);

  // Deliver every sample until the end or the first failure.
  Sample sample;
  for (std::size_t i = 0; i < sample_times.size(); ++i) {
    if (!result.status.ok()) break;
    result.status = integrator->advance_to(sample_times[i], sample);
    if (!result.status.ok()) break;
    on_sample(sample);
    ++result.samples;
    result.status = check(sample);
  }
  result.statistics = integrator->statistics();
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return result;
}

}  // namespace limber::integrate
