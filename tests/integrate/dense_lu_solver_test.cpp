// The dense LU SUNLinearSolver IDA uses (integrate/dense_lu_solver.h): a solution against its
// closed form, backward stability on IDA's scaling, and a singular matrix reported as SUNDIALS'
// dense solver reports it.
#include "integrate/dense_lu_solver.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace limber::integrate {
namespace {

// A SUNDIALS context, dense matrix and vectors of size n, freed at the end of a test.
struct Fixture {
  explicit Fixture(int n) : n(n) {
    SUNContext_Create(nullptr, &context);
    A = SUNDenseMatrix(n, n, context);
    x = N_VNew_Serial(n, context);
    b = N_VNew_Serial(n, context);
    solver = make_dense_lu_solver(n, context);
  }
  ~Fixture() {
    SUNLinSolFree(solver);
    N_VDestroy(b);
    N_VDestroy(x);
    SUNMatDestroy(A);
    SUNContext_Free(&context);
  }
  Eigen::Map<Eigen::MatrixXd> matrix() { return {SUNDenseMatrix_Data(A), n, n}; }
  Eigen::Map<Eigen::VectorXd> vec(N_Vector v) { return {N_VGetArrayPointer(v), n}; }

  int n;
  SUNContext context = nullptr;
  SUNMatrix A = nullptr;
  N_Vector x = nullptr, b = nullptr;
  SUNLinearSolver solver = nullptr;
};

TEST(DenseLuSolver, SolvesASmallSystemExactly) {
  // [2 1; 1 3] x = [3; 5] has x = [0.8; 1.4]; round-off only (bound 1e-15 relative).
  Fixture f(2);
  f.matrix() << 2.0, 1.0, 1.0, 3.0;
  f.vec(f.b) << 3.0, 5.0;
  ASSERT_EQ(SUNLinSolGetType(f.solver), SUNLINEARSOLVER_DIRECT);
  ASSERT_EQ(SUNLinSolSetup(f.solver, f.A), SUNLS_SUCCESS);
  ASSERT_EQ(SUNLinSolSolve(f.solver, f.A, f.x, f.b, 0.0), SUNLS_SUCCESS);
  EXPECT_NEAR(f.vec(f.x)(0), 0.8, 1e-15);
  EXPECT_NEAR(f.vec(f.x)(1), 1.4, 1e-15);
}

TEST(DenseLuSolver, IsBackwardStableOnAnIdaLikeScaling) {
  // A saddle-point matrix scaled like IDA's Newton matrix at a small step: c M (c = 1e7) over
  // O(1) constraint rows, zero block (rank-revealing full pivoting misjudges its rank: its
  // O(1) pivots are 1e-7 of the largest). Partial pivoting is backward stable: the residual
  // ‖J x − b‖ within a small multiple of n ε (‖J‖ ‖x‖ + ‖b‖) (bound 1e-13; n ε = 2e-15).
  const int nv = 6, nc = 3, n = nv + nc;
  Fixture f(n);
  const Eigen::MatrixXd R = Eigen::MatrixXd::Random(nv, nv);
  const Eigen::MatrixXd M = R * R.transpose() + nv * Eigen::MatrixXd::Identity(nv, nv);
  const Eigen::MatrixXd G = Eigen::MatrixXd::Random(nc, nv);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  J.topLeftCorner(nv, nv) = 1e7 * M;
  J.topRightCorner(nv, nc) = G.transpose();
  J.bottomLeftCorner(nc, nv) = G;
  const Eigen::VectorXd rhs = Eigen::VectorXd::Random(n);
  f.matrix() = J;
  f.vec(f.b) = rhs;
  ASSERT_EQ(SUNLinSolSetup(f.solver, f.A), SUNLS_SUCCESS);
  ASSERT_EQ(SUNLinSolSolve(f.solver, f.A, f.x, f.b, 0.0), SUNLS_SUCCESS);
  const Eigen::VectorXd x = f.vec(f.x);
  const double backward_error = (J * x - rhs).norm() / (J.norm() * x.norm() + rhs.norm());
  EXPECT_LT(backward_error, 1e-13);
  // The constraint rows hold to the same relative accuracy.
  EXPECT_LT((G * x.head(nv) - rhs.tail(nc)).norm(), 1e-13 * (G.norm() * x.head(nv).norm() + 1.0));
}

TEST(DenseLuSolver, AZeroPivotIsARecoverableSetupFailure) {
  // A zero column leaves an exactly zero pivot: SUNLS_LUFACT_FAIL (> 0, recoverable), as
  // SUNLinSol_Dense returns; IDA then cuts its step and finally reports IDA_LSETUP_FAIL.
  Fixture f(3);
  f.matrix() << 1.0, 0.0, 2.0, 3.0, 0.0, 1.0, 4.0, 0.0, 5.0;
  EXPECT_EQ(SUNLinSolSetup(f.solver, f.A), SUNLS_LUFACT_FAIL);
  EXPECT_EQ(SUNLinSolLastFlag(f.solver), SUNLS_LUFACT_FAIL);
}

}  // namespace
}  // namespace limber::integrate
