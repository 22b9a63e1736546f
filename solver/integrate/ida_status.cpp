#include "integrate/ida_status.h"

#include <ida/ida.h>

namespace limber::integrate {

StatusCode status_code_of_ida_flag(int flag) {
  switch (flag) {
    case IDA_ERR_FAIL:
    case IDA_TOO_MUCH_ACC:
      return StatusCode::kErrorTestFailures;
    case IDA_LSETUP_FAIL:
    case IDA_LSOLVE_FAIL:
      return StatusCode::kSingularJacobian;
    case IDA_RES_FAIL:
    case IDA_REP_RES_ERR:
    case IDA_FIRST_RES_FAIL:
      return StatusCode::kNaN;
    case IDA_TOO_MUCH_WORK:
      return StatusCode::kTooManySteps;
    default:
      return StatusCode::kConvergenceFailures;
  }
}

}  // namespace limber::integrate
