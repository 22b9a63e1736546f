// The run driver: integrates a MechanicalSystem and hands every output sample to a callback.
#pragma once

#include <functional>
#include <vector>

#include "integrate/integrator.h"

namespace limber::integrate {

struct SimulationResult {
  Status status;          // kOk, or the failure that ended the run (when and why)
  Statistics statistics;  // work done up to the end (or the failure)
  int samples = 0;        // samples delivered to the callback
  double wall_seconds = 0.0;
};

// Most samples a run may ask for (1e8: 800 MB of times alone).
inline constexpr double kMaxSamples = 1e8;

// Output times t0, t0 + dt, ..., up to t_end (the last is t_end itself, even when dt does not
// divide the span). Throws InputError unless dt > 0, t_end ≥ t0 is finite and the samples
// number at most kMaxSamples.
std::vector<double> uniform_sample_times(double t0, double t_end, double dt);

// The checks of uniform_sample_times without building the times (a settings check must not
// allocate 800 MB). Throws InputError (no location: callers that have one catch and place it).
void check_sample_times(double t0, double t_end, double dt);

// Integrates from `start` with the integrator `options.method` and calls on_sample at each of
// `sample_times` (strictly increasing, all ≥ start.t; the run ends at the last one, which
// becomes options.t_stop). Samples are interpolated inside the integrator's steps, never forced
// step ends. On a failure the samples before it have already been delivered and the result's
// status says when and why. Throws InputError on bad options or sample times.
SimulationResult simulate(const MechanicalSystem& system, const IntegratorOptions& options,
                          const InitialState& start, const std::vector<double>& sample_times,
                          const std::function<void(const Sample&)>& on_sample);

}  // namespace limber::integrate
