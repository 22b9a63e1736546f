// Elastic displacement relative to a rigid fit through a flexible body's joint nodes, for
// pictures that scale deformation: u_rel = u − (t + θ × (X − X̄)), with the translation t and
// small rotation θ that best carry the joint nodes (least squares, minimum norm; X̄ their
// centroid). Drawing X + (t + θ × (X − X̄)) + scale · u_rel keeps every joint node where the
// joint holds it (to the fit's residual, zero for one or two joint nodes up to their stretch)
// at any scale, and |u_rel| is the deflection a reviewer reads: a node on a hinge shows none.
// The floating frame of reference leaves u free to carry a rigid part (e.g. a free-free
// panel's hinge node moves millimetres in its frame), which a plain scale would magnify.
// u is linear in the modal coordinates, so the linearised rigid motion is exact for it.
#pragma once

#include "results_reader.h"

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace limber::render {

// The fit's operator for one body and its joint nodes.
struct RigidFitBasis {
  std::vector<Eigen::Index> anchors;        // node indices the fit goes through
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // their centroid, body frame [m]
  Eigen::Matrix<double, 6, Eigen::Dynamic> solve;    // (t, θ) = solve · u at the anchors (3 per node)
};

// Precomputes the fit through `anchors` (node indices into `nodes`, body frame [m]). No
// anchors: an empty basis, and relative_displacements returns u unchanged.
RigidFitBasis rigid_fit_basis(const RowMatrix3d& nodes, const std::vector<Eigen::Index>& anchors);

// u − (t + θ × (X − X̄)) for every node, nn x 3 [m], with (t, θ) fitted to u at the anchors.
RowMatrix3d relative_displacements(const RigidFitBasis& basis, const RowMatrix3d& nodes,
                                   const RowMatrix3d& u);

// The joint nodes of a flexible body: for each joint with the body as body_i or body_j and
// released after `held_after` [s] (JointTrack::release_time; the default takes every joint),
// the node nearest the joint point at the first sample (deformed, scale 1), once each; with
// their joints' names. Empty for a body without joints.
std::vector<Eigen::Index> joint_nodes(const Results& results, const BodyTrack& body,
                                      std::vector<std::string>* joint_names = nullptr,
                                      double held_after = -std::numeric_limits<double>::infinity());

// A flexible body's rigid fits over a run (issue 28): through the joints that hold it at time t.
// A released joint (a hold-down) is no support after its release, so the fit changes after each
// release time of the body's joints; a joint is held up to and at its release time (held_at).
struct TimedRigidFit {
  struct Span {
    double after = -std::numeric_limits<double>::infinity();  // the span holds for t > after [s]
    RigidFitBasis basis;
    std::vector<std::string> joints;  // the joints the fit goes through
  };
  std::vector<Span> spans;  // ascending `after`, the first at -inf; empty for a rigid body
  // The span of time t [s]. Precondition: spans not empty.
  const Span& at(double t) const;
  // Whether the fit goes through some joint at some time.
  bool any_anchor() const;
};

TimedRigidFit timed_rigid_fit(const Results& results, const BodyTrack& body);

}  // namespace limber::render
