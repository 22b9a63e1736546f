#include "integrate/status.h"

namespace limber::integrate {

const char* to_string(StatusCode code) {
  switch (code) {
    case StatusCode::kOk: return "ok";
    case StatusCode::kErrorTestFailures: return "error_test_failures";
    case StatusCode::kConvergenceFailures: return "convergence_failures";
    case StatusCode::kSingularJacobian: return "singular_jacobian";
    case StatusCode::kNaN: return "nan";
    case StatusCode::kTooManySteps: return "too_many_steps";
    case StatusCode::kWallClock: return "wall_clock";
    case StatusCode::kRedundantViolated: return "redundant_equation_violated";
    case StatusCode::kRestartDue: return "restart_due";
  }
  return "unknown";
}

}  // namespace limber::integrate
