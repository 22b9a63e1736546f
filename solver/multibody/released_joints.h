// Evaluations that leave released joints out (hold-downs after their release time,
// Joint::release_time): their rows carry no multiplier and leave the integrator's equations
// (redundancy.h, rows_released_by), so evaluating them, and the markers only they use, is
// wasted work in every residual. The satellite's 16 hold-downs hold 48 of its 92 rows and 16 of
// the 22 markers on its flexible panels, whose kinematics (mode shapes at the node) are the
// dearest part of an evaluation.
//
// Each function is the one of constraints.h or dynamics.h it names, over the rows and markers
// in force only: the released rows of ws.g, ws.G, ws.g_t and ws.gamma and the released
// markers of ws.markers are not written (they keep whatever they held); every other entry is
// what the full evaluation gives, to the bit (the same arithmetic).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

struct ReleasedJoints {
  std::vector<bool> rows;     // per model equation: released; empty: none
  std::vector<bool> markers;  // per model marker: only released rows use it (no row in force,
                              // driver or force element does)
};

// From the rows flagged in `released_rows` (rows_released_by; empty: none).
ReleasedJoints released_joints(const Model& model, const std::vector<bool>& released_rows);

// update_marker_kinematics, evaluate_constraint_rows and evaluate_constraints (constraints.h)
// without the released markers and rows.
void update_marker_kinematics(const Model& model, const State& state, Stage stage, const ReleasedJoints& released,
                              Workspace& ws);
void evaluate_constraint_rows(const Model& model, const State& state, Stage stage, const ReleasedJoints& released,
                              Workspace& ws);
void evaluate_constraints(const Model& model, const State& state, Stage stage, const ReleasedJoints& released,
                          Workspace& ws);

// mass_matrix_and_forces (dynamics.h) without the released markers.
void mass_matrix_and_forces(const Model& model, const State& state, const ReleasedJoints& released, Workspace& ws);

// The powers generalized_forces (dynamics.h) returns, without the released markers and without
// the bodies' inertial and gravity forces, which the powers do not depend on: the energy
// integrals' pass at every step, where the flexible bodies' quadratic-velocity forces were most
// of the cost. ws.Q is scratch after it. A model with load-dependent geometric stiffening
// (GeometricStiffening::kFull) gets the full pass: its power depends on accelerations
// estimated from all the forces.
PowerTerms power_terms(const Model& model, const State& state, const ReleasedJoints& released, Workspace& ws);

}  // namespace limber::multibody
