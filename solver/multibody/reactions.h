// Joint reactions and driver efforts from the equations of motion
//   M v̇ + G_fullᵀ λ = Q   →   λ = minimum-norm solution of G_fullᵀ λ = Q − M v̇
// (unique when no equation is redundant; for redundant rows the minimum-norm choice over
// the equations as defined — rows in N or N·m — is one of infinitely many, and the joints
// concerned are flagged indeterminate; see redundancy.h).
// Multipliers are not forces (they are conjugate to the constraint equations): joint k
// applies the generalized force Q_k = −G_kᵀ λ_k, and for body j the force F and torque T
// at the origin of marker j are the solution of [J_p; J_w]ᵀ [F; T] = Q_k restricted to
// body j's velocities (exact for a rigid body: the 6 x 6 matrix is invertible). The
// reaction on body i follows from equilibrium of the joint: F_i = −F_j and
// T_i = −T_j − (p_j − p_i) × F_j about marker i's origin.
// Conventions (docs/multibody.md): "on body j, joint frame" = axes of marker j, about its
// origin; driver equations are not part of a joint's reaction: the driver effort is
// reported separately, effort = −λ_driver = torque about z_i [N·m] or force along z_i [N]
// applied by the driver on body j.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"

namespace limber::multibody {

struct JointReaction {
  Eigen::Vector3d point_W = Eigen::Vector3d::Zero();  // origin of marker j [m]
  // On body j, about the origin of marker j: ground axes and marker-j axes [N, N·m].
  Eigen::Vector3d force_j_W = Eigen::Vector3d::Zero(), torque_j_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_j_J = Eigen::Vector3d::Zero(), torque_j_J = Eigen::Vector3d::Zero();
  // On body i, about the origin of marker i: ground axes and marker-i axes.
  Eigen::Vector3d force_i_W = Eigen::Vector3d::Zero(), torque_i_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_i_I = Eigen::Vector3d::Zero(), torque_i_I = Eigen::Vector3d::Zero();
  bool indeterminate = false;
};

struct Reactions {
  Eigen::VectorXd lambda;               // all rows of the model
  std::vector<JointReaction> joints;    // per model joint
  std::vector<double> driver_efforts;   // per model driver [N·m or N]
  double driver_power = 0.0;            // Σ effort · ḟ(t) [W]
};

// The wrench of joint `joint` on body j about the origin of marker j, ground axes, [F; T]
// (6 x the joint's rows) per unit multiplier of its rows: [F; T] = W λ_k. Linear in λ_k at
// fixed kinematics, from ws.G and ws.markers (constraints evaluated at `state`'s positions).
Eigen::Matrix<double, 6, Eigen::Dynamic> joint_wrench_map(const Model& model, const Workspace& ws, int joint);

// Precondition: v_dot satisfies the equations of motion at `state` (e.g. from
// solve_accelerations or an integrator). Updates ws.
Reactions compute_reactions(const Model& model, const State& state, const Eigen::VectorXd& v_dot,
                            const ConstraintPartition& partition, Workspace& ws);

// The same from an integrator's multipliers of the independent rows (ordered as
// partition.independent): G_indᵀ λ_ind stands for Q − M v̇, so neither the mass matrix nor the
// forces are evaluated (half the cost of compute_reactions, for reactions at every step).
// Equal to compute_reactions to the integrator's convergence of the equations of motion.
Reactions reactions_from_multipliers(const Model& model, const State& state,
                                     const Eigen::VectorXd& lambda_independent,
                                     const ConstraintPartition& partition, Workspace& ws);

}  // namespace limber::multibody
