#include "integrate/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"

namespace limber::integrate {

void check_sample_times(double t0, double t_end, double dt) {
  if (!(dt > 0.0)) throw InputError(fmt::format("sample interval: expected > 0, got {}", dt));
  if (!(t_end >= t0) || !std::isfinite(t_end)) {
    throw InputError(fmt::format("end time: expected a finite time ≥ {} (the start), got {}", t0, t_end));
  }
  // Every sample is held in memory and written to the results file: bound their number
  // before the count is cast (an end time of 1e308 s overflowed it and crashed).
  const double count = std::floor((t_end - t0) / dt);
  if (!(count <= kMaxSamples)) {
    throw InputError(fmt::format("number of samples (end time {} s / sample interval {} s): expected "
                                 "at most {:g}, got {:g}; choose a larger sample interval",
                                 t_end - t0, dt, kMaxSamples, count));
  }
}

std::vector<double> uniform_sample_times(double t0, double t_end, double dt) {
  check_sample_times(t0, t_end, dt);
  // Multiples of dt (no accumulated round-off); a last interval shorter than 1e-9 dt is merged.
  std::vector<double> times;
  const long n = static_cast<long>(std::floor((t_end - t0) / dt * (1.0 + 1e-12)));
  for (long i = 0; i <= n; ++i) times.push_back(std::min(t0 + static_cast<double>(i) * dt, t_end));
  if (t_end - times.back() > 1e-9 * dt) {
    times.push_back(t_end);
  } else {
    times.back() = t_end;
  }
  return times;
}

SimulationResult simulate(const MechanicalSystem& system, const IntegratorOptions& options,
                          const InitialState& start, const std::vector<double>& sample_times,
                          const std::function<void(const Sample&)>& on_sample) {
  const auto wall_start = std::chrono::steady_clock::now();
  // Sample times: non-empty, from the start on, strictly increasing.
  if (sample_times.empty()) throw InputError("sample times: expected at least one, got none");
  if (sample_times.front() < start.t) {
    throw InputError(fmt::format("first sample time: expected ≥ {} (the start), got {}", start.t,
                                 sample_times.front()));
  }
  for (size_t i = 1; i < sample_times.size(); ++i) {
    if (!(sample_times[i] > sample_times[i - 1])) {
      throw InputError(fmt::format("sample time {}: expected > {} (strictly increasing), got {}",
                                   i, sample_times[i - 1], sample_times[i]));
    }
  }

  // Integrate no further than the last sample.
  IntegratorOptions run_options = options;
  run_options.t_stop = sample_times.back();
  auto integrator = make_integrator(run_options.method);
  SimulationResult result;
  result.status = integrator->init(system, start, run_options);

  // Deliver every sample until the end or the first failure.
  Sample sample;
  for (const double t : sample_times) {
    if (!result.status.ok()) break;
    result.status = integrator->advance_to(t, sample);
    if (!result.status.ok()) break;
    on_sample(sample);
    ++result.samples;
  }
  result.statistics = integrator->statistics();
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return result;
}

}  // namespace limber::integrate
