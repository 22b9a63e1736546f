// A SUNDIALS direct linear solver (SUNLinearSolver) on a dense SUNMatrix, factorised by Eigen's
// blocked LU with partial pivoting. SUNDIALS' own SUNLinSol_Dense factorises and solves with
// unblocked column loops; on IDA's ~95 x 95 Newton matrix of the seed slider-crank they were
// 39 % of the run (16 % factorising, 22 % solving), Eigen's vectorised kernels a fraction of it
// (docs/benchmarks.md).
// A zero or non-finite pivot makes setup return SUNLS_LUFACT_FAIL (recoverable: IDA retries
// with a smaller step, then fails with IDA_LSETUP_FAIL), as SUNLinSol_Dense does. No relative
// threshold: IDA's matrix mixes rows scaled by c_j ~ 1/h with O(1) constraint rows.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

namespace limber::integrate {

// A new solver for n x n dense matrices; free it with SUNLinSolFree.
SUNLinearSolver make_dense_lu_solver(int n, SUNContext context);

}  // namespace limber::integrate
