#include "body_pose.h"

#include "core/error.h"

#include <algorithm>

namespace limber::render {

SampleBracket bracket(const Eigen::VectorXd& time, double t) {
  LIMBER_DEMAND(time.size() >= 1);
  const Eigen::Index ns = time.size();
  if (ns == 1 || t <= time(0)) return {0, 0.0, time(0)};
  if (t >= time(ns - 1)) return {ns - 1, 0.0, time(ns - 1)};
  // First sample strictly after t, then the interval before it.
  const double* begin = time.data();
  const Eigen::Index after = std::upper_bound(begin, begin + ns, t) - begin;
  const Eigen::Index i = after - 1;
  const double span = time(i + 1) - time(i);
  return {i, span > 0.0 ? (t - time(i)) / span : 0.0, t};
}

namespace {

Eigen::Quaterniond quaternion_row(const BodyTrack& body, Eigen::Index i) {
  return Eigen::Quaterniond(body.orientation(i, 0), body.orientation(i, 1), body.orientation(i, 2),
                            body.orientation(i, 3))
      .normalized();
}

}  // namespace

BodyState body_state(const BodyTrack& body, const SampleBracket& at) {
  BodyState state;
  const Eigen::Index j = std::min<Eigen::Index>(at.i + 1, body.position.rows() - 1);
  // Linear in position, modal coordinates and node displacements, slerp in orientation.
  state.position = (1.0 - at.w) * body.position.row(at.i).transpose() +
                   at.w * body.position.row(j).transpose();
  state.orientation = quaternion_row(body, at.i).slerp(at.w, quaternion_row(body, j));
  if (body.flexible && body.modal_coordinates.cols() > 0) {
    state.modal_coordinates = (1.0 - at.w) * body.modal_coordinates.row(at.i).transpose() +
                              at.w * body.modal_coordinates.row(j).transpose();
  }
  if (body.flexible && body.node_displacements.cols() > 0) {
    state.node_displacements = (1.0 - at.w) * body.node_displacements.row(at.i).transpose() +
                               at.w * body.node_displacements.row(j).transpose();
  }
  return state;
}

Eigen::Vector3d joint_position(const JointTrack& joint, const SampleBracket& at) {
  const Eigen::Index j = std::min<Eigen::Index>(at.i + 1, joint.position.rows() - 1);
  return (1.0 - at.w) * joint.position.row(at.i).transpose() +
         at.w * joint.position.row(j).transpose();
}

RowMatrix3d elastic_displacements(const FlexibleMesh& mesh, const Eigen::VectorXd& eta) {
  const Eigen::Index nn = mesh.nodes.rows();
  if (eta.size() == 0 || mesh.mode_translations.cols() == 0) return RowMatrix3d::Zero(nn, 3);
  LIMBER_DEMAND(eta.size() == mesh.mode_translations.cols());
  // (3 nn) vector node-major xyz, viewed as nn x 3 row-major.
  const Eigen::VectorXd u = mesh.mode_translations * eta;
  return Eigen::Map<const RowMatrix3d>(u.data(), nn, 3);
}

RowMatrix3d elastic_displacements(const FlexibleMesh& mesh, const BodyState& state) {
  if (state.node_displacements.size() == 0) return elastic_displacements(mesh, state.modal_coordinates);
  const Eigen::Index nn = mesh.nodes.rows();
  LIMBER_DEMAND(state.node_displacements.size() == 3 * nn);
  return Eigen::Map<const RowMatrix3d>(state.node_displacements.data(), nn, 3);
}

}  // namespace limber::render
