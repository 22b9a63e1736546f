// The linear and angular momentum of a whole model: the quantities a free-floating system
// (no joint to ground, no gravity or other external load) keeps constant, so their drift over a
// run measures the integration's error (docs/results-format.md, /momentum).
#pragma once

#include <Eigen/Core>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

// [P; L]: P = Σ_b ∂T/∂ṙ_b [kg m/s] and L = Σ_b (r_b × ∂T/∂ṙ_b + A_b ∂T/∂ω_b) about the ground
// origin [kg m²/s], ground axes, with ∂T/∂v = M v (ω_b in body axes, so A_b turns its
// momentum into ground axes). These are the momenta conjugate to a rigid translation and
// rotation of everything, conserved when the Lagrangian is invariant under them (Noether);
// exact for flexible bodies (their modal rows are unaffected by a rigid motion of the whole).
// M v body block by body block (mass_times): no nv x nv matrix per call.
Eigen::Matrix<double, 6, 1> system_momentum(const Model& model, const State& state);

}  // namespace limber::multibody
