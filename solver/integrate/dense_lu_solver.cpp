#include "integrate/dense_lu_solver.h"

#include <Eigen/LU>
#include <sunmatrix/sunmatrix_dense.h>

#include "core/error.h"

namespace limber::integrate {
namespace {

struct DenseLu {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  int last_flag = SUNLS_SUCCESS;
};

DenseLu& content(SUNLinearSolver solver) { return *static_cast<DenseLu*>(solver->content); }

SUNLinearSolver_Type get_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID get_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }

int setup(SUNLinearSolver solver, SUNMatrix A) {
  DenseLu& s = content(solver);
  const auto n = static_cast<Eigen::Index>(SUNDenseMatrix_Rows(A));
  s.lu.compute(Eigen::Map<const Eigen::MatrixXd>(SUNDenseMatrix_Data(A), n, n));
  // A zero (or non-finite) pivot: singular. No relative threshold: IDA's matrix mixes rows
  // scaled by c_j ~ 1/h with O(1) constraint rows, so its pivots span 14 decades and more.
  const auto pivots = s.lu.matrixLU().diagonal().cwiseAbs();
  const bool singular = !(pivots.minCoeff() > 0.0) || !pivots.allFinite();
  s.last_flag = singular ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
  return s.last_flag;
}

int solve(SUNLinearSolver solver, SUNMatrix A, N_Vector x, N_Vector b, double) {
  DenseLu& s = content(solver);
  const auto n = static_cast<Eigen::Index>(SUNDenseMatrix_Rows(A));
  Eigen::Map<Eigen::VectorXd> x_map(N_VGetArrayPointer(x), n);
  x_map = s.lu.solve(Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(b), n));
  s.last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

sunindextype last_flag(SUNLinearSolver solver) { return content(solver).last_flag; }

int free_solver(SUNLinearSolver solver) {
  if (solver == nullptr) return SUNLS_SUCCESS;
  delete static_cast<DenseLu*>(solver->content);
  solver->content = nullptr;
  SUNLinSolFreeEmpty(solver);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver make_dense_lu_solver(int n, SUNContext context) {
  SUNLinearSolver solver = SUNLinSolNewEmpty(context);
  LIMBER_DEMAND(solver != nullptr);
  solver->ops->gettype = get_type;
  solver->ops->getid = get_id;
  solver->ops->initialize = initialize;
  solver->ops->setup = setup;
  solver->ops->solve = solve;
  solver->ops->lastflag = last_flag;
  solver->ops->free = free_solver;
  solver->content = new DenseLu{Eigen::PartialPivLU<Eigen::MatrixXd>(n), SUNLS_SUCCESS};
  return solver;
}

}  // namespace limber::integrate
