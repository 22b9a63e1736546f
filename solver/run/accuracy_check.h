// The run's own accuracy estimate (`limber run`, docs/integrators.md "Accuracy check"): a fast
// setting must not buy a wrong answer that is reported as success. Three independent measures:
//   energy balance  max |E_bal(t) − E_bal(0)| over the samples, E_bal = kinetic + gravity +
//                   spring + strain + dissipated − driver work − force work (the integrator's
//                   own quadrature of the powers), relative to the run's energy scale (the sum of
//                   each term's largest magnitude): zero for an exact solution of any mechanism;
//   local error     generalized-α's estimate of its steps' local error (generalized_alpha.h),
//                   relative to the largest step increment; IDA controls its own to rtol;
//   constraint drift  the largest position-constraint violation over the samples, relative to
//                   the mechanism's size (the spread of its joint points and body origins at
//                   the start, at least 1 mm).
// A measure above its threshold gives a warning that names the option that would fix it; the
// run's status is then "ok_inaccurate" instead of "ok". So does a flexible body leaving the
// linear range (multibody/linear_range.h; added by run_mechanism): the integration may be
// accurate, but the linear model's answer is not the physical one.
#pragma once

#include <string>
#include <vector>

#include "integrate/integrator_options.h"
#include "integrate/status.h"
#include "results/results_writer.h"

namespace limber::run {

// Thresholds, each a relative measure (docs/integrators.md says how they were chosen).
struct AccuracyThresholds {
  double energy = 1e-2;       // energy balance residual / energy scale
  double local_error = 1e-2;  // generalized-α local error / largest step increment
  double drift = 1e-3;        // position violation / mechanism size
};

struct AccuracyEstimate {
  double energy_residual = 0.0;  // [J]
  double energy_scale = 0.0;     // [J]
  double energy_relative = 0.0;
  double local_error = 0.0;      // generalized-α only, else 0
  double position_violation = 0.0;  // [m or rad]
  double size = 0.0;                // [m]
  double drift_relative = 0.0;
  std::vector<std::string> warnings;  // what is off, by how much, and the option that fixes it

  bool accurate() const { return warnings.empty(); }
};

// Collects the measures sample by sample.
class AccuracyMonitor {
 public:
  void add(const results::Sample& sample);
  // The estimate after the last sample; `statistics` and `options` are the run's.
  // The mechanism's size [m] (the spread of its joint points and body origins at the first
  // sample, at least 1 mm); 0 before it.
  double size() const { return size_; }
  AccuracyEstimate estimate(const integrate::Statistics& statistics,
                            const integrate::IntegratorOptions& options,
                            const AccuracyThresholds& thresholds = {}) const;

 private:
  bool started_ = false;
  double balance_start_ = 0.0;
  double gravity_start_ = 0.0;
  double residual_ = 0.0;
  std::vector<double> term_peaks_;  // largest magnitude of each energy term
  double position_violation_ = 0.0;
  double size_ = 0.0;
};

}  // namespace limber::run
