// Equations of motion of one flexible body in the floating frame of reference
// (docs/multibody.md, "Flexible bodies"). With d(η) = m c + S_t η the first moment of the
// deformed body, J(η) = J0 + Σ η_i J1_i + Σ η_i η_j J2_ij its inertia about the frame
// origin and S(η) = S_r + Σ η_i B_i (B_i = Ψ_r_iᵀ M Φ) the rotation-deformation coupling
// (invariants: modal/mode_set.h), the kinetic energy is
//   T = ½ m ṙ·ṙ + ṙ·A (ω × d + S_t η̇) + ½ ωᵀ J ω + ωᵀ S η̇ + ½ η̇ᵀ η̇,
// i.e. the mass block, over v_b = [ṙ (ground), ω (body axes), η̇]:
//   M_b = [ m I          −A [d]×     A S_t ]
//         [ [d]× Aᵀ       J           S     ]
//         [ S_tᵀ Aᵀ       Sᵀ          I     ]
// (Shabana, Dynamics of Multibody Systems, 3rd ed., 2005, §5.5-5.6 with the inertia shape
// integrals replaced by their consistent-mass nodal counterparts). Lagrange's equations in
// the quasi-velocities ω (Euler–Poincaré on SO(3)) give the quadratic-velocity forces
//   Q_r = −A (ω × (ω × d) + 2 ω × S_t η̇)
//   Q_ω = −(J̇ ω + Ṡ η̇ + ω × (J ω + S η̇))
//   Q_η,k = ½ ωᵀ (∂J/∂η_k) ω + ω·(B_k η̇) − (Ṡᵀ ω)_k
// with J̇ = Σ η̇_k ∂J/∂η_k, Ṡ = Σ η̇_k B_k; gravity m g, d × Aᵀg, S_tᵀ Aᵀ g; elastic −ω_k² η_k
// and damping −c_k η̇_k; with geometric stiffening on (flexible_body.h), the centrifugal
// geometric stiffness −Σ ω_iω_j K_ij η (geometric_stiffening.h).
#pragma once

#include <Eigen/Dense>

#include "multibody/model.h"

namespace limber::multibody {

// M_b of the header, the body's own (6 + nm) square block. Precondition: body.kind == kFlexible.
Eigen::MatrixXd flexible_mass_block(const Body& body, const Eigen::VectorXd& q);

// Adds the quadratic-velocity, gravity, elastic and damping forces into Q (nv).
void add_flexible_forces(const Body& body, const Eigen::Vector3d& gravity_W, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v, Eigen::VectorXd& Q);

// Both of the above, the deformed inertia computed once (the evaluation pass of a residual):
// writes M_b into the body's diagonal block of M (nv x nv; the rest untouched) and adds the
// forces into Q.
void add_flexible_mass_matrix_and_forces(const Body& body, const Eigen::Vector3d& gravity_W,
                                         const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                         Eigen::MatrixXd& M, Eigen::VectorXd& Q);

// ½ v_bᵀ M_b v_b [J]; −g·(m r + A d(η)) [J]; strain energy ½ Σ ω_k² η_k² [J].
double flexible_kinetic_energy(const Body& body, const Eigen::VectorXd& q, const Eigen::VectorXd& v);
double flexible_gravity_potential(const Body& body, const Eigen::Vector3d& gravity_W, const Eigen::VectorXd& q);
double flexible_strain_energy(const Body& body, const Eigen::VectorXd& q);

}  // namespace limber::multibody
