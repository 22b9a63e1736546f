// Our status code for an IDASolve return flag (ida_integrator.h).
#pragma once

#include "integrate/status.h"

namespace limber::integrate {

// Error-test failures, a failed linear solver (singular Newton matrix), residual failures (NaN),
// too much work; every other negative flag counts as convergence failures.
StatusCode status_code_of_ida_flag(int flag);

}  // namespace limber::integrate
