// The state of a body between output samples: linear interpolation of position, modal
// coordinates and node displacements, spherical linear interpolation (slerp) of the orientation.
#pragma once

#include "results_reader.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace limber::render {

struct BodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();          // frame origin in ground [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // ground <- body
  Eigen::VectorXd modal_coordinates;                           // nm (flexible bodies)
  Eigen::VectorXd node_displacements;  // 3 nn, body frame [m] (bodies that store them), else empty
};

// Where t falls among the sample times: samples i and i+1 with weight w of i+1 in [0, 1].
// Clamps t to [time(0), time(ns-1)]. Precondition: ns >= 1, times non-decreasing.
struct SampleBracket {
  Eigen::Index i = 0;
  double w = 0.0;
  double t = 0.0;  // the time bracketed [s] (clamped to the samples' span)
};
SampleBracket bracket(const Eigen::VectorXd& time, double t);

BodyState body_state(const BodyTrack& body, const SampleBracket& at);
Eigen::Vector3d joint_position(const JointTrack& joint, const SampleBracket& at);

// Nodal elastic displacements u = sum_i eta_i phi_i in the body frame, nn x 3 [m].
RowMatrix3d elastic_displacements(const FlexibleMesh& mesh, const Eigen::VectorXd& eta);

// A body state's nodal displacements in the body frame, nn x 3 [m]: its node displacements
// when it has them (a nonlinear body), else its modes' sum.
RowMatrix3d elastic_displacements(const FlexibleMesh& mesh, const BodyState& state);

}  // namespace limber::render
