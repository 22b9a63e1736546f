// The work of a run made of stretches (an integrator restarted after a constraint change or an
// IDA restart): counts add up, the last step is the later stretch's, the largest local error
// the larger of the two.
#pragma once

#include <algorithm>

#include "integrate/status.h"

namespace limber::integrate {

inline Statistics combined(const Statistics& before, const Statistics& after) {
  Statistics out = after;
  out.steps += before.steps;
  out.rejected_steps += before.rejected_steps;
  out.newton_iterations += before.newton_iterations;
  out.newton_failures += before.newton_failures;
  out.jacobian_evaluations += before.jacobian_evaluations;
  out.residual_evaluations += before.residual_evaluations;
  out.max_local_error = std::max(before.max_local_error, after.max_local_error);
  return out;
}

}  // namespace limber::integrate
