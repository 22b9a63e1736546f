// Kinematics of a frame on an FE node of a flexible body: it follows the frame's motion
// and the node's elastic translation u = Φ_t η and small rotation θ = Φ_r η (the nodal
// rotational rows of the mode shapes; PITFALLS.md). With s = x_p + u:
//   p = r + A s,                      R = A exp([θ]×) R_BF,
//   ṗ = ṙ − A [s]× ω + A Φ_t η̇,      ω_F = A (ω + J_l(θ) Φ_r η̇)
// (J_l the left Jacobian of SO(3), rotation.h: exp keeps R orthonormal, so every joint
// equation sees a true frame), and the bias accelerations
//   ā = A (ω × (ω × s) + 2 ω × u̇),   ᾱ = A (ω × J_l θ̇ + J̇_l θ̇).
#pragma once

#include <Eigen/Dense>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

// Fills `out` (J_p, J_w sized 3 x model.nv) for the frame R_BF (body axes, undeformed) at
// node `node` of flexible body `body`; the velocity stage only when v is non-null.
void node_frame_kinematics(const Model& model, int body, int node, const Eigen::Matrix3d& R_BF,
                           const Eigen::VectorXd& q, const Eigen::VectorXd* v, FrameKinematics& out);

}  // namespace limber::multibody
