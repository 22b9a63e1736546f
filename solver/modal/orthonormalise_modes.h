// Combination of normal and static modes into one M-orthonormal, K-diagonal set
// (seed paper §2: static modes "made independent of the normal modes and normalised";
// Craig, "Structural Dynamics", Wiley 1981, §19.4 Rayleigh-Ritz on a mode span;
// the "orthonormalization" of Adams Flex / MSC Nastran's DMAP alignment).
//
// Steps, for candidate columns X = [x_1 ... x_m] (normal modes first, then static):
//  1. M-Gram-Schmidt in column order, projecting twice ("twice is enough": Giraud et al.
//     2005). x_j is dropped as nearly dependent, with a notice naming it, when
//     ||x_j - projection||_M < dependency_tolerance x ||x_j||_M. Result Q, Q^T M Q = I.
//  2. Reduced eigenproblem K_r z = omega^2 z with K_r = Q^T K Q (M_r = I); Phi = Q Z.
//  3. If the span contains rigid motion (free components: `rigid_motion` = Psi_N, the
//     rigid motions left free by the fixed DOFs), its dimension d is the number of
//     principal cosines between span(Q) and span(Psi_N) above 1 - kRigidCosineTolerance;
//     the d lowest (zero-frequency) vectors are dropped: the floating frame carries them.
//  4. Each remaining vector phi_k takes the kind and label of the candidate with the
//     largest M-weighted participation |x_j^T M phi_k| / ||x_j||_M, assigned one-to-one
//     in decreasing order of participation (an exact normal mode lies in the span, is a
//     Ritz vector with its own eigenvalue, and so keeps its label and frequency).
// Output: ModeSet.shapes (n x nm), modes (ascending), modal_stiffness = omega^2, with
// ||Phi^T M Phi - I|| and off-diag(Phi^T K Phi) / max diag at round-off level.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "modal/mode_set.h"

namespace limber::modal {

// Principal cosine above 1 - kRigidCosineTolerance: the direction is rigid motion
// (angle below 1.4e-4 rad; static solutions carry errors far below that).
inline constexpr double kRigidCosineTolerance = 1e-8;

struct OrthonormalisedModes {
  ModeSet mode_set;                  // shapes, modes, modal_stiffness (no invariants)
  std::vector<std::string> notices;  // dropped dependent / rigid vectors
};

// Preconditions (DEMAND): candidates n x m with m == info.size(); rigid_motion n x r
// (r may be 0); 0 < dependency_tolerance < 1.
OrthonormalisedModes orthonormalise_modes(const Eigen::SparseMatrix<double>& stiffness,
                                          const Eigen::SparseMatrix<double>& mass,
                                          const Eigen::MatrixXd& candidates,
                                          const std::vector<ModeInfo>& info,
                                          const Eigen::MatrixXd& rigid_motion,
                                          double dependency_tolerance);

}  // namespace limber::modal
