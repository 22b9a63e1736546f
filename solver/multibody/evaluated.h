// Readers of an evaluation already made at one state: a sample's one pass (house style §4,
// run/sample_record.h) evaluates M, Q, every marker and every constraint row once, and these
// read them from the workspace instead of evaluating again. Each is the function of
// constraints.h, dynamics.h, momentum.h or reactions.h it names, less its evaluation; they are
// defined beside those (as released_joints.h's are).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/model.h"
#include "multibody/reactions.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"

namespace limber::multibody {

// constraint_violation from ws.g, ws.G and ws.g_t as they are (every row evaluated at state.q).
ConstraintViolation violation_of_rows(const Model& model, const State& state, const Workspace& ws,
                                      const std::vector<bool>& released = {});

// energies from ws.markers as they are (updated at state.q, any stage).
EnergyTerms energies_at_markers(const Model& model, const State& state, const Workspace& ws);

// system_momentum from M = M(state.q) already evaluated (nv x nv).
Eigen::Matrix<double, 6, 1> momentum_of(const Model& model, const State& state, const Eigen::MatrixXd& M);

// compute_reactions from ws.M and ws.Q (mass_matrix_and_forces) and ws.G and ws.markers
// (evaluate_constraint_rows), every row and marker evaluated at `state`. Equal to
// compute_reactions to round-off (M v̇ from the full matrix instead of body blocks).
Reactions reactions_of_evaluation(const Model& model, const State& state, const Eigen::VectorXd& v_dot,
                                  const ConstraintPartition& partition, const Workspace& ws);

}  // namespace limber::multibody
