// Consistent initial conditions for the constrained equations of mechanical_system.h:
// positions on g = 0 and h = 0, velocities on G v + g_t = 0, then the accelerations and
// multipliers that satisfy the dynamics and G v̇ = γ. Both integrators start from here
// (IDA is given y, y' from this projection; IDACalcIC is not used).
#pragma once

#include <Eigen/Core>

#include "core/mechanical_system.h"
#include "integrate/status.h"

namespace limber::integrate {

// Moves q onto g(t,q) = 0, h(q) = 0 by Gauss–Newton with minimum-norm corrections
// Δq = −A⁺ [g; h], A = [∂g/∂q; ∂h/∂q], until ‖Δq‖∞ ≤ 1e-12 (1 + ‖q‖∞); then moves v onto
// G v + g_t = 0 with the smallest change in kinetic energy,
// v ← v − M⁻¹Gᵀ (G M⁻¹ Gᵀ)⁻¹ (G v + g_t).
// Meant for small corrections (assembly is the model builder's job). Returns
// kConvergenceFailures when positions do not converge in 25 iterations, kSingularJacobian when
// G M⁻¹ Gᵀ is singular (dependent constraints), kNaN on non-finite model values.
Status project_initial_state(MechanicalSystem& system, double t, Eigen::VectorXd& q,
                             Eigen::VectorXd& v);

// Solves the saddle-point system [M Gᵀ; G 0] [v̇; λ] = [Q; γ] at (t, q, v).
// Returns kSingularJacobian when it is singular (M not positive definite on the null space of
// G, or dependent rows of G), kNaN on non-finite values.
Status solve_accelerations(MechanicalSystem& system, double t, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v, Eigen::VectorXd& vdot,
                           Eigen::VectorXd& lambda);

}  // namespace limber::integrate
