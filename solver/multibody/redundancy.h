// Redundant constraint equations: found by rank-revealing QR with column pivoting (Golub &
// Van Loan, Matrix Computations, §5.4.2) at an assembled configuration. The rank is that of
// the full constraint Jacobian G (m x nv) in the mass metric, the rows of G L⁻ᵀ (M = L Lᵀ)
// whose products are G M⁻¹ Gᵀ, the matrix the integrators factorise; the independent rows
// are the first `rank` pivots of G itself. Rows are scaled to unit norm first, so the test
// is independent of units (metres vs radians) and of the mechanism's size; a pivot
// |R_kk| ≤ relative_threshold · |R_11| counts as zero. The mass metric weighs a coordinate
// by how easily it moves: a joint equation that only a mode's spurious content makes
// independent (a bending mode with 1e-6 of rotation about the beam axis, whose own inertia
// is small) stays redundant, as it is physically. The pivoted rows are the
// independent equations; every other row is redundant, and it depends on the independent
// rows with non-zero coefficients in its least-squares expansion over them.
#pragma once

#include <string>
#include <vector>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

// Default relative pivot threshold: far below the pivots of a well-posed mechanism away from
// singular positions (≥ 0.05 for the seed slider-crank, rigid or flexible), far above
// rounding (1e-16 · √m) and above the spurious coupling a computed mode set carries: the
// seed rod meshed with 20 beams has up to 6e-6 of rotation about its axis in its bending
// modes, a pivot of 2e-8 in the mass metric. Counted independent, such a row carries
// multipliers amplified by the inverse pivot and makes G M⁻¹ Gᵀ numerically singular (its
// eigenvalues go with the pivot squared).
constexpr double kRedundancyThreshold = 1e-6;

struct RedundantEquation {
  int row = 0;                  // equation index in model.equations
  std::vector<int> depends_on;  // independent rows it is a combination of
};

struct ConstraintPartition {
  std::vector<int> independent;              // ascending row indices
  std::vector<RedundantEquation> redundant;  // ascending row indices
  std::vector<bool> row_indeterminate;       // per row: in a dependency group
  std::vector<bool> joint_indeterminate;     // per joint: one of its rows is
  // Per row: its joint has been released (Joint::release_time): the row is in neither set and
  // carries no multiplier. Empty when no joint is released.
  std::vector<bool> row_released;
  double relative_threshold = kRedundancyThreshold;

  bool released(int row) const {
    return !row_released.empty() && row_released[static_cast<std::size_t>(row)];
  }

  // One line per redundant equation, e.g. "R3.y is redundant with R1.y, R2.y, T.y".
  std::vector<std::string> describe(const Model& model) const;
};

// The rows of A scaled to unit norm (zero rows stay zero: they are redundant with nothing).
Eigen::MatrixXd unit_rows(Eigen::MatrixXd A);

// The rows of G in the mass metric, G L⁻ᵀ (M = L Lᵀ), scaled to unit norm: the matrix whose
// rank analyse_redundancy measures. Evaluates G and M at `state` (updates ws).
Eigen::MatrixXd mass_metric_rows(const Model& model, const State& state, Workspace& ws);

// Per row of S: whether it adds a direction to the rows taken before it in `order` (its part
// orthogonal to them exceeds `tolerance`; rows of S have unit norm or are zero).
std::vector<bool> rows_adding_directions(const Eigen::MatrixXd& S, const std::vector<int>& order,
                                         double tolerance = kRedundancyThreshold);

// All rows independent (no analysis).
ConstraintPartition full_partition(const Model& model);

// Per row of the model: its joint's release time is at or before t (empty when none is).
std::vector<bool> rows_released_by(const Model& model, double t);

// Analyses G at `state` (evaluated there; updates ws). Rows in `keep` are pivoted first, so
// they stay independent where the rank allows (MultibodySystem::reselect_constraints); rows
// flagged in `released` (rows_released_by) are left out of both sets.
// Precondition: the state is assembled (redundancy is a property of the configuration).
ConstraintPartition analyse_redundancy(const Model& model, const State& state, Workspace& ws,
                                       double relative_threshold = kRedundancyThreshold,
                                       const std::vector<int>& keep = {},
                                       const std::vector<bool>& released = {});

}  // namespace limber::multibody
