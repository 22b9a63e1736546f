#include "select/step_choice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace limber::select {

double highest_frequency(const multibody::Model& model) {
  double f_max = 0.0;
  for (const multibody::Body& body : model.bodies) {
    if (!body.flexible || body.flexible->stiffness.size() == 0) continue;
    f_max = std::max(f_max, std::sqrt(std::max(0.0, body.flexible->stiffness.maxCoeff())) / (2.0 * std::numbers::pi));
  }
  return f_max;
}

StepChoice choose_step(double f_max, const integrate::IntegratorOptions& options, const StepPolicy& policy,
                       double event_window) {
  StepChoice choice;
  choice.f_max = f_max;
  choice.needed = f_max > 0.0 ? 1.0 / (kStepsPerPeriod * f_max) : 0.0;
  const bool galpha = options.method == integrate::Method::kGeneralizedAlpha;
  // The case's bound on the step: gen-α's step, IDA's max_step (0: none).
  const double case_step = galpha ? options.step : options.max_step;
  if (policy.keep_case_step || choice.needed == 0.0) {
    choice.step = case_step;
  } else {
    // At most max_refinement times shorter than the case's (IDA without a max_step: no floor).
    const double floor = case_step / policy.max_refinement;
    const double bound = case_step > 0.0 ? std::min(case_step, choice.needed) : choice.needed;
    choice.step = std::max(bound, floor);
  }
  if (galpha && !policy.whole_run && event_window > 0.0 && choice.step < case_step) {
    choice.window = event_window;
    choice.outside_step = case_step * policy.scale;
  }
  choice.step *= policy.scale;
  choice.steps_per_period = choice.step > 0.0 && f_max > 0.0 ? 1.0 / (choice.step * f_max)
                                                              : std::numeric_limits<double>::infinity();
  // A relative slack of 1e-9 for the round trip through 1 / (N f_max).
  choice.resolved = choice.needed == 0.0 || (choice.step > 0.0 && choice.step <= choice.needed * (1.0 + 1e-9));
  return choice;
}

integrate::IntegratorOptions apply_step(integrate::IntegratorOptions options, const StepChoice& choice) {
  if (options.method == integrate::Method::kGeneralizedAlpha && choice.window > 0.0) {
    options.step = choice.outside_step;
    options.event_step = choice.step;
    options.event_window = choice.window;
  } else if (options.method == integrate::Method::kGeneralizedAlpha) {
    options.step = choice.step;
  } else {
    options.max_step = choice.step;
  }
  return options;
}

}  // namespace limber::select
