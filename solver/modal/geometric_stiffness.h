// Modal geometric-stiffness matrices of one component per unit load case, for the
// geometric stiffening (softening) of a floating-frame body (docs/geometric-stiffening.md).
//
// The approach of the "geometric stiffness" terms of the Standard Input Data (SID) of a
// flexible body (Wallrapp, "Standardization of flexible body modeling in multibody system
// codes, Part I: Definition of standard input data", Mech. Struct. Mach. 22(3), 1994;
// Wallrapp & Wiedemann, "Simulation of deployment of a flexible solar array", Multibody
// Syst. Dyn. 7, 2002, for the linear superposition of unit load cases; the same first-order
// terms in Shabana, "Dynamics of Multibody Systems", 3rd ed., 2005, ch. 5): the stress state
// is linear in the loads, the geometric stiffness linear in the stresses, so
//   K_geo(t) = Σ_k λ_k(t) K_G,k,   K_G,k = Φᵀ K_G(σ_k) Φ   (nm x nm),
// where σ_k is the static stress state of the FE model under unit load case k and λ_k(t) the
// current value of that load. For each case:
//   1. the load f_k (n, full DOF vector, body axes) below;
//   2. the static response u_k (modal/static_modes.h, compute_static_responses): clamped
//      parts K_ff u = f_f; free or partly held parts with inertia relief (the load balanced by
//      the inertia of the free rigid motion, Craig & Chang 1977), as for attachment modes;
//   3. the axial force of every beam element and the membrane forces of every shell element
//      from u_k, their geometric stiffness (fe/beam_geometric_stiffness.h,
//      fe/shell_geometric_stiffness.h), projected on the modes element by element.
// Load cases, all in body axes (the inertia loads are the d'Alembert forces −M a of the
// frame's rigid acceleration field a, translational rows; nodal rotational inertia ignored):
//   centrifugal c (6): a_p = S_c x_p for the products ω_x², ω_y², ω_z², ω_xω_y, ω_yω_z,
//       ω_zω_x in that order, from ω×(ω×x) = (ωωᵀ − |ω|² I) x: S = e_i e_iᵀ − I for a square,
//       e_i e_jᵀ + e_j e_iᵀ for a product. Per unit (rad/s)².
//   angular acceleration (3): a_p = e_k × x_p (and e_k on the rotational rows). Per rad/s².
//   translational acceleration (3): a_p = e_k. Per m/s².
//   node force (3 per load node): a unit force along e_k at the node's translational DOFs. Per N.
//   node moment (3 per load node): a unit moment about e_k at the node's rotational DOFs. Per N·m.
//       On a straight beam a moment makes no axial force (its matrices vanish); on a frame or a
//       curved part it does (the legs of an L-frame carry the moment's couple as axial forces).
// For a free-free component the two acceleration cases are rigid-body inertia fields that
// inertia relief balances exactly: their matrices are zero (to round-off), as they should be.
// The node cases take any load at a load node: joint and driver reactions, springs, point
// loads (multibody/geometric_stiffening.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fe/assembly.h"
#include "fe/fe_model.h"
#include "modal/modal_status.h"

namespace limber::modal {

struct ModalGeometricStiffness {
  // Each matrix nm x nm, symmetric; modal units (η in kg^½ m): K_G,k η is a modal force per
  // unit load, so ω² K_centrifugal is in 1/s² like the modal stiffness ω_i².
  std::array<Eigen::MatrixXd, 6> centrifugal;               // per (rad/s)²: xx yy zz xy yz zx
  std::array<Eigen::MatrixXd, 3> angular_acceleration;      // per rad/s², body axes
  std::array<Eigen::MatrixXd, 3> translational_acceleration;  // per m/s², body axes
  std::vector<int> load_nodes;                              // node indices
  std::vector<std::array<Eigen::MatrixXd, 3>> node_forces;   // per N, body axes, one per load node
  std::vector<std::array<Eigen::MatrixXd, 3>> node_moments;  // per N·m, body axes, one per load node
};

struct ModalGeometricStiffnessResult {
  ModalStatus status = ModalStatus::kOk;  // kSingular when the static solve fails
  std::string message;
  ModalGeometricStiffness stiffness;
};

// The load vectors f_k (n x (12 + 6 load nodes)) of the cases above, in that order (per load
// node: its three forces, then its three moments).
// Preconditions (DEMAND): load nodes within the model.
Eigen::MatrixXd geometric_stiffness_load_cases(const fe::FeModel& model, const fe::SparseMatrix& mass,
                                               const std::vector<int>& load_nodes);

// Φᵀ K_G Φ summed over the beam and shell elements, their axial and membrane forces from the
// FE displacement `u` (n).
Eigen::MatrixXd projected_geometric_stiffness(const fe::FeModel& model, const Eigen::MatrixXd& shapes,
                                              const Eigen::VectorXd& u);

// All cases for the mode shapes `shapes` (n x nm, modal/mode_set.h) of `model`, whose
// assembled K and M are `matrices`. Preconditions (DEMAND): shapes has n rows, load nodes in
// range. Throws InputError for a degenerate element, as fe::assemble does first.
ModalGeometricStiffnessResult compute_modal_geometric_stiffness(const fe::FeModel& model,
                                                                const fe::StructuralMatrices& matrices,
                                                                const Eigen::MatrixXd& shapes,
                                                                const std::vector<int>& load_nodes);

}  // namespace limber::modal
