#include "modal/static_modes.h"

#include <algorithm>

#include <Eigen/Cholesky>
#include <Eigen/CholmodSupport>
#include <fmt/format.h>

#include "core/error.h"
#include "modal/dof_selection.h"
#include "modal/rigid_body_modes.h"

namespace limber::modal {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

std::vector<int> sorted(std::vector<int> dofs) {
  std::sort(dofs.begin(), dofs.end());
  LIMBER_DEMAND(std::adjacent_find(dofs.begin(), dofs.end()) == dofs.end());
  return dofs;
}

// phi <- phi - Psi_N (Psi_N^T M Psi_N)^-1 Psi_N^T M phi.
void remove_rigid_motion(const SparseMatrix& mass, const Eigen::MatrixXd& psi_n,
                         Eigen::MatrixXd& phi) {
  if (psi_n.cols() == 0) return;
  const Eigen::MatrixXd m_psi = mass * psi_n;
  const Eigen::LDLT<Eigen::MatrixXd> rigid_mass(psi_n.transpose() * m_psi);
  phi -= psi_n * rigid_mass.solve(m_psi.transpose() * phi);
}

// Solves K(u, u) X = B for the DOFs u with one factorisation; kSingular on failure.
bool solve_restricted(const SparseMatrix& stiffness, const std::vector<int>& unknowns,
                      const Eigen::MatrixXd& rhs, Eigen::MatrixXd& solution, std::string& message,
                      const char* what) {
  // Every free DOF chosen: nothing left to solve for.
  if (unknowns.empty()) {
    solution.resize(0, rhs.cols());
    return true;
  }
  SparseMatrix k_uu = submatrix(stiffness, unknowns, unknowns);
  k_uu.makeCompressed();
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> factor(k_uu);
  if (factor.info() != Eigen::Success) {
    message = fmt::format(
        "{}: the stiffness matrix on the {} unheld DOFs is not positive definite (a "
        "mechanism or an element with no stiffness?)",
        what, unknowns.size());
    return false;
  }
  solution = factor.solve(rhs);
  return true;
}

std::vector<int> fixed_dofs_of(int n, const std::vector<int>& free_dofs) {
  std::vector<int> all(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
  return set_difference(all, free_dofs);
}

}  // namespace

StaticModes compute_constraint_modes(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                     const Eigen::MatrixXd& psi,
                                     const std::vector<int>& free_dofs,
                                     const std::vector<int>& chosen_dofs) {
  const int n = static_cast<int>(stiffness.rows());
  StaticModes result;
  const std::vector<int> c = sorted(chosen_dofs);
  const std::vector<int> v = set_difference(free_dofs, c);
  LIMBER_DEMAND(v.size() + c.size() == free_dofs.size());

  // Rigid motion left free by fixed ∪ c, and a temporary support s ⊂ v for it.
  std::vector<int> held = fixed_dofs_of(n, free_dofs);
  held.insert(held.end(), c.begin(), c.end());
  std::sort(held.begin(), held.end());
  const Eigen::MatrixXd psi_n = unrestrained_rigid_motion(psi, held);
  const std::vector<int> unknowns = set_difference(v, determinate_support(psi_n, v, rigid_length_scale(psi)));

  // K_uu X = -K_uc (columns in the caller's order of chosen DOFs).
  const SparseMatrix k_uc = submatrix(stiffness, unknowns, chosen_dofs);
  Eigen::MatrixXd x;
  if (!solve_restricted(stiffness, unknowns, -Eigen::MatrixXd(k_uc), x, result.message,
                        "constraint modes")) {
    result.status = ModalStatus::kSingular;
    return result;
  }

  // Phi_c = [X; I], then remove the rigid motion the held DOFs leave free.
  result.shapes = scatter_rows(x, unknowns, n);
  for (std::size_t j = 0; j < chosen_dofs.size(); ++j) {
    result.shapes(chosen_dofs[j], static_cast<Eigen::Index>(j)) = 1.0;
  }
  remove_rigid_motion(mass, psi_n, result.shapes);
  return result;
}

StaticModes compute_attachment_modes(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                     const Eigen::MatrixXd& psi,
                                     const std::vector<int>& free_dofs,
                                     const std::vector<int>& chosen_dofs) {
  const int n = static_cast<int>(stiffness.rows());
  const std::vector<int> a = sorted(chosen_dofs);
  LIMBER_DEMAND(set_difference(free_dofs, a).size() + a.size() == free_dofs.size());

  // Unit loads at the chosen DOFs.
  Eigen::MatrixXd loads = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(chosen_dofs.size()));
  for (std::size_t j = 0; j < chosen_dofs.size(); ++j) {
    loads(chosen_dofs[j], static_cast<Eigen::Index>(j)) = 1.0;
  }
  return compute_static_responses(stiffness, mass, psi, free_dofs, loads, "attachment modes");
}

StaticModes compute_static_responses(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                     const Eigen::MatrixXd& psi, const std::vector<int>& free_dofs,
                                     Eigen::MatrixXd loads, const char* what) {
  const int n = static_cast<int>(stiffness.rows());
  LIMBER_DEMAND(loads.rows() == n);
  StaticModes result;

  // Inertia relief: balance each load by the rigid-body inertia forces, P f.
  const Eigen::MatrixXd psi_n = unrestrained_rigid_motion(psi, fixed_dofs_of(n, free_dofs));
  if (psi_n.cols() > 0) {
    const Eigen::MatrixXd m_psi = mass * psi_n;
    const Eigen::LDLT<Eigen::MatrixXd> rigid_mass(psi_n.transpose() * m_psi);
    loads -= m_psi * rigid_mass.solve(psi_n.transpose() * loads);
  }

  // Solve with the temporary determinate support (none for a restrained component).
  const std::vector<int> unknowns = set_difference(free_dofs, determinate_support(psi_n, free_dofs, rigid_length_scale(psi)));
  Eigen::MatrixXd x;
  if (!solve_restricted(stiffness, unknowns, gather_rows(loads, unknowns), x, result.message, what)) {
    result.status = ModalStatus::kSingular;
    return result;
  }
  result.shapes = scatter_rows(x, unknowns, n);
  remove_rigid_motion(mass, psi_n, result.shapes);
  return result;
}

}  // namespace limber::modal
