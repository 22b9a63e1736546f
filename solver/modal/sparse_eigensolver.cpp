#include "modal/sparse_eigensolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <random>
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "core/error.h"

// ARPACK (arpack-ng, gfortran ABI): hidden character lengths follow the arguments.
extern "C" {
void dsaupd_(int* ido, const char* bmat, const int* n, const char* which, const int* nev,
             const double* tol, double* resid, const int* ncv, double* v, const int* ldv,
             int* iparam, int* ipntr, double* workd, double* workl, const int* lworkl,
             int* info, std::size_t bmat_len, std::size_t which_len);
void dseupd_(const int* rvec, const char* howmny, int* select, double* d, double* z,
             const int* ldz, const double* sigma, const char* bmat, const int* n,
             const char* which, const int* nev, const double* tol, double* resid,
             const int* ncv, double* v, const int* ldv, int* iparam, int* ipntr,
             double* workd, double* workl, const int* lworkl, int* info,
             std::size_t howmny_len, std::size_t bmat_len, std::size_t which_len);
}

namespace limber::modal {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double default_shift(const SparseMatrix& k, const SparseMatrix& m) {
  // Largest diagonal ratio K_ii / M_ii: an upper-end estimate of the spectrum.
  const Eigen::VectorXd kd = k.diagonal();
  const Eigen::VectorXd md = m.diagonal();
  double ratio = 0.0;
  for (Eigen::Index i = 0; i < kd.size(); ++i) {
    if (md[i] > 0.0) ratio = std::max(ratio, kd[i] / md[i]);
  }
  return -kDefaultShiftFactor * std::max(ratio, 1.0);
}

// Largest absolute column sum.
double norm_1(const SparseMatrix& a) {
  double norm = 0.0;
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    double column = 0.0;
    for (SparseMatrix::InnerIterator it(a, j); it; ++it) column += std::abs(it.value());
    norm = std::max(norm, column);
  }
  return norm;
}

// Sort ascending, M-normalise, and measure backward errors.
void finish(const SparseMatrix& k, const SparseMatrix& m, EigenSolution& solution) {
  const Eigen::Index nev = solution.eigenvalues.size();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(nev));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return solution.eigenvalues[a] < solution.eigenvalues[b];
  });
  const double k_norm = norm_1(k);
  const double m_norm = norm_1(m);
  Eigen::VectorXd values(nev);
  Eigen::MatrixXd vectors(solution.vectors.rows(), nev);
  solution.max_backward_error = 0.0;
  for (Eigen::Index j = 0; j < nev; ++j) {
    // Mass normalisation phi^T M phi = 1 (seed paper eq. 5).
    Eigen::VectorXd phi = solution.vectors.col(order[static_cast<std::size_t>(j)]);
    Eigen::VectorXd m_phi = m * phi;
    const double scale = 1.0 / std::sqrt(phi.dot(m_phi));
    phi *= scale;
    m_phi *= scale;
    const double lambda = solution.eigenvalues[order[static_cast<std::size_t>(j)]];
    const Eigen::VectorXd residual = k * phi - lambda * m_phi;
    const double error = residual.lpNorm<1>() /
                         ((k_norm + std::abs(lambda) * m_norm) * phi.lpNorm<1>());
    solution.max_backward_error = std::max(solution.max_backward_error, error);
    values[j] = lambda;
    vectors.col(j) = phi;
  }
  solution.eigenvalues = std::move(values);
  solution.vectors = std::move(vectors);
}

EigenSolution solve_dense(const SparseMatrix& k, const SparseMatrix& m, int nev, double shift) {
  EigenSolution solution;
  solution.shift = shift;
  const Eigen::MatrixXd kd(k);
  const Eigen::MatrixXd md(m);
  // Cholesky-reduced standard problem L^-1 K L^-T (M = L L^T).
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(kd, md);
  if (dense.info() != Eigen::Success) {
    solution.status = ModalStatus::kSingular;
    solution.message = "dense generalized eigen-solver failed: mass matrix not positive definite";
    return solution;
  }
  solution.eigenvalues = dense.eigenvalues().head(nev);
  solution.vectors = dense.eigenvectors().leftCols(nev);
  return solution;
}

}  // namespace

EigenSolution solve_lowest_eigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                      int nev, const EigenSolverOptions& options) {
  const int n = static_cast<int>(stiffness.rows());
  LIMBER_DEMAND(stiffness.cols() == n && mass.rows() == n && mass.cols() == n);
  LIMBER_DEMAND(nev >= 1 && nev <= n);
  const double sigma = options.shift.value_or(default_shift(stiffness, mass));

  // Small problems: dense solution (ARPACK needs nev < ncv <= n and gains nothing).
  if (2 * nev >= n) {
    EigenSolution solution = solve_dense(stiffness, mass, nev, sigma);
    if (solution.status == ModalStatus::kOk) finish(stiffness, mass, solution);
    return solution;
  }

  EigenSolution solution;
  solution.shift = sigma;

  // Factorise K - sigma M once (lower triangle is read).
  const Clock::time_point factorisation_start = Clock::now();
  SparseMatrix shifted = stiffness - sigma * mass;
  shifted.makeCompressed();
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> factor;
  factor.compute(shifted);
  solution.factorisation_seconds = seconds_since(factorisation_start);
  if (factor.info() != Eigen::Success) {
    solution.status = ModalStatus::kSingular;
    solution.message = fmt::format(
        "Cholesky factorisation of K - sigma M failed (sigma = {:.6g} 1/s^2): the matrix is "
        "not positive definite",
        sigma);
    return solution;
  }

  // ARPACK work arrays (ARPACK Users' Guide, dsaupd documentation).
  const Clock::time_point lanczos_start = Clock::now();
  const int ncv = options.basis_size > 0 ? std::min(n, options.basis_size)
                                         : std::min(n, std::max(2 * nev + 1, nev + 20));
  LIMBER_DEMAND(ncv > nev);
  const int ldv = n;
  const int lworkl = ncv * (ncv + 8);
  const double tol = options.tolerance;
  std::vector<double> resid(static_cast<std::size_t>(n));
  std::vector<double> v(static_cast<std::size_t>(n) * static_cast<std::size_t>(ncv));
  std::vector<double> workd(3 * static_cast<std::size_t>(n));
  std::vector<double> workl(static_cast<std::size_t>(lworkl));
  int iparam[11] = {};
  int ipntr[11] = {};
  iparam[0] = 1;                       // exact shifts
  iparam[2] = options.max_iterations;  // restarts
  iparam[6] = 3;                       // mode 3: shift-invert, B = M

  // Deterministic random start vector (info = 1: resid is supplied).
  std::mt19937 generator(20240611u);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (double& r : resid) r = uniform(generator);
  int info = 1;

  // Reverse-communication loop: apply OP = (K - sigma M)^-1 M or B = M as asked.
  int ido = 0;
  Eigen::VectorXd buffer(n);
  while (true) {
    dsaupd_(&ido, "G", &n, "LM", &nev, &tol, resid.data(), &ncv, v.data(), &ldv, iparam, ipntr,
            workd.data(), workl.data(), &lworkl, &info, 1, 2);
    if (ido != -1 && ido != 1 && ido != 2) break;
    Eigen::Map<const Eigen::VectorXd> x(&workd[static_cast<std::size_t>(ipntr[0] - 1)], n);
    Eigen::Map<Eigen::VectorXd> y(&workd[static_cast<std::size_t>(ipntr[1] - 1)], n);
    if (ido == -1) {
      buffer = mass * x;
      y = factor.solve(buffer);
    } else if (ido == 1) {
      // M x is already available at ipntr[2].
      Eigen::Map<const Eigen::VectorXd> mx(&workd[static_cast<std::size_t>(ipntr[2] - 1)], n);
      y = factor.solve(Eigen::VectorXd(mx));
    } else {
      y = mass * x;
    }
  }
  solution.arpack_info = info;
  if (info != 0) {
    solution.status = ModalStatus::kNotConverged;
    solution.message =
        info == 1 ? fmt::format("ARPACK dsaupd reached the maximum of {} restarts with {} of {} "
                                "eigenpairs converged (info = 1)",
                                options.max_iterations, iparam[4], nev)
                  : fmt::format("ARPACK dsaupd failed with info = {} (n = {}, nev = {}, ncv = {})",
                                info, n, nev, ncv);
    return solution;
  }

  // Ritz vectors; dseupd returns lambda (already transformed back from theta).
  const int rvec = 1;
  std::vector<int> select(static_cast<std::size_t>(ncv));
  solution.eigenvalues.resize(nev);
  solution.vectors.resize(n, nev);
  dseupd_(&rvec, "A", select.data(), solution.eigenvalues.data(), solution.vectors.data(), &ldv,
          &sigma, "G", &n, "LM", &nev, &tol, resid.data(), &ncv, v.data(), &ldv, iparam, ipntr,
          workd.data(), workl.data(), &lworkl, &info, 1, 1, 2);
  solution.lanczos_seconds = seconds_since(lanczos_start);
  if (info != 0 || iparam[4] < nev) {
    solution.arpack_info = info;
    solution.status = ModalStatus::kNotConverged;
    solution.message = fmt::format("ARPACK dseupd: info = {}, {} of {} eigenpairs converged", info,
                                   iparam[4], nev);
    solution.eigenvalues.resize(0);
    solution.vectors.resize(0, 0);
    return solution;
  }
  finish(stiffness, mass, solution);
  return solution;
}

}  // namespace limber::modal
