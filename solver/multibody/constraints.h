// The full set of constraint equations of a model (joints then drivers), with their
// velocity Jacobian and acceleration right-hand side, exact (no finite differences):
//   g(t,q) = 0,   ġ = G v + g_t = 0,   G v̇ = γ(t,q,v)   (γ = −Ġ v − ∂g_t/∂t).
// Primitives on markers i, j with axes a_i, b_j, d = p_j − p_i, ω angular velocities,
// ᾱ, ā the bias accelerations of FrameKinematics (Haug 1989, §9.2; Nikravesh 1988, §7.3):
//   dot1  g = a·b        G = (a×b)ᵀ (J_wi − J_wj)
//         γ = −(a×b)·(ᾱ_i − ᾱ_j) − ((ω_i×a)×b + a×(ω_j×b))·(ω_i − ω_j)
//   dot2  g = a·d − f    G = (a×d)ᵀ J_wi + aᵀ (J_pj − J_pi),   g_t = −ḟ
//         γ = −ᾱ_i·(a×d) − ω_i·((ω_i×a)×d + a×ḋ) − (ω_i×a)·ḋ − a·(ā_j − ā_i) + f̈
//   angle g = wrap(θ − f) with θ = atan2(x_j·y_i, x_j·x_i), θ̇ = u·(ω_j − ω_i) (see
//         relative_angle), G = uᵀ (J_wj − J_wi), g_t = −ḟ, γ = −u·(ᾱ_j − ᾱ_i) − u̇·(ω_j − ω_i) + f̈.
#pragma once

#include <Eigen/Dense>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

enum class Stage { kPosition, kVelocity };

// Marker kinematics for all markers into ws.markers (velocity stage needs state.v).
void update_marker_kinematics(const Model& model, const State& state, Stage stage, Workspace& ws);

// Fills ws.g, ws.G, ws.g_t (always) and ws.gamma (velocity stage), all rows of the model.
// Updates ws.markers first.
void evaluate_constraints(const Model& model, const State& state, Stage stage, Workspace& ws);

// The same from ws.markers as they are: updated at `state` at `stage` or the velocity stage
// (e.g. by mass_matrix_and_forces, dynamics.h), so that one pass computes them once.
void evaluate_constraint_rows(const Model& model, const State& state, Stage stage, Workspace& ws);

// Largest residuals over all rows but those flagged in `released` (rows of released joints,
// redundancy.h's rows_released_by; empty: none): max |g| [m or rad] and max |G v + g_t|
// [m/s or rad/s] (the results file's constraint-violation norms). Updates ws.
struct ConstraintViolation {
  double position = 0.0;
  double velocity = 0.0;
};
ConstraintViolation constraint_violation(const Model& model, const State& state, Workspace& ws,
                                         const std::vector<bool>& released = {});

// Rotation angle of marker j about z_i: θ = atan2(x_j·y_i, x_j·x_i) ∈ (−π, π] [rad];
// θ̇ = u·(ω_j − ω_i) exactly (u = (c ∂s − s ∂c)/(c² + s²), s, c the two dot products), and
// θ̈ = u·(J_wj − J_wi) v̇ + bias.
struct RelativeAngle {
  double theta = 0.0;
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  double rate = 0.0;  // θ̇ (velocity stage)
  double bias = 0.0;  // θ̈ − u·(J_wj − J_wi) v̇ (velocity stage)
};
RelativeAngle relative_angle(const FrameKinematics& marker_i, const FrameKinematics& marker_j,
                             Stage stage);

// x − 2π k in (−π, π].
double wrap_angle(double x);

}  // namespace limber::multibody
