// Whether a factorised matrix counts as singular, judged on its equilibrated form.
//
// The matrices the integrators factorise ([M Gᵀ; G 0], G M⁻¹ Gᵀ, generalized-α's iteration
// matrix) hold rows in mixed units (m and rad, N and N m) over bodies whose masses and inertias
// may differ by many orders of magnitude: their unscaled reciprocal condition number measures
// that spread, not singularity (a 3 µg beam beside a 10 kg link read as "dependent constraints",
// found by the mechanism fuzz: docs/fuzzing.md). A matrix whose LU's estimate falls below the
// threshold is judged again after scaling its rows, then its columns, to unit largest entries
// (the equilibration of LAPACK's xGEEQU); only then does it count as singular. The factorisation
// used for solving is the caller's, unchanged.
#pragma once

#include <Eigen/Dense>

namespace limber::integrate {

// Reciprocal condition number below which a factorisation counts as singular.
inline constexpr double kSingularRcond = 1e-14;

// True when `a` (factorised as `lu`) is singular to working precision after equilibration.
bool is_singular(const Eigen::MatrixXd& a, const Eigen::PartialPivLU<Eigen::MatrixXd>& lu);

}  // namespace limber::integrate
