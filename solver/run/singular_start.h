// A start exactly at a singular configuration (issue 14): a parallelogram assembled with its
// cranks along the ground line, a slider-crank at a dead centre of a locked loop. There the
// constraint Jacobian G loses rank, so the redundancy analysis of the start counts an equation
// redundant that is independent everywhere next to it. The integrators enforce only the rows
// chosen at the start, so that equation would never be held and the joints would come apart
// (measured: 19 % of the parallelogram's size by t = 0.7 s, flagged only by the drift check).
//
// The test, on the rigid skeleton (the frame columns of G with unit rows; modal columns left
// out): the rows that add a direction, taken in the start's order, at the start and a small
// feasible step away, along fixed combinations of the skeleton's null space (directions the
// constraints allow to first order). A step of size ε leaves the manifold by O(ε²), far below
// the redundancy threshold (redundancy.h) for ε = 1e-4, while an equation lost to the
// singularity regains a direction O(ε), far above it.
#pragma once

#include <vector>

#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"

namespace limber::run {

// Step length along the unit null-space direction (frame coordinates, m and rad).
inline constexpr double kSingularStartProbe = 1e-4;

// Rows of model.equations counted redundant in `partition` (the analysis of the assembled
// start `state`) that are independent a step kSingularStartProbe away; empty when the start
// is not singular. Deterministic (fixed directions). Updates ws.
std::vector<int> rows_lost_at_singular_start(const multibody::Model& model,
                                             const multibody::State& state,
                                             const multibody::ConstraintPartition& partition,
                                             multibody::Workspace& ws);

}  // namespace limber::run
