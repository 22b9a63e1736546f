#include "modal/sparse_eigensolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <mutex>
#include <numeric>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "core/error.h"
#include "modal/dof_selection.h"
#include "modal/shifted_factor.h"

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

// The problem restricted to `dofs`, never formed: products and norms go through the
// full matrices and the position map.
struct Restricted {
  const SparseMatrix& k;
  const SparseMatrix& m;
  const std::vector<int>& dofs;
  std::vector<int> positions;  // global DOF -> position in dofs, or -1
  int size() const { return static_cast<int>(dofs.size()); }
};

double default_shift(const Restricted& problem) {
  // Largest diagonal ratio K_ii / M_ii: an upper-end estimate of the spectrum.
  double ratio = 0.0;
  for (int g : problem.dofs) {
    const double kd = problem.k.coeff(g, g);
    const double md = problem.m.coeff(g, g);
    if (md > 0.0) ratio = std::max(ratio, kd / md);
  }
  return -kDefaultShiftFactor * std::max(ratio, 1.0);
}

// Sort ascending, M-normalise, and measure backward errors.
void finish(const Restricted& problem, EigenSolution& solution) {
  const Eigen::Index nev = solution.eigenvalues.size();
  const Eigen::Index n = problem.size();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(nev));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return solution.eigenvalues[a] < solution.eigenvalues[b];
  });
  const double k_norm = submatrix_norm_1(problem.k, problem.dofs, problem.positions);
  const double m_norm = submatrix_norm_1(problem.m, problem.dofs, problem.positions);
  Eigen::VectorXd values(nev);
  Eigen::MatrixXd vectors(n, nev);
  Eigen::VectorXd m_phi(n);
  Eigen::VectorXd k_phi(n);
  solution.max_backward_error = 0.0;
  for (Eigen::Index j = 0; j < nev; ++j) {
    // Mass normalisation phi^T M phi = 1 (seed paper eq. 5).
    auto phi = vectors.col(j);
    phi = solution.vectors.col(order[static_cast<std::size_t>(j)]);
    multiply_submatrix(problem.m, problem.dofs, problem.positions, phi.data(), m_phi.data());
    const double scale = 1.0 / std::sqrt(phi.dot(m_phi));
    phi *= scale;
    m_phi *= scale;
    multiply_submatrix(problem.k, problem.dofs, problem.positions, phi.data(), k_phi.data());
    const double lambda = solution.eigenvalues[order[static_cast<std::size_t>(j)]];
    const double error = (k_phi - lambda * m_phi).lpNorm<1>() /
                         ((k_norm + std::abs(lambda) * m_norm) * phi.lpNorm<1>());
    solution.max_backward_error = std::max(solution.max_backward_error, error);
    values[j] = lambda;
  }
  solution.eigenvalues = std::move(values);
  solution.vectors = std::move(vectors);
}

EigenSolution solve_dense(const Restricted& problem, int nev, double shift) {
  EigenSolution solution;
  solution.shift = shift;
  const Eigen::MatrixXd kd(submatrix(problem.k, problem.dofs, problem.dofs));
  const Eigen::MatrixXd md(submatrix(problem.m, problem.dofs, problem.dofs));
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

std::vector<int> all_dofs(const SparseMatrix& stiffness) {
  std::vector<int> dofs(static_cast<std::size_t>(stiffness.rows()));
  std::iota(dofs.begin(), dofs.end(), 0);
  return dofs;
}

// ARPACK's work arrays and settings for one solve of `nev` eigenpairs of an n x n operator
// (ARPACK Users' Guide, dsaupd documentation).
struct ArpackWork {
  int n = 0;
  int nev = 0;
  int ncv = 0;     // Lanczos basis size, nev < ncv <= n
  int lworkl = 0;  // ncv (ncv + 8)
  double tol = 0.0;
  std::vector<double> resid;
  std::vector<double> v;  // n x ncv Lanczos basis
  std::vector<double> workd;
  std::vector<double> workl;
  std::vector<double> scratch;  // one vector of size n for the operator
  int iparam[11] = {};
  int ipntr[11] = {};
  int info = 1;  // 1: resid holds the start vector
};

ArpackWork arpack_work(int n, int nev, const EigenSolverOptions& options) {
  ArpackWork work;
  work.n = n;
  work.nev = nev;
  work.ncv = options.basis_size > 0 ? std::min(n, options.basis_size)
                                    : std::min(n, default_basis_size(nev));
  LIMBER_DEMAND(work.ncv > nev);
  work.lworkl = work.ncv * (work.ncv + 8);
  work.tol = options.tolerance;
  work.resid.resize(static_cast<std::size_t>(n));
  work.v.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(work.ncv));
  work.workd.resize(3 * static_cast<std::size_t>(n));
  work.workl.resize(static_cast<std::size_t>(work.lworkl));
  work.scratch.resize(static_cast<std::size_t>(n));
  work.iparam[0] = 1;                       // exact shifts
  work.iparam[2] = options.max_iterations;  // restarts
  work.iparam[6] = 1;                       // mode 1: standard problem C w = theta w
  // Deterministic random start vector (info = 1: resid is supplied).
  std::mt19937 generator(20240611u);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (double& r : work.resid) r = uniform(generator);
  return work;
}

// Reverse-communication loop: y = C x = L^-1 P M P^T L^-T x in ARPACK's own work array
// (nothing allocated per step). Leaves ARPACK's status in work.info.
void iterate_lanczos(const Restricted& problem, ShiftedFactor& factor, ArpackWork& work) {
  int ido = 0;
  while (true) {
    dsaupd_(&ido, "I", &work.n, "LM", &work.nev, &work.tol, work.resid.data(), &work.ncv,
            work.v.data(), &work.n, work.iparam, work.ipntr, work.workd.data(), work.workl.data(),
            &work.lworkl, &work.info, 1, 2);
    if (ido != -1 && ido != 1) break;
    const double* x = &work.workd[static_cast<std::size_t>(work.ipntr[0] - 1)];
    double* y = &work.workd[static_cast<std::size_t>(work.ipntr[1] - 1)];
    factor.solve_transposed_factor(x, work.scratch.data());
    multiply_submatrix(problem.m, problem.dofs, problem.positions, work.scratch.data(), y);
    factor.solve_factor(y, y);
  }
}

// Ritz pairs (theta, w) of C; then lambda = sigma + 1 / theta, and w in solution.vectors (the
// caller maps it to phi = P^T L^-T w). Sets the status kNotConverged when dseupd fails or
// converged fewer than nev pairs.
void extract_ritz_pairs(double sigma, ArpackWork& work, EigenSolution& solution) {
  const int rvec = 1;
  std::vector<int> select(static_cast<std::size_t>(work.ncv));
  Eigen::VectorXd theta(work.nev);
  solution.vectors.resize(work.n, work.nev);
  dseupd_(&rvec, "A", select.data(), theta.data(), solution.vectors.data(), &work.n, &sigma, "I",
          &work.n, "LM", &work.nev, &work.tol, work.resid.data(), &work.ncv, work.v.data(),
          &work.n, work.iparam, work.ipntr, work.workd.data(), work.workl.data(), &work.lworkl,
          &work.info, 1, 1, 2);
  if (work.info != 0 || work.iparam[4] < work.nev) {
    solution.arpack_info = work.info;
    solution.status = ModalStatus::kNotConverged;
    solution.message = fmt::format("ARPACK dseupd: info = {}, {} of {} eigenpairs converged",
                                   work.info, work.iparam[4], work.nev);
    solution.vectors.resize(0, 0);
    return;
  }
  solution.eigenvalues = sigma + theta.cwiseInverse().array();
}

}  // namespace

EigenSolution solve_lowest_eigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                      int nev, const EigenSolverOptions& options) {
  return solve_lowest_eigenpairs(stiffness, mass, all_dofs(stiffness), nev, options);
}

EigenSolution solve_lowest_eigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                      const std::vector<int>& dofs, int nev,
                                      const EigenSolverOptions& options) {
  LIMBER_DEMAND(stiffness.rows() == stiffness.cols() && mass.rows() == stiffness.rows() &&
                mass.cols() == stiffness.cols());
  const Restricted problem{stiffness, mass, dofs,
                           dof_positions(dofs, static_cast<int>(stiffness.rows()))};
  const int n = problem.size();
  LIMBER_DEMAND(nev >= 1 && nev <= n);
  const double sigma = options.shift.value_or(default_shift(problem));

  // Small problems: dense solution (ARPACK needs nev < ncv <= n and gains nothing).
  if (2 * nev >= n) {
    EigenSolution solution = solve_dense(problem, nev, sigma);
    if (solution.status == ModalStatus::kOk) finish(problem, solution);
    return solution;
  }

  EigenSolution solution;
  solution.shift = sigma;
  // ARPACK keeps its iteration state in Fortran SAVE variables: one solve per process at a
  // time (`limber select` reduces two mode sets at once, on two threads). The BLAS threads are
  // the program's choice (modal/blas_threads.h: one, set by limber's main and the Python module).
  static std::mutex arpack_mutex;
  const std::lock_guard arpack_lock(arpack_mutex);

  // Factorise K - sigma M once.
  const Clock::time_point factorisation_start = Clock::now();
  ShiftedFactor factor(stiffness, mass, dofs, sigma);
  solution.factorisation_seconds = seconds_since(factorisation_start);
  if (!factor.ok()) {
    solution.status = ModalStatus::kSingular;
    solution.message = fmt::format(
        "Cholesky factorisation of K - sigma M failed (sigma = {:.6g} 1/s^2): the matrix is "
        "not positive definite",
        sigma);
    return solution;
  }

  // Lanczos iterations, then the eigenpairs from the Ritz pairs.
  const Clock::time_point lanczos_start = Clock::now();
  ArpackWork work = arpack_work(n, nev, options);
  iterate_lanczos(problem, factor, work);
  solution.arpack_info = work.info;
  solution.operator_applications = work.iparam[8];
  if (work.info != 0) {
    solution.status = ModalStatus::kNotConverged;
    solution.message =
        work.info == 1
            ? fmt::format("ARPACK dsaupd reached the maximum of {} restarts with {} of {} "
                          "eigenpairs converged (info = 1)",
                          options.max_iterations, work.iparam[4], nev)
            : fmt::format("ARPACK dsaupd failed with info = {} (n = {}, nev = {}, ncv = {})",
                          work.info, n, nev, work.ncv);
    return solution;
  }
  extract_ritz_pairs(sigma, work, solution);
  solution.lanczos_seconds = seconds_since(lanczos_start);
  if (solution.status != ModalStatus::kOk) return solution;
  for (Eigen::Index j = 0; j < nev; ++j) {
    auto w = solution.vectors.col(j);
    factor.solve_transposed_factor(w.data(), w.data());
  }
  finish(problem, solution);
  return solution;
}

}  // namespace limber::modal
