#include "integrate/integrator.h"

#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "integrate/generalized_alpha.h"
#include "integrate/ida_integrator.h"

namespace limber::integrate {
namespace {

// Throws "<what>: expected <expected>, got <value>" unless ok.
void demand_input(bool ok, const char* what, const char* expected, double value) {
  if (!ok) throw InputError(fmt::format("{}: expected {}, got {}", what, expected, value));
}

}  // namespace

const char* to_string(Method method) {
  switch (method) {
    case Method::kIda: return "ida";
    case Method::kGeneralizedAlpha: return "galpha";
  }
  return "unknown";
}

IntegratorOptions IntegratorOptions::ida(double rtol, double atol) {
  IntegratorOptions options;
  options.method = Method::kIda;
  options.rtol = rtol;
  options.atol = atol;
  return options;
}

IntegratorOptions IntegratorOptions::generalized_alpha(double step, double rho_inf) {
  IntegratorOptions options;
  options.method = Method::kGeneralizedAlpha;
  options.step = step;
  options.rho_inf = rho_inf;
  return options;
}

IntegratorOptions IntegratorOptions::trapezoidal(double step) {
  return generalized_alpha(step, 1.0);
}

void IntegratorOptions::validate() const {
  demand_input(rtol > 0.0 && rtol < 1.0, "integrator rtol", "0 < rtol < 1", rtol);
  demand_input(atol > 0.0 && std::isfinite(atol), "integrator atol", "atol > 0", atol);
  demand_input(max_wall_seconds > 0.0, "integrator max_wall", "> 0 s", max_wall_seconds);
  demand_input(max_step >= 0.0, "integrator max_step", "max_step ≥ 0 (0: none)", max_step);
  demand_input(initial_step >= 0.0, "integrator initial_step", "initial_step ≥ 0 (0: automatic)",
               initial_step);
  demand_input(step > 0.0 && std::isfinite(step), "integrator step", "step > 0", step);
  demand_input(event_step >= 0.0 && std::isfinite(event_step), "integrator event_step",
               "event_step ≥ 0 (0: none)", event_step);
  demand_input(event_window >= 0.0 && std::isfinite(event_window), "integrator event_window",
               "event_window ≥ 0 (0: none)", event_window);
  demand_input(max_order >= 0 && max_order <= 5, "integrator max_order", "1 to 5 (0: 5)",
               max_order);
  demand_input(rho_inf >= 0.0 && rho_inf <= 1.0, "integrator rho_inf", "0 ≤ rho_inf ≤ 1",
               rho_inf);
  demand_input(max_newton_iterations >= 1, "integrator max_newton_iterations", "at least 1",
               max_newton_iterations);
  demand_input(newton_tolerance > 0.0 && newton_tolerance < 1.0, "integrator newton_tolerance",
               "0 < newton_tolerance < 1", newton_tolerance);
  demand_input(max_step_halvings >= 0, "integrator max_step_halvings", "≥ 0", max_step_halvings);
  demand_input(event_tolerance > 0.0, "integrator event_tolerance", "> 0", event_tolerance);
  demand_input(max_steps >= 1, "integrator max_steps", "at least 1",
               static_cast<double>(max_steps));
  demand_input(quadrature.size >= 0, "quadrature size", "≥ 0", quadrature.size);
  demand_input(quadrature.atol >= 0.0, "quadrature atol", "≥ 0", quadrature.atol);
  if (quadrature.size > 0 && !quadrature.integrand) {
    throw InputError(fmt::format("quadrature: expected an integrand for {} integrals, got none",
                                 quadrature.size));
  }
}

std::unique_ptr<Integrator> make_integrator(Method method) {
  switch (method) {
    case Method::kIda: return std::make_unique<IdaIntegrator>();
    case Method::kGeneralizedAlpha: return std::make_unique<GeneralizedAlpha>();
  }
  demand_failed("known integration method", __FILE__, __LINE__);
}

}  // namespace limber::integrate
