#include "modal/normal_modes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/error.h"
#include "modal/dof_selection.h"

namespace limber::modal {
namespace {

// Number of leading modes below kRigidFrequencyRatio x the frequency of mode `expected`.
int count_rigid(const Eigen::VectorXd& eigenvalues, int expected) {
  if (expected == 0 || eigenvalues.size() <= expected) return 0;
  const double reference = frequency_hz(eigenvalues[expected]);
  int rigid = 0;
  while (rigid < expected &&
         std::abs(frequency_hz(eigenvalues[rigid])) < kRigidFrequencyRatio * reference) {
    ++rigid;
  }
  return rigid;
}

}  // namespace

double frequency_hz(double eigenvalue) {
  const double omega = std::sqrt(std::abs(eigenvalue));
  return std::copysign(omega, eigenvalue) / (2.0 * std::numbers::pi);
}

NormalModes compute_normal_modes(const Eigen::SparseMatrix<double>& stiffness,
                                 const Eigen::SparseMatrix<double>& mass,
                                 const std::vector<int>& free_dofs,
                                 const NormalModeRequest& request) {
  const int n = static_cast<int>(stiffness.rows());
  const int n_free = static_cast<int>(free_dofs.size());
  LIMBER_DEMAND(request.count > 0 || request.max_frequency_hz.has_value());
  LIMBER_DEMAND(request.count >= 0 && request.count + request.rigid_count <= n_free);
  // First block: the requested count, or 10 elastic modes when only a cut-off is given;
  // one mode beyond the rigid ones is needed for the classification reference.
  const int first_block = request.count > 0 ? request.count : 10;
  int nev = std::min(n_free, request.rigid_count + first_block);
  NormalModes result;
  EigenSolution solution;
  int rigid = 0;
  while (true) {
    solution = solve_lowest_eigenpairs(stiffness, mass, free_dofs, nev, request.solver);
    if (solution.status != ModalStatus::kOk) {
      result.status = solution.status;
      result.message = solution.message;
      return result;
    }
    rigid = count_rigid(solution.eigenvalues, request.rigid_count);
    // Done when no cut-off applies, the cut-off is passed, enough modes exist, or all DOFs used.
    if (!request.max_frequency_hz || nev == n_free) break;
    if (request.count > 0 && nev - rigid >= request.count) break;
    if (frequency_hz(solution.eigenvalues[nev - 1]) > *request.max_frequency_hz) break;
    nev = std::min(n_free, 2 * nev);
  }

  // Report the rigid-body classification.
  if (rigid < request.rigid_count) {
    result.notices.push_back(fmt::format(
        "expected {} rigid-body modes, found {} below {} x the next frequency ({:.6g} Hz)",
        request.rigid_count, rigid, kRigidFrequencyRatio,
        frequency_hz(solution.eigenvalues[std::min<Eigen::Index>(request.rigid_count, nev - 1)])));
  }
  if (rigid + 1 < nev && frequency_hz(solution.eigenvalues[rigid]) <
                             kRigidFrequencyRatio * frequency_hz(solution.eigenvalues[rigid + 1])) {
    result.notices.push_back(fmt::format(
        "elastic mode 1 ({:.6g} Hz) is below {} x the next ({:.6g} Hz): a mechanism or a "
        "disconnected mesh?",
        frequency_hz(solution.eigenvalues[rigid]), kRigidFrequencyRatio,
        frequency_hz(solution.eigenvalues[rigid + 1])));
  }
  result.rigid_eigenvalues = solution.eigenvalues.head(rigid);
  result.rigid_shapes = scatter_rows(solution.vectors.leftCols(rigid), free_dofs, n);

  // Elastic modes: below the cut-off, at most `count`.
  int elastic = nev - rigid;
  if (request.count > 0) elastic = std::min(elastic, request.count);
  if (request.max_frequency_hz) {
    int below = 0;
    while (below < elastic &&
           frequency_hz(solution.eigenvalues[rigid + below]) <= *request.max_frequency_hz) {
      ++below;
    }
    elastic = below;
  }
  result.eigenvalues = solution.eigenvalues.segment(rigid, elastic);
  result.shapes = scatter_rows(solution.vectors.middleCols(rigid, elastic), free_dofs, n);
  return result;
}

}  // namespace limber::modal
