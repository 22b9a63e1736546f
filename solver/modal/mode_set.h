// The reduced description of one flexible component: its mode shapes with their
// origin labels and frequencies, and the modal invariants of the floating frame.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace limber::modal {

// Where a mode vector comes from (seed paper §2: normal modes eq. 4-6, constraint
// modes eq. 7-9, attachment modes eq. 10-11; rigid = zero-frequency body motion).
enum class ModeKind { kRigid, kNormal, kConstraint, kAttachment };

const char* to_string(ModeKind kind);

struct ModeInfo {
  ModeKind kind = ModeKind::kNormal;
  double frequency_hz = 0.0;  // natural or (for orthonormalised static modes) equivalent frequency
  std::string label;          // e.g. "normal 3", "constraint uz at node 101"
};

// Inertia invariants of the floating-frame-of-reference equations, built from the
// FE mass matrix M (rotational DOFs included) and the rigid-body modes Psi of the
// undeformed component about its frame origin:
//   Psi = [Psi_t  Psi_r]   (n x 3 translations, n x 3 small rotations)
//   Psi_r(eta) = Psi_r + sum_i eta_i Psi_r_i,  Psi_r_i built from the translational part of phi_i.
// See modal_invariants.h for the derivation and the references.
struct ModalInvariants {
  double mass = 0.0;                                           // Psi_tᵀ M Psi_t = m I
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();      // m c (c: centre of mass)
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();           // J about frame origin, undeformed
  Eigen::MatrixXd translation_coupling;                        // 3 x nm: Psi_tᵀ M Phi
  Eigen::MatrixXd rotation_coupling;                           // 3 x nm: Psi_rᵀ M Phi
  std::vector<Eigen::Matrix3d> inertia_first_order;            // nm: Psi_rᵀ M Psi_r_i + transpose
  std::vector<Eigen::Matrix3d> inertia_second_order;           // nm*nm (i*nm+j): Psi_r_iᵀ M Psi_r_j
  std::vector<Eigen::MatrixXd> rotation_coupling_first_order;  // nm: Psi_r_iᵀ M Phi (3 x nm)
};

// A component's final mode set: columns of `shapes` are M-orthonormal and K-diagonal.
struct ModeSet {
  Eigen::MatrixXd shapes;          // n_dof x nm, full FE DOF vector (fixed DOFs hold zero)
  std::vector<ModeInfo> modes;     // nm entries, same order as columns, ascending frequency
  Eigen::VectorXd modal_stiffness;  // nm: omega_i^2 = phi_iᵀ K phi_i [1/s^2]
  std::vector<ModeInfo> rigid_modes;  // rigid-body modes found and set aside (free components)
  ModalInvariants invariants;
};

}  // namespace limber::modal
