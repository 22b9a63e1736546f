// The run driver: integrates a MechanicalSystem and hands every output sample to a callback.
#pragma once

#include <functional>
#include <vector>

#include "integrate/integrator.h"
#include "integrate/sample_times.h"

namespace limber::integrate {

struct SimulationResult {
  Status status;          // kOk, or the failure that ended the run (when and why)
  Statistics statistics;  // work done up to the end (or the failure)
  int samples = 0;        // samples delivered to the callback
  double wall_seconds = 0.0;
};

// Integrates from `start` with the integrator `options.method` and calls on_sample at each of
// `sample_times` (all ≥ start.t; the run ends at the last one, which becomes options.t_stop). Samples are interpolated inside the integrator's steps, never forced
// step ends. On a failure the samples before it have already been delivered and the result's
// status says when and why. Throws InputError on bad options or a first sample before the start.
SimulationResult simulate(MechanicalSystem& system, const IntegratorOptions& options,
                          const InitialState& start, const SampleTimes& sample_times,
                          const std::function<void(const Sample&)>& on_sample);

// Times where the system changes its constraint set (a hold-down released: nc changes) and
// the change. At each time (ascending; those before the start or at or after the last sample
// are ignored) the integrator stops exactly there, `apply` gets the time and the state reached
// (a sample time or not), and a new integrator starts from it. Integrals
// (IntegratorOptions::quadrature) and statistics run on across restarts. `apply` is also called
// at a located event after which the system's equations change (MechanicalSystem::restart_due,
// a joint released at an event), with the state there; it must then leave restart_due() false.
struct Restarts {
  std::vector<double> times;
  std::function<void(double t, const Sample& state)> apply;
};

// As above; after each delivered sample `check` judges it, and a status it returns that is not
// ok ends the run with that status (the sample judged has been delivered).
SimulationResult simulate(MechanicalSystem& system, const IntegratorOptions& options,
                          const InitialState& start, const SampleTimes& sample_times,
                          const std::function<void(const Sample&)>& on_sample,
                          const std::function<Status(const Sample&)>& check,
                          const Restarts& restarts = {});

}  // namespace limber::integrate
