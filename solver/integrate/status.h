// What an integrator reports back (house style §11: numerical non-convergence is a returned
// status the caller must handle, never an exception and never a silently accepted step).
#pragma once

#include <string>

namespace limber::integrate {

enum class StatusCode {
  kOk,
  kErrorTestFailures,    // repeated local-error-test failures (IDA)
  kConvergenceFailures,  // Newton failed repeatedly, also after step reduction
  kSingularJacobian,     // the iteration matrix could not be factorised
  kNaN,                  // the model returned non-finite values
  kTooManySteps,         // the step budget (IntegratorOptions::max_steps) ran out
  kWallClock,            // the wall-clock budget (IntegratorOptions::max_wall_seconds) ran out
  kRedundantViolated,    // a redundant equation the run does not hold came loose (run/redundant_row_watch.h)
  kRestartDue,           // not a failure: the system's equations change at a located event
                         // (MechanicalSystem::restart_due); `out` holds the state there and the
                         // caller restarts (simulate.h). Never leaves integrate::simulate.
};

// "ok", "error_test_failures", ... (stable names, used in results files and --json).
const char* to_string(StatusCode code);

struct Status {
  StatusCode code = StatusCode::kOk;
  double t = 0.0;       // time reached when the status was raised [s]
  std::string message;  // when and why, e.g. "at t = 0.4137 s: Newton did not converge ..."

  bool ok() const { return code == StatusCode::kOk; }
  static Status success(double t) { return {StatusCode::kOk, t, {}}; }
};

// Work counters, cumulative since init().
struct Statistics {
  long steps = 0;                 // accepted steps
  long rejected_steps = 0;        // error-test failures plus Newton failures
  long newton_iterations = 0;
  long newton_failures = 0;       // nonlinear convergence failures (each rejects a step)
  long jacobian_evaluations = 0;  // iteration-matrix evaluations
  long residual_evaluations = 0;  // evaluations of M, Q and the constraints (incl. for Jacobians)
  double last_step = 0.0;         // size of the last accepted step [s]
  // Generalized-α only: the largest local error estimate of a step's position increment over
  // the run, relative to the run's largest increment (generalized_alpha.h); IDA's error test keeps its own
  // local error within rtol, and leaves this 0.
  double max_local_error = 0.0;
};

}  // namespace limber::integrate
