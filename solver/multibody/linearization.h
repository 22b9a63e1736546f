// Linearization of a mechanism about one state (docs/linearize.md): the tangent mass, damping
// and stiffness of the equations of motion (dynamics.h)
//   r(q, v, v̇) = M(q) v̇ + G_i(q)ᵀ λ − Q(t, q, v) = 0,   G_i(q) v = 0 (drivers held),
// for small motions q = q0 ⊕ ξ, v = ξ̇ about (q0, v0) with λ = λ0 and v̇ = v̇0 of that state:
//   M = M(q0),  C = ∂r/∂v,  K = ∂r/∂ξ   (nv x nv; ξ, v per body: ṙ ground, ω body, η̇),
// C and K by central differences of r (ε = 1e-6, error O(ε²)), as statics.h forms its tangent,
// so every force element, latch in its mode, the joints' geometric stiffness ∂(G_iᵀλ)/∂ξ and
// M(q)v̇0 away from equilibrium are in them without a derivative of their own.
// The motions the joints allow are ξ = Z y with Z an orthonormal basis of null(G_i), from the
// SVD of G_i (rank revealed at the redundancy analysis' relative threshold, so redundant rows
// cost nothing and a rank loss is detected): Mr = Zᵀ M Z, Cr = Zᵀ C Z, Kr = Zᵀ K Z.
// The mode problem Mr ÿ + Cr ẏ + Kr y = 0 is solved twice: undamped (the symmetric part of Kr,
// a generalized symmetric eigenproblem: normal modes, mass-normalized shapes) and as the first
// order 2n problem [0 I; −K̃ −C̃] in the elastic normal modes' coordinates, which gives each
// mode's damped natural frequency |s| and damping ratio −Re s / |s| (Eigen's real Schur).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"

namespace limber::multibody {

// A mode is rigid (a zero frequency) when ω ≤ this fraction of the largest ω of the problem.
// The central differences leave ≈ 1e-10 of the largest stiffness entry as noise on K (rounding
// 1e-16 / ε with ε = 1e-6), i.e. ω ≈ 1e-5 ω_max on a mode that has none; ten times that.
inline constexpr double kRigidFrequencyFraction = 1e-4;

struct TangentMatrices {
  Eigen::MatrixXd M, C, K;     // nv x nv [kg, kg m, kg m²; N s/m ...; N/m ...]
  Eigen::MatrixXd G;           // the constraint rows held (independent ones, plus any extra)
  std::vector<int> rows;       // their indices among the model's equations
  Eigen::VectorXd vdot, lambda;  // v̇0 and λ0 of the state (zero v̇0 at an equilibrium)
};

enum class LinearizationStatus { kOk, kSingularConstraints };

// Tangent matrices at `state` with the independent rows of `partition`. v̇0 and λ0 are solved
// from [M G_iᵀ; G_i 0] at the state. A G_i that has lost rank at the state (a singular
// configuration) returns kSingularConstraints with the rows' joints in `message`.
LinearizationStatus tangent_matrices(const Model& model, const ConstraintPartition& partition,
                                     const State& state, TangentMatrices& out, std::string& message);

// q ⊕ ξ, body by body (body.h integrate_body_coordinates): the configuration displaced by ξ.
Eigen::VectorXd displaced_coordinates(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& xi);

// An orthonormal basis (nv x n) of the null space of G by SVD, rank at relative threshold
// kRedundancyThreshold.
Eigen::MatrixXd null_space_basis(const Eigen::MatrixXd& G, int nv);

// The Cholesky factor of Mr = Zᵀ M Z (symmetrized). Throws NumericalError when Mr is not
// positive definite (a free motion without inertia).
Eigen::LLT<Eigen::MatrixXd> reduced_mass_factor(const Eigen::MatrixXd& M, const Eigen::MatrixXd& Z);

struct SystemModes {
  // Entries in ascending frequencies_hz: unstable ones (negative) first, then the rigid zeros.
  int rigid_modes = 0;                // zeros (frequency and damping reported as 0)
  int unstable_modes = 0;             // negative ω² beyond the threshold (reported as −|f|)
  double zero_threshold_hz = 0.0;     // the rigid-mode threshold used
  double largest_rigid_hz = 0.0;      // the largest √|ω²|/2π counted rigid: the zeros' noise
  Eigen::VectorXd frequencies_hz;     // n, ascending: damped natural frequency |s|/2π [Hz]
  Eigen::VectorXd damping;            // n: ζ = −Re s/|s| (0 for rigid modes) [-]
  Eigen::VectorXd undamped_hz;        // n: √(ω²)/2π of the undamped normal modes [Hz]
  Eigen::MatrixXd shapes;             // nv x n: undamped normal modes, ΦᵀMΦ = I, in ξ
  int approximate_damping = 0;        // modes whose damping came from Φᵀ C Φ (mixed roots)
};

// Modes of M ẍ + C ẋ + K x = 0 on x = Z y. zero_threshold_hz > 0 replaces the relative
// rule kRigidFrequencyFraction. Throws NumericalError when ZᵀMZ is not positive definite.
SystemModes system_modes(const TangentMatrices& tangent, const Eigen::MatrixXd& Z,
                         double zero_threshold_hz = 0.0);

}  // namespace limber::multibody
