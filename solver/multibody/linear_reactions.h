// Joint reactions as outputs of the state-space model (state_space.h; docs/linearize.md,
// "Joint reactions"). The reaction of joint k on its body j is [F; T] = W_k(q) λ_k
// (reactions.h, joint_wrench_map), so to first order about the point
//   δ[F; T] = W_k(q0) δλ_k + ∂(W_k(q) λ0_k)/∂ξ ξ,
// with δλ from the multiplier solve [M G_iᵀ; G_i 0][v̇; λ] = [Q; γ_i] linearized:
//   [M G_iᵀ; G_i 0] [δv̇; δλ] = [−K ξ − C δv + B_ξ u;  −A_ξ ξ − A_v δv],
//   A(q, v) = G_i(q) v̇0 − γ_i(q, v),   ξ = Z y,  δv = Z ẏ,
// K and C the tangent matrices (linearization.h: ∂r/∂ξ and ∂r/∂v of r = M v̇0 + G_iᵀλ0 − Q),
// and A's derivatives and the wrench's by central differences (ε = 1e-6, error O(ε²)), as K
// is formed. About an equilibrium A's derivatives vanish (v0 = 0, v̇0 = 0, drivers held) and
// δv̇ = Z ÿ; about a state in motion the result is still the derivative of the nonlinear
// reaction, which tests/multibody/linear_reactions_test.cpp checks by differences.
#pragma once

#include <Eigen/Core>

#include "multibody/linearization.h"
#include "multibody/model.h"
#include "multibody/state.h"
#include "multibody/state_space.h"

namespace limber::multibody {

// δλ (of tangent.rows) = of_state x + of_input u, x = [y; ẏ].
struct LinearMultipliers {
  Eigen::MatrixXd of_state;  // nc x 2n
  Eigen::MatrixXd of_input;  // nc x ni
};

// The linearized multiplier solve at `point` for the inputs' generalized forces B_xi (nv x ni).
LinearMultipliers linear_multipliers(const Model& model, const State& point, const TangentMatrices& tangent,
                                     const Eigen::MatrixXd& Z, const Eigen::MatrixXd& B_xi);

// The three rows of C (3 x 2n) and D (3 x ni) of a kReactionForce or kReactionTorque output,
// ground axes or joint axes (marker j's, moving with it). Throws InputError naming the output
// and the joint when one of the joint's equations is not among tangent.rows (redundant at the
// point, or released: its reaction is not determined or is nil).
void reaction_rows(const Model& model, const State& point, const TangentMatrices& tangent, const Eigen::MatrixXd& Z,
                   const LinearMultipliers& multipliers, const LinearOutput& output, Eigen::MatrixXd& C_rows,
                   Eigen::MatrixXd& D_rows);

}  // namespace limber::multibody
