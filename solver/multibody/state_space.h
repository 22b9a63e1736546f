// State-space model of a linearized mechanism (docs/linearize.md, "State space"): with the
// tangent matrices of linearization.h on the motions the joints allow, ξ = Z y,
//   Mr ÿ + Cr ẏ + Kr y = Zᵀ B_ξ u,    Mr, Cr, Kr = Zᵀ (M, C, K) Z,
// and the state x = [y; ẏ] (2n; y in the null-space coordinates, ẏ their rates):
//   ẋ = A x + B u,   A = [0 I; −Mr⁻¹Kr −Mr⁻¹Cr],   B = [0; Mr⁻¹ Zᵀ B_ξ],
//   out = C x + D u.
// Inputs u: a force or a torque at a marker (three channels, ground or marker axes, the axes
// at the linearization point), an actuator torque added to an RSDA (one channel, on body j
// about the RSDA's axis, −τ on body i, as its spring torque), or a driver's effort (one
// channel: the driver is released, its coordinate a free motion of this model, and u the
// effort's deviation from its value λ0 at the point, which stays applied). B_ξ holds their
// generalized forces J_pᵀ f, J_wᵀ τ (virtual work, body.h add_frame_load), G_dᵀ u for an
// effort (reactions.h: effort = −λ_driver, the driver row's generalized force). With efforts
// the states are on Z_u = null(G_i without the released drivers' rows), which holds the
// joints' Z and the drivers' coordinates; Kr and Cr keep the released rows' G_dᵀλ0 terms, so
// the point stays an equilibrium of the released model. Outputs: a marker's
// displacement, velocity and acceleration, small rotation, angular velocity and angular
// acceleration (three channels each), from J_p Z and J_w Z; accelerations take ÿ from the
// second block row of A and B, so they have a D; a joint's reaction force and torque on its
// body j (linear_reactions.h: the multiplier solve linearized), which has one too. All are
// deviations from the values at the linearization point; about a state in motion the J̇ v
// terms of the accelerations are left out (the linearization is then indicative only, as the
// modes are; the reactions are exact to first order there too).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "multibody/linearization.h"
#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

enum class LinearInputKind { kForce, kTorque, kRsdaTorque, kDriverEffort };
enum class LinearOutputKind {
  kPosition, kVelocity, kAcceleration, kRotation, kAngularVelocity, kAngularAcceleration,
  kReactionForce, kReactionTorque  // of a joint on its body j (reactions.h), linear_reactions.h
};

// Components along ground axes or along the marker's axes at the linearization point; for a
// joint's reaction, along its marker j's axes as they move (the joint frame, reactions.h).
enum class ChannelAxes { kGround, kMarker };

struct LinearInput {
  std::string name;  // channels "<name>.x", ".y", ".z" [N, N m]; "<name>" for an RSDA torque
                     // [N m] and for a driver's effort [N m about z_i, or N along z_i, on body j]
  LinearInputKind kind = LinearInputKind::kForce;
  int marker = -1;  // kForce, kTorque: the marker the load acts at
  int force = -1;   // kRsdaTorque: index of an Rsda in model.forces
  ChannelAxes axes = ChannelAxes::kGround;
  int driver = -1;  // kDriverEffort: index in model.drivers (the driver released)
};

struct LinearOutput {
  std::string name;  // channels "<name>.x", ".y", ".z" [m, m/s, m/s², rad, rad/s, rad/s², N, N m]
  LinearOutputKind kind = LinearOutputKind::kPosition;
  int marker = -1;  // the marker of a kinematic output
  ChannelAxes axes = ChannelAxes::kGround;
  int joint = -1;   // kReactionForce, kReactionTorque: index in model.joints
};

struct StateSpace {
  Eigen::MatrixXd A, B, C, D;  // 2n x 2n, 2n x ni, no x 2n, no x ni
  Eigen::MatrixXd Z;           // nv x n: ξ = Z y, the joints' basis, or Z_u with driver efforts
  std::vector<std::string> state_names;   // "y1" ... "yn", "y1_dot" ... "yn_dot"
  std::vector<std::string> input_names;   // ni channels
  std::vector<std::string> output_names;  // no channels
};

// The model above at `point` with the tangent matrices and the basis Z (nv x n) of
// linearization.h. Preconditions (DEMAND): markers, joints, RSDA and driver indices valid (the
// case reader checks the names). Throws NumericalError when Zᵀ M Z is not positive definite,
// InputError for the reaction of a joint whose equations are not all independent at the point
// (redundant or released: its reaction is not determined), and InputError for a driver's effort
// whose equation is redundant there (another joint holds its coordinate: no effort of its own).
StateSpace state_space(const Model& model, const State& point, const TangentMatrices& tangent,
                       const Eigen::MatrixXd& Z, const std::vector<LinearInput>& inputs,
                       const std::vector<LinearOutput>& outputs);

}  // namespace limber::multibody
