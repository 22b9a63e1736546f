// The co-rotational beams of a nonlinear body (model.h, NonlinearBody) as internal forces
// between the rigid bodies that carry its FE nodes (docs/nonlinear-beams.md, "In a mechanism").
//
// Node body k of a nonlinear body has q = [r_WB, p_WB] and v = [ṙ_WB, ω_B] like any rigid
// body; its frame is along the FE component axes C at t = 0, so the node's configuration in
// the structure's own terms (beam_structure.h: component axes, rotation from the undeformed
// state) is
//   x_k = R_WCᵀ (r_WB − p_WC),   R_k = R_WCᵀ R_WB.
// A material spin δθ_B of the node body is the spatial spin R_k δθ_B of the structure's node, a
// ground translation δr_W its translation R_WCᵀ δr_W; with T = diag(R_WCᵀ, R_k) per node,
// the beams' generalized force and its stiffness in the body velocities are
//   Q = −Tᵀ f_int,   K = −∂Q/∂(δr_W, δθ_B) = Tᵀ (∂f_int/∂(δx, δw)) T + diag(0, S(R_kᵀ m_k))
// (the second term: the node's axes turning under the internal moment m_k; the same as
// nonlinear_beam/dynamic_solver.h's K_rot).
#pragma once

#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "multibody/model.h"
#include "nonlinear_beam/beam_structure.h"

namespace limber::multibody {

// The structure's configuration at q (above).
nonlinear_beam::BeamState nonlinear_body_state(const Model& model, const NonlinearBody& body,
                                               const Eigen::VectorXd& q);

// Q += −Tᵀ f_int over every nonlinear body of the model (Q: nv), with its Rayleigh damping
// (NonlinearBody::mass_damping α, stiffness_damping β), which acts on the deformation only:
//  - β: Kelvin–Voigt damping of each element's local deformations, f_l = K_l (p_l + β ṗ_l)
//    (nonlinear_beam/corotational_beam.h, DeformationRateDamping); a rigid velocity makes none;
//  - α: −α M (v − v_r) on the node bodies, v_r the M-orthogonal projection of v on the body's
//    six rigid velocities: no net force or moment on the body.
// On a free-free mode φ_i about the undeformed state both give c_i = α + β ω_i², the modal
// body's `damping: {rayleigh: [α, β]}`. `dissipation` (when given) += the power they remove [W].
void add_nonlinear_body_forces(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               Eigen::VectorXd& Q, double* dissipation = nullptr);

// The beams' stiffness K above as one nv x nv sparse matrix. Its pattern (every element's
// node-pair 6 x 6 blocks) is built on the first call, or when K has another size; later calls
// write the values in place, so the pattern stays the same. Returns false (K untouched) when
// the model has no nonlinear body.
bool nonlinear_body_stiffness(const Model& model, const Eigen::VectorXd& q, Eigen::SparseMatrix<double>& K);

// The damping above as C ≈ −∂Q/∂v (nv x nv sparse, the pattern of nonlinear_body_stiffness,
// written in place the same way): β's element blocks exactly, α M per node body without the
// rank-6 rigid projection (a Newton matrix: α h ≪ 1 makes what it leaves out small). Returns
// false (C untouched) when no nonlinear body is damped.
bool nonlinear_body_damping(const Model& model, const Eigen::VectorXd& q, Eigen::SparseMatrix<double>& C);

// Strain energy of the beams of every nonlinear body [J] (f_int is its gradient).
double nonlinear_body_strain_energy(const Model& model, const Eigen::VectorXd& q);

// The body's deflection probe at q: the probe node's displacement from the chord between the
// two chord nodes (interpolated at the node's projection on the undeformed chord), in the
// component axes turned by the smallest rotation that takes the undeformed chord onto the
// current one, minus its undeformed value [m]. The modal body's probe (flexible_body.h) in
// the nonlinear body's terms. Precondition: body.deflection_probe is set.
Eigen::Vector3d nonlinear_probe_deflection(const Model& model, const NonlinearBody& body,
                                           const Eigen::VectorXd& q);

// For every model body: the nonlinear body whose node it carries, or −1.
std::vector<int> nonlinear_body_of(const Model& model);

// The velocities in which every nonlinear body moves rigidly (nv x n): each body outside them
// keeps its own columns; each nonlinear body gets 6, the velocity of its FE component origin and
// its angular velocity (ground axes). Used to start a nonlinear body moving as a rigid one when
// the velocities are projected onto the constraints (assembly.h), as the modal body's frame does.
Eigen::MatrixXd rigid_nonlinear_velocity_basis(const Model& model, const Eigen::VectorXd& q);

}  // namespace limber::multibody
