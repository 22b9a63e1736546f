// Lowest eigenpairs of the symmetric generalized problem K phi = lambda M phi
// (seed paper eq. 4) with ARPACK's implicitly restarted Lanczos method (Lehoucq, Sorensen &
// Yang, "ARPACK Users' Guide", SIAM 1998) on the shift-invert spectral transformation
// (Ericsson & Ruhe, Math. Comp. 35, 1980) in its symmetric form: with the Cholesky factor
// P (K - sigma M) P^T = L L^T (CHOLMOD, supernodal; shifted_factor.h), the operator
//   C = L^-1 P M P^T L^-T,  C w = theta w,  lambda = sigma + 1 / theta,  phi = P^T L^-T w,
// is symmetric in the Euclidean inner product, so ARPACK runs in mode 1 (standard problem):
// the same Krylov space and Ritz values as mode 3 with OP = (K - sigma M)^-1 M, but one
// product with M per Lanczos step instead of three (mode 3's M-inner products). Its largest
// theta belong to the lambda nearest above sigma. With sigma < 0, K positive semi-definite
// and M positive definite, K - sigma M is SPD even for free components. A problem restricted
// to a DOF subset (the free DOFs of a held component) is solved without copying K_ff or
// M_ff: products and norms go through the full matrices.
//
// Problems too small for ARPACK (2 nev >= n) are solved densely (Eigen's
// GeneralizedSelfAdjointEigenSolver), which gives the same result to round-off.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "modal/modal_status.h"

namespace limber::modal {

// Default ARPACK tolerance (EigenSolverOptions::tolerance).
inline constexpr double kDefaultTolerance = 1e-10;

struct EigenSolverOptions {
  // Shift sigma [1/s^2]. Default: -kDefaultShiftFactor x max_i(K_ii / M_ii), a negative
  // shift far below the lowest elastic eigenvalue of FE models yet large enough for a
  // stable Cholesky of K - sigma M when K has rigid-body null vectors.
  std::optional<double> shift;
  // Lanczos basis size; 0 chooses min(n, max(2 nev + 1, nev + 20)).
  int basis_size = 0;
  // ARPACK convergence tolerance on the Ritz estimates; 0 means machine precision.
  // ARPACK stops when every wanted Ritz pair has ||C w - theta w|| <= tol |theta|. C is
  // symmetric, so each theta lies within that residual of an eigenvalue of C (the
  // residual bound for self-adjoint operators, Krylov-Weinstein), and lambda - sigma =
  // 1/theta is then relatively accurate to tol: with sigma <= 0, lambda to tol and the
  // frequency to tol / 2, whatever the gaps. The actual error is of order ||r||^2 / gap
  // (Kato-Temple bound), far below.
  // 1e-10 stops the Lanczos iteration a quarter of the operator applications earlier than
  // machine precision; on the benchmark plates (61k DOFs, 10 modes; 252k DOFs, 20 modes) the
  // Ritz frequencies did not change in their 11 printed digits (docs/benchmarks.md; bound
  // tested in tests/modal/test_restricted_eigensolver.cpp).
  double tolerance = kDefaultTolerance;
  int max_iterations = 1000;
};

// sigma = -kDefaultShiftFactor x max(K_ii / M_ii).
inline constexpr double kDefaultShiftFactor = 1e-12;

struct EigenSolution {
  ModalStatus status = ModalStatus::kOk;
  std::string message;       // failure explanation (ARPACK info code, factorisation), or ""
  int arpack_info = 0;       // dsaupd/dseupd info (0 when fine or solved densely)
  double shift = 0.0;        // sigma used [1/s^2]
  Eigen::VectorXd eigenvalues;  // nev, ascending lambda = omega^2 [1/s^2]
  Eigen::MatrixXd vectors;      // n x nev, columns M-normalised: phi_i^T M phi_i = 1
  // Largest normwise backward error of the pairs (Higham & Higham, "Structured backward
  // error and condition of generalized eigenvalue problems", SIMAX 20, 1998):
  //   max_i ||K phi_i - lambda_i M phi_i||_1 / ((||K||_1 + |lambda_i| ||M||_1) ||phi_i||_1).
  // A backward-stable solution has a few machine epsilons.
  double max_backward_error = 0.0;
  // Wall time [s] of the Cholesky factorisation and of the Lanczos iteration (dsaupd loop
  // and dseupd), for benchmarks; 0 for the dense path.
  double factorisation_seconds = 0.0;
  double lanczos_seconds = 0.0;
  int operator_applications = 0;  // applications of C in the Lanczos iteration (ARPACK numop)
};

// Default Lanczos basis size for nev eigenpairs: max(2 nev + 1, nev + 20).
inline int default_basis_size(int nev) { return nev + 20 > 2 * nev + 1 ? nev + 20 : 2 * nev + 1; }

// The `nev` eigenpairs with lambda nearest above the shift (the lowest ones for a shift
// below the spectrum). Preconditions (DEMAND): K, M square, same size n, symmetric with
// both triangles stored, M positive definite, 1 <= nev <= n. Never throws on numerical
// trouble: a failed factorisation returns kSingular, ARPACK trouble kNotConverged
// (status message carries ARPACK's info code); eigenvalues/vectors are then empty.
EigenSolution solve_lowest_eigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                                      const Eigen::SparseMatrix<double>& mass, int nev,
                                      const EigenSolverOptions& options = {});

// The same for K(dofs, dofs), M(dofs, dofs) (dofs ascending, distinct, in range; DEMAND):
// eigenvectors have dofs.size() rows. K and M are not copied.
EigenSolution solve_lowest_eigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                                      const Eigen::SparseMatrix<double>& mass,
                                      const std::vector<int>& dofs, int nev,
                                      const EigenSolverOptions& options = {});

}  // namespace limber::modal
