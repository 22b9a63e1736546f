// Run-time geometric stiffening of flexible bodies (docs/geometric-stiffening.md): the
// modal geometric-stiffness matrices of modal/geometric_stiffness.h, precomputed per unit
// load case, scaled by the current loads (the SID-file approach of Wallrapp, Mech. Struct.
// Mach. 22(3), 1994), added to the modal equations as
//   Q_η −= K_geo η,   K_geo = Σ_c p_c(ω) K_c + Σ_k α_k K_α,k + Σ_k a_k K_a,k
//                            + Σ_nodes Σ_k (F_k K_F,k + T_k K_T,k)
// with p_c the products ω_x², ω_y², ω_z², ω_xω_y, ω_yω_z, ω_zω_x of the frame's angular
// velocity, α its angular acceleration, a = Aᵀ(r̈ − g) its translational acceleration less
// gravity, and F, T the forces and moments on the body at its load nodes (joint reactions,
// driver efforts, springs, dampers, actuators, point loads, locked hinge limits), body axes.
// Only the modal equations get the term: the frame equations lack the matching second-order
// terms, so energy is conserved to first order in the loads only (the SID convention).
#pragma once

#include <Eigen/Dense>

#include "modal/geometric_stiffness.h"
#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

// (Σ_c p_c(ω) K_c) η (nm) for the angular velocity w_B [rad/s, body axes] and modal
// coordinates eta [kg^½ m].
Eigen::VectorXd centrifugal_geometric_force(const modal::ModalGeometricStiffness& g, const Eigen::Vector3d& w_B,
                                            const Eigen::VectorXd& eta);

// The instantaneous accelerations and multipliers of M v̇ + Gᵀ λ = Q, G v̇ = γ at one state,
// for M SPD and any G. With L Lᵀ = M and B = G L⁻ᵀ: y = Lᵀ v̇ is the point of {B y = γ}
// nearest to L⁻¹ Q (Gauss's principle of least constraint), y = L⁻¹Q − Bᵀλ with
// B Bᵀ λ = B L⁻¹ Q − γ; redundant rows: the minimum-norm λ, singular values of B below the
// redundancy analysis' threshold (redundancy.h) times the largest taken as zero.
struct AccelerationEstimate {
  Eigen::VectorXd v_dot;   // nv
  Eigen::VectorXd lambda;  // rows of G
};
AccelerationEstimate estimate_accelerations(const Eigen::MatrixXd& M, const Eigen::MatrixXd& G,
                                            const Eigen::VectorXd& Q, const Eigen::VectorXd& gamma);

// True when some body has GeometricStiffening::kFull (its loads need v̇ and λ).
bool has_load_stiffening(const Model& model);

// The loads of every body with GeometricStiffening::kFull at `state` (the other bodies'
// entries stay empty), from the accelerations v_dot (nv) and the multipliers lambda of all
// rows of ws.G (model.num_equations()): the frame's accelerations, and at the load nodes
// (markers on nodes listed in geometric.load_nodes) the joints' reactions with the efforts of
// their drivers (the wrench of −G_kᵀλ_k, as reactions.h) and the force elements' loads
// (dynamics.h, force_element_loads), as forces and moments.
// Precondition: ws.G and ws.markers evaluated at `state`. Updates ws.markers (velocity stage).
std::vector<StiffeningLoads> stiffening_loads(const Model& model, const State& state, const Eigen::VectorXd& v_dot,
                                              const Eigen::VectorXd& lambda, Workspace& ws);

// The loads solved for at `state` itself: estimate_accelerations from ws.Q as it stands (the
// forces so far; first order: the load-dependent terms are not in the estimate), then
// stiffening_loads. Updates ws.M, ws.G, ws.g, ws.g_t, ws.gamma and ws.markers (velocity stage).
std::vector<StiffeningLoads> solved_stiffening_loads(const Model& model, const State& state, Workspace& ws);

// The loads of an integrator's accepted step: its accelerations v_dot and the multipliers
// lambda_rows of the rows `rows` of ws.G (the partition's independent rows, redundancy.h),
// the other rows carrying none: the indeterminate part of redundant joints' loads goes where
// the partition puts it, not spread by least norm as in estimate_accelerations (a least-norm
// spread of the integrator's Gᵀλ over the raw rows blew up on the seed's set-up, whose
// deformation makes its redundant row R2.rot_x slightly independent). No solve of the
// equations of motion: v̇ and λ satisfy them already.
// Precondition: ws.G and ws.markers evaluated at `state` (velocity stage).
std::vector<StiffeningLoads> accepted_step_stiffening_loads(const Model& model, const State& state,
                                                            const Eigen::VectorXd& v_dot, const std::vector<int>& rows,
                                                            const Eigen::VectorXd& lambda_rows, Workspace& ws);

// For every flexible body with GeometricStiffening::kFull, adds −(K_geo − centrifugal part) η
// to ws.Q (the centrifugal part is added with the body's other forces, flexible_dynamics.h),
// K_geo scaled by state.stiffening: the loads of the last accepted step, lagging the state by
// up to one step (an error O(h) in the loads, docs/geometric-stiffening.md). When the state
// carries none (one-off evaluations: statics, linearisation, reactions, an integrator's
// consistent start), the loads are solved_stiffening_loads at the state, whose updates of ws
// then apply. A no-op when no body asks for kFull.
// When `power` is non-null, also adds the power of these forces, −Σ η̇ᵀ (K_geo − centrifugal) η [W].
void add_load_geometric_stiffness(const Model& model, const State& state, Workspace& ws, double* power = nullptr);

}  // namespace limber::multibody
