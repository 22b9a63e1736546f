// What one body contributes to the equations of motion — the body abstraction. A rigid
// body implements it here; a flexible body (floating frame + modal coordinates η) adds its
// modal blocks behind the same functions (flexible_dynamics.h, flexible_marker.h;
// Shabana, Dynamics of Multibody Systems, 3rd ed., ch. 5; Nikravesh 1988, ch. 6 for the
// rigid case).
//
// Rigid body b with origin r, rotation A(p), centre of mass c (body frame), mass m, inertia
// J_o about the origin (J_o = J_c − m c̃c̃), velocities v_b = [ṙ; ω'] (ω' in body axes):
//   M_b = [ m I        −m A c̃ ]       Q_v = [ −m A (ω' × (ω' × c)) ]
//         [ m c̃ Aᵀ     J_o    ],            [ −ω' × J_o ω'        ]
// (kinetic energy ½ v_bᵀ M_b v_b; Q_v the quadratic-velocity forces).
#pragma once

#include <Eigen/Dense>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

// Kinematics of model.markers[marker]: a frame fixed on a rigid body (or ground), or on an
// FE node of a flexible body; the velocity-stage members (v_W, w_W, a_bias, alpha_bias)
// are filled only when v is non-null.
void marker_kinematics(const Model& model, int marker, const Eigen::VectorXd& q,
                       const Eigen::VectorXd* v, FrameKinematics& out);

// Makes out.J_p and out.J_w 3 x nv, zero in the columns of the body at v_offset (body_nv wide,
// which the caller then fills) and outside them. The columns outside stay zero between calls for
// the same body, so only the body's own are cleared again: clearing all nv columns of every
// marker in every pass was a tenth of a satellite deployment's run time.
void clear_frame_jacobians(int nv, int v_offset, int body_nv, FrameKinematics& out);

// Kinematics of the frame (p_BF, R_BF) fixed on the reference frame of body `body`
// (on a flexible body: a point of the floating frame, not of the material).
void body_frame_kinematics(const Model& model, int body, const Eigen::Vector3d& p_BF,
                           const Eigen::Matrix3d& R_BF, const Eigen::VectorXd& q,
                           const Eigen::VectorXd* v, FrameKinematics& out);

// M_b, the body's own block of M (its nv x nv; empty for ground).
Eigen::MatrixXd body_mass_block(const Model& model, int body, const Eigen::VectorXd& q);

// Adds the quadratic-velocity forces Q_v and the gravity force (m g at the centre of mass)
// into Q (nv); for a flexible body also its elastic and modal damping forces.
void add_body_inertial_and_gravity_forces(const Model& model, int body, const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& v, Eigen::VectorXd& Q);

// Generalized force of a force f_W and torque τ_W (ground axes) applied at a frame of
// known kinematics: Q += J_pᵀ f + J_wᵀ τ (virtual work).
void add_frame_load(const FrameKinematics& frame, const Eigen::Vector3d& f_W,
                    const Eigen::Vector3d& tau_W, Eigen::VectorXd& Q);

// Kinetic energy ½ v_bᵀ M_b v_b [J] and gravity potential −m g·r_c [J] of one body.
// (Strain energy of flexible bodies: flexible_dynamics.h.)
double body_kinetic_energy(const Model& model, int body, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v);
double body_gravity_potential(const Model& model, int body, const Eigen::VectorXd& q);

// Kinematic matrix block N_b (q̇_b = N_b v_b): I for r, ½ L(p)ᵀ for p, I for η. Written
// into N at the body's (q, v) block.
void set_body_kinematic_matrix(const Model& model, int body, const Eigen::VectorXd& q,
                               Eigen::MatrixXd& N);

// Maps a Jacobian w.r.t. v to one w.r.t. q for a function of q through the body's pose
// (with A(p) = A(p/|p|)): ∂f/∂q_b = ∂f/∂v_b · T_b, T_b = diag(I, 2 L(p̂)/|p|, I). Written
// into the columns of f_q for the body's q block, from the columns of f_v.
void map_body_jacobian_to_q(const Model& model, int body, const Eigen::VectorXd& q,
                            const Eigen::MatrixXd& f_v, Eigen::MatrixXd& f_q);

// q_out = q ⊕ dv for the body block: r + Δr, p ⊗ exp(Δω') (body-fixed increment), η + Δη.
void integrate_body_coordinates(const Model& model, int body, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& dv, Eigen::VectorXd& q_out);

}  // namespace limber::multibody
