// State-space model of a linearized mechanism (docs/linearize.md, "State space"): with the
// tangent matrices of linearization.h on the motions the joints allow, ξ = Z y,
//   Mr ÿ + Cr ẏ + Kr y = Zᵀ B_ξ u,    Mr, Cr, Kr = Zᵀ (M, C, K) Z,
// and the state x = [y; ẏ] (2n; y in the null-space coordinates, ẏ their rates):
//   ẋ = A x + B u,   A = [0 I; −Mr⁻¹Kr −Mr⁻¹Cr],   B = [0; Mr⁻¹ Zᵀ B_ξ],
//   out = C x + D u.
// Inputs u: a force or a torque at a marker (three channels, ground or marker axes, the axes
// at the linearization point), or an actuator torque added to an RSDA (one channel, on body j
// about the RSDA's axis, −τ on body i, as its spring torque). B_ξ holds their generalized
// forces J_pᵀ f, J_wᵀ τ (virtual work, body.h add_frame_load). Outputs: a marker's
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

enum class LinearInputKind { kForce, kTorque, kRsdaTorque };
enum class LinearOutputKind {
  kPosition, kVelocity, kAcceleration, kRotation, kAngularVelocity, kAngularAcceleration,
  kReactionForce, kReactionTorque  // of a joint on its body j (reactions.h), linear_reactions.h
};

// Components along ground axes or along the marker's axes at the linearization point; for a
// joint's reaction, along its marker j's axes as they move (the joint frame, reactions.h).
enum class ChannelAxes { kGround, kMarker };

struct LinearInput {
  std::string name;  // channels "<name>.x", ".y", ".z" [N, N m]; "<name>" for an RSDA torque [N m]
  LinearInputKind kind = LinearInputKind::kForce;
  int marker = -1;  // kForce, kTorque: the marker the load acts at
  int force = -1;   // kRsdaTorque: index of an Rsda in model.forces
  ChannelAxes axes = ChannelAxes::kGround;
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
  std::vector<std::string> state_names;   // "y1" ... "yn", "y1_dot" ... "yn_dot"
  std::vector<std::string> input_names;   // ni channels
  std::vector<std::string> output_names;  // no channels
};

// The model above at `point` with the tangent matrices and the basis Z (nv x n) of
// linearization.h. Preconditions (DEMAND): markers, joints and RSDA indices valid (the case
// reader checks the names). Throws NumericalError when Zᵀ M Z is not positive definite, and
// InputError for the reaction of a joint whose equations are not all independent at the point
// (redundant or released: its reaction is not determined).
StateSpace state_space(const Model& model, const State& point, const TangentMatrices& tangent,
                       const Eigen::MatrixXd& Z, const std::vector<LinearInput>& inputs,
                       const std::vector<LinearOutput>& outputs);

}  // namespace limber::multibody
