// Static equilibrium of a mechanism (docs/statics.md): the configuration q and multipliers λ
// (independent rows of a ConstraintPartition) where, at rest,
//   Q(t, q, 0) − Gᵀ(q) λ = 0      applied, spring and elastic forces balance the joints
//   g(t, q)          = 0          the joints and drivers hold
// Q at rest holds the modal elastic forces −ω² η of flexible bodies, springs (RSDA, TSDA, with
// their preloads), actuators, point loads, gravity and hinge limits in their current modes;
// damping and velocity terms vanish. Solved by Newton's method on the configuration manifold
// (increments ξ ∈ R^nv, q ← q ⊕ ξ as in assembly.h) with a backtracking line search on the
// scaled residual (Nocedal & Wright, Numerical Optimization, §3.1 and §11.2). The tangent
// matrix −∂(Q − Gᵀλ)/∂ξ is formed by central differences of the residual (its error O(ε²),
// ε = 1e-6), so every force element, the geometric stiffness of the joints (∂(Gᵀλ)/∂ξ) and
// follower loads are in it without a derivative of their own, the beams of nonlinear bodies
// too (differenced with the rest; their exact tangent, nonlinear_body.h, is not used here).
// With a nonlinear body the loads are stepped on (StaticsOptions::load_increments); large
// deflections do not converge yet (docs/nonlinear-beams.md, "Statics with a nonlinear body").
//
// Free motions. A mechanism may move freely at rest (a floating satellite, an unloaded crank):
// the Newton matrix [K Gᵀ; G 0] is singular along those motions. The matrix is equilibrated
// (Ruiz 2001, "A scaling algorithm to equilibrate both rows and columns norms in matrices") and
// solved by a truncated SVD: motions with singular value ≤ kFreeMotionThreshold σ_max are
// left where they are (the minimum-norm step), which is right when no load acts along them.
// One that the loads do push along is solved along when its singular value is above rounding
// (a soft direction: ≥ 1e-13 σ_max); at rounding (a slider pushed with nothing to push
// against) there is no equilibrium: the solve fails with the motion named, body by body.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"

namespace limber::multibody {

// Singular values of the equilibrated Newton matrix at or below this fraction of the largest
// are free motions: far above the central differences' rounding (≈ 1e-16 / ε² relative to the
// stiffest entry, 1e-4 at ε = 1e-6 before equilibration scales it back to ≈ 1e-12) and far
// below the softest physical stiffness of a mechanism (a hinge spring of 0.2 N·m/rad beside
// panel modes of 4e5 s⁻² gives 1e-6 after equilibration).
inline constexpr double kFreeMotionThreshold = 1e-9;

struct StaticsOptions {
  // ‖Q − Gᵀλ‖∞ ≤ this × the largest force in Q or Gᵀλ, or (nonlinear bodies) ≤ the beams'
  // rounding, a tenth of nonlinear_beam::BeamStructure::force_roundoff
  double force_tolerance = 1e-9;
  double constraint_tolerance = 1e-10; // max |g| [m or rad]
  int max_iterations = 50;              // Newton iterations (per load increment)
  // With a nonlinear body, the loads (every force but its beams': gravity, springs, point
  // loads, ...) are stepped on in this many equal increments (≥ 1) from the start, each solved
  // from the last equilibrium, and a failed increment is halved up to max_bisections times:
  // Newton from the straight beam does not reach a large deflection in one step.
  int load_increments = 10;
  int max_bisections = 6;
};

enum class StaticsStatus { kOk, kNotConverged, kFreeMotionUnderLoad };
const char* to_string(StaticsStatus status);

// A motion the mechanism can make at rest with no stiffness against it (free motions section
// above), and the load along it.
struct FreeMotion {
  std::string description;  // "bus translates along [0 0 1], panel rotates about [1 0 0] ..."
  double load = 0.0;        // generalized force along the (unit) motion [N or N·m mixed]
};

struct StaticsResult {
  StaticsStatus status = StaticsStatus::kOk;
  std::string message;        // on failure: why, in words (names the free motion)
  int iterations = 0;         // Newton iterations (over every load increment)
  State state;                // the equilibrium (v = 0), or the last iterate
  Eigen::VectorXd lambda;     // multipliers of partition.independent at `state`
  double force_residual = 0.0;       // ‖Q − Gᵀλ‖∞ at the end [N, N·m]
  double force_scale = 0.0;          // the largest force it is measured against
  double constraint_residual = 0.0;  // max |g| at the end
  std::vector<FreeMotion> free_motions;  // free motions at the equilibrium (no load on them)
  // Directions of negative stiffness within the joints' freedom (Zᵀ K Z, Z a basis of the
  // motions G allows): > 0 means the equilibrium found is unstable.
  int unstable_directions = 0;
};

// Solves for the equilibrium from `start` (assembled: g ≈ 0 there) at time start.t, with the
// hinge limits in the modes start.engaged. Numerical failures are returned (status, message),
// never thrown. Precondition (DEMAND): load_increments ≥ 1, max_bisections ≥ 0.
StaticsResult solve_statics(const Model& model, const ConstraintPartition& partition,
                            const State& start, const StaticsOptions& options = {});

}  // namespace limber::multibody
