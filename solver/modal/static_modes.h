// Static modes of a component: constraint modes (seed paper eq. 7-9; Craig & Bampton
// 1968) and attachment modes (eq. 10-11; inertia relief for unrestrained components:
// Craig & Chang 1977, "On the use of attachment modes in substructure coupling for
// dynamic analysis", AIAA/ASME SDM conf., paper 77-405; Craig & Kurdila, "Fundamentals
// of Structural Dynamics", 2nd ed., Wiley 2006, ch. 18).
//
// Notation: f = free DOFs (not in FeModel::fixed_dofs), Psi = rigid_body_modes (n x 6).
// Each function factorises one sparse stiffness submatrix (CHOLMOD supernodal Cholesky)
// once and reuses it for all right-hand sides. Results are full DOF vectors (n rows).
//
// Constraint modes, chosen DOFs c ⊂ f, v = f \ c:
//   K_vv Phi_vc = -K_vc,  Phi_c = [Phi_vc; I_cc]   (fixed DOFs and the other c held at 0).
// If the held set (fixed ∪ c) leaves r > 0 rigid motions Psi_N free (fewer than 6
// independent held DOFs, see unrestrained_rigid_motion), K_vv is singular: its null
// space is Psi_N(v). The system is still consistent (Psi_N^T K = 0), so it is solved
// with r more DOFs s ⊂ v held temporarily (a statically determinate support, see
// determinate_support; it carries no reaction), and the arbitrary rigid part is then
// removed by M-orthogonalisation against Psi_N (which vanishes on the held set, so the
// unit value at c and the zeros at fixed DOFs are kept):
//   phi <- phi - Psi_N (Psi_N^T M Psi_N)^-1 Psi_N^T M phi.
// A constraint mode of a component held only at c is then a pure rigid motion.
//
// Attachment modes, unit loads at DOFs a ⊂ f:
//   restrained (r = 0 for the fixed DOFs): K_ff Phi_a = I(:, a) (columns of G = K_ff^-1);
//   unrestrained (r > 0): inertia relief. The unit load is balanced by the rigid-body
//   inertia forces of the r free rigid motions, P = I - M Psi_N (Psi_N^T M Psi_N)^-1 Psi_N^T:
//     K_ff phi = (P e_a)_f,   solved with the temporary support s as above, then
//     phi <- phi - Psi_N (Psi_N^T M Psi_N)^-1 Psi_N^T M phi   (M-orthogonal to Psi_N).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "modal/modal_status.h"

namespace limber::modal {

struct StaticModes {
  ModalStatus status = ModalStatus::kOk;  // kSingular when the factorisation fails
  std::string message;
  Eigen::MatrixXd shapes;  // n x (number of chosen DOFs), same order as the chosen DOFs
};

// Preconditions (DEMAND): K, M n x n symmetric; psi n x 6; free_dofs ascending; every
// chosen DOF (unique) is a free DOF. Chosen DOFs may be in any order.
StaticModes compute_constraint_modes(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::SparseMatrix<double>& mass,
                                     const Eigen::MatrixXd& psi,
                                     const std::vector<int>& free_dofs,
                                     const std::vector<int>& chosen_dofs);

StaticModes compute_attachment_modes(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::SparseMatrix<double>& mass,
                                     const Eigen::MatrixXd& psi,
                                     const std::vector<int>& free_dofs,
                                     const std::vector<int>& chosen_dofs);

// Static responses u to arbitrary loads f (n x k columns, full DOF vectors; entries at fixed
// DOFs are ignored): the attachment-mode solve above with f in place of unit loads —
// K_ff u = f_f when restrained, K_ff u = (P f)_f with inertia relief and u M-orthogonal to
// Psi_N when not. `what` names the solve in the kSingular message.
StaticModes compute_static_responses(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::SparseMatrix<double>& mass,
                                     const Eigen::MatrixXd& psi,
                                     const std::vector<int>& free_dofs, Eigen::MatrixXd loads,
                                     const char* what);

}  // namespace limber::modal
