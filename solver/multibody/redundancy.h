// Redundant constraint equations: found by a rank-revealing QR with column pivoting
// (Golub & Van Loan, Matrix Computations, §5.4.2) of the full constraint Jacobian G
// (m x nv) at an assembled configuration. Each row of G is first scaled to unit norm, so
// the test is independent of units (metres vs radians) and of the mechanism's size; a
// pivot |R_kk| ≤ relative_threshold · |R_11| counts as zero. The pivoted rows are the
// independent equations; every other row is redundant, and it depends on the independent
// rows with non-zero coefficients in its least-squares expansion over them.
#pragma once

#include <string>
#include <vector>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

// Default relative pivot threshold: far above rounding (1e-16 · √m) and far below the
// pivots of a well-posed mechanism away from singular positions.
constexpr double kRedundancyThreshold = 1e-8;

struct RedundantEquation {
  int row = 0;                  // equation index in model.equations
  std::vector<int> depends_on;  // independent rows it is a combination of
};

struct ConstraintPartition {
  std::vector<int> independent;              // ascending row indices
  std::vector<RedundantEquation> redundant;  // ascending row indices
  std::vector<bool> row_indeterminate;       // per row: in a dependency group
  std::vector<bool> joint_indeterminate;     // per joint: one of its rows is
  double relative_threshold = kRedundancyThreshold;

  // One line per redundant equation, e.g. "R3.y is redundant with R1.y, R2.y, T.y".
  std::vector<std::string> describe(const Model& model) const;
};

// All rows independent (no analysis).
ConstraintPartition full_partition(const Model& model);

// Analyses G at `state` (evaluated there; updates ws). Precondition: the state is
// assembled (redundancy is a property of the configuration).
ConstraintPartition analyse_redundancy(const Model& model, const State& state, Workspace& ws,
                                       double relative_threshold = kRedundancyThreshold);

}  // namespace limber::multibody
