// Inertia invariants of a reduced flexible body in the floating frame of reference,
// computed from the FE mass matrix M (consistent, rotational DOFs included) — the nodal,
// consistent-mass generalisation of Shabana's inertia shape integrals (Shabana, "Dynamics
// of Multibody Systems", 3rd ed., Cambridge 2005, ch. 5; Zwölfer & Gerstmayr, "A concise
// nodal-based derivation of the floating frame of reference formulation", Multibody Syst.
// Dyn. 49, 2020).
//
// Psi = [Psi_t Psi_r] are the rigid-body modes about the frame origin (rigid_body_modes.h)
// and Phi = [phi_1 ... phi_nm] the mode shapes (n x nm). The deformed body's rotation
// field is Psi_r(eta) = Psi_r + sum_i eta_i Psi_r_i, where Psi_r_i (n x 3) is built from
// the translational part of phi_i: at node p, translational rows of column k are
// e_k × phi_i,t(p) (= -[phi_i,t(p)]× e_k), rotational rows are zero. Psi_r(eta) is thus
// exactly Psi_r rebuilt at the deformed node positions x_p + sum_i eta_i phi_i,t(p).
//
// Terms (component-frame axes; mass-normalised modes, so phi is in kg^-1/2 and eta in
// kg^1/2 m):
//   mass                         m     = trace(Psi_t^T M Psi_t) / 3   (Psi_t^T M Psi_t = m I) [kg]
//   first_moment                 m c,  from Psi_t^T M Psi_r = -[m c]×                     [kg m]
//   inertia                      J0    = Psi_r^T M Psi_r  (about the frame origin)      [kg m^2]
//   translation_coupling         S_t   = Psi_t^T M Phi    (3 x nm)                      [kg^1/2]
//   rotation_coupling            S_r   = Psi_r^T M Phi    (3 x nm)                    [kg^1/2 m]
//   inertia_first_order[i]       J1_i  = Psi_r^T M Psi_r_i + (Psi_r^T M Psi_r_i)^T    [kg^1/2 m]
//   inertia_second_order[i*nm+j] J2_ij = Psi_r_i^T M Psi_r_j                                [-]
//   rotation_coupling_first_order[i] = Psi_r_i^T M Phi  (3 x nm)                            [-]
// so that J(eta) = Psi_r(eta)^T M Psi_r(eta) = J0 + sum_i eta_i J1_i + sum_ij eta_i eta_j J2_ij
// exactly (J is quadratic in eta), and the rotation-deformation coupling of the deformed
// body is S_r + sum_i eta_i Psi_r_i^T M Phi.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "modal/mode_set.h"

namespace limber::modal {

// Psi_r_i of one mode shape (n x 3), as defined above. shape has n = 6 x nodes rows.
Eigen::MatrixXd rotation_field(const Eigen::VectorXd& shape);

// All invariants. Preconditions (DEMAND): M n x n, psi n x 6, shapes n x nm.
ModalInvariants compute_modal_invariants(const Eigen::SparseMatrix<double>& mass,
                                         const Eigen::MatrixXd& psi,
                                         const Eigen::MatrixXd& shapes);

}  // namespace limber::modal
