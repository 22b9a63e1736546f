#include "io/run_settings_reader.h"

#include <string>

#include "integrate/sample_times.h"

namespace limber::io {

RunSettings read_run_settings(const YamlValue& entry) {
  entry.allow_only({"integrator", "rtol", "atol", "max_step", "step", "event_step", "event_window", "rho_inf",
                    "max_steps", "max_wall",
                    "max_order", "newton_matrix", "event_tolerance", "t_end", "sample_interval", "start",
                    "peak_window"});
  RunSettings settings;
  integrate::IntegratorOptions& options = settings.integrator;
  // Integrator and its settings (those of the other integrator are allowed and kept).
  if (const auto method = entry.find("integrator")) {
    options.method = method->as_choice({"ida", "galpha"}) == "galpha"
                         ? integrate::Method::kGeneralizedAlpha
                         : integrate::Method::kIda;
  }
  if (const auto rtol = entry.find("rtol")) {
    options.rtol = rtol->as_positive();
    if (!(options.rtol < 1.0)) {
      rtol->fail("expected 0 < rtol < 1 for 'rtol', got '" + rtol->node().Scalar() + "'");
    }
  }
  if (const auto atol = entry.find("atol")) options.atol = atol->as_positive();
  if (const auto max_step = entry.find("max_step")) options.max_step = max_step->as_non_negative();
  if (const auto step = entry.find("step")) options.step = step->as_positive();
  if (const auto event_step = entry.find("event_step")) {
    options.event_step = event_step->as_positive();
    const auto window = entry.find("event_window");
    if (!window) {
      event_step->fail("expected 'event_window' beside 'event_step' (how long after the start and after every "
                       "event the event step applies)");
    }
    options.event_window = window->as_positive();
  }
  if (const auto rho = entry.find("rho_inf")) {
    options.rho_inf = rho->as_non_negative();
    if (options.rho_inf > 1.0) {
      rho->fail("expected 0 <= rho_inf <= 1 for 'rho_inf', got '" + rho->node().Scalar() + "'");
    }
  }
  if (const auto order = entry.find("max_order")) {
    options.max_order = order->as_positive_integer();
    if (options.max_order > 5) {
      order->fail("expected 1 <= max_order <= 5 for 'max_order', got '" + order->node().Scalar() + "'");
    }
  }
  if (const auto matrix = entry.find("newton_matrix")) {
    options.ida_newton_matrix = matrix->as_choice({"differences", "structured"}) == "structured"
                                    ? integrate::IdaNewtonMatrix::kStructured
                                    : integrate::IdaNewtonMatrix::kDifferences;
  }
  if (const auto budget = entry.find("max_steps")) options.max_steps = budget->as_positive_integer();
  if (const auto wall = entry.find("max_wall")) options.max_wall_seconds = wall->as_positive();
  if (const auto events = entry.find("event_tolerance")) options.event_tolerance = events->as_positive();
  if (const auto start = entry.find("start")) {
    settings.start = start->as_choice({"assembly", "statics"}) == "statics" ? StartKind::kStatics
                                                                            : StartKind::kAssembly;
  }
  // Time span and output.
  if (const auto t_end = entry.find("t_end")) settings.t_end = t_end->as_non_negative();
  const auto interval = entry.find("sample_interval");
  if (interval) settings.sample_interval = interval->as_positive();
  if (const auto window = entry.find("peak_window")) settings.peak_window = window->as_non_negative();
  // The number of samples, bounded (integrate::kMaxSamples): at the interval, else the end time.
  try {
    integrate::check_sample_times(0.0, settings.t_end, settings.sample_interval);
  } catch (const InputError& e) {
    const auto t_end = entry.find("t_end");
    (interval ? *interval : t_end ? *t_end : entry).fail(e.message());
  }
  return settings;
}

}  // namespace limber::io
