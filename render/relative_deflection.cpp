#include "relative_deflection.h"

#include "body_pose.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>

namespace limber::render {

RigidFitBasis rigid_fit_basis(const RowMatrix3d& nodes, const std::vector<Eigen::Index>& anchors) {
  RigidFitBasis basis;
  basis.anchors = anchors;
  if (anchors.empty()) return basis;
  for (Eigen::Index a : anchors) basis.center += nodes.row(a).transpose();
  basis.center /= static_cast<double>(anchors.size());
  // u_a = t + θ × d_a = t − [d_a]× θ, d_a = X_a − X̄: about the centroid the translation and
  // rotation columns are orthogonal, so the minimum-norm solution zeroes only what the anchors
  // cannot see (the spin about the line through two anchors).
  const auto m = static_cast<Eigen::Index>(anchors.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * m, 6);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Eigen::Vector3d d = nodes.row(anchors[static_cast<std::size_t>(k)]).transpose() - basis.center;
    A.block<3, 3>(3 * k, 0).setIdentity();
    A.block<3, 3>(3 * k, 3) << 0.0, d.z(), -d.y(), -d.z(), 0.0, d.x(), d.y(), -d.x(), 0.0;
  }
  basis.solve = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(A).pseudoInverse();
  return basis;
}

RowMatrix3d relative_displacements(const RigidFitBasis& basis, const RowMatrix3d& nodes,
                                   const RowMatrix3d& u) {
  if (basis.anchors.empty()) return u;
  Eigen::VectorXd u_anchors(3 * static_cast<Eigen::Index>(basis.anchors.size()));
  for (std::size_t k = 0; k < basis.anchors.size(); ++k) {
    u_anchors.segment<3>(3 * static_cast<Eigen::Index>(k)) = u.row(basis.anchors[k]).transpose();
  }
  const Eigen::Matrix<double, 6, 1> fit = basis.solve * u_anchors;
  const Eigen::Vector3d t = fit.head<3>(), theta = fit.tail<3>();
  RowMatrix3d relative(u.rows(), 3);
  for (Eigen::Index n = 0; n < u.rows(); ++n) {
    const Eigen::Vector3d d = nodes.row(n).transpose() - basis.center;
    relative.row(n) = u.row(n) - (t + theta.cross(d)).transpose();
  }
  return relative;
}

std::vector<Eigen::Index> joint_nodes(const Results& results, const BodyTrack& body,
                                      std::vector<std::string>* joint_names, double held_after) {
  std::vector<Eigen::Index> nodes;
  if (!body.flexible || body.mesh.nodes.rows() == 0 || results.sample_count() == 0) return nodes;
  // Nodes in ground at the first sample.
  const SampleBracket first{0, 0.0};
  const BodyState state = body_state(body, first);
  const RowMatrix3d x_W =
      ((body.mesh.nodes + elastic_displacements(body.mesh, state)) *
       state.orientation.toRotationMatrix().transpose())
          .rowwise() +
      state.position.transpose();
  for (const JointTrack& joint : results.joints) {
    if (joint.body_i != body.name && joint.body_j != body.name) continue;
    if (joint.position.rows() == 0 || !(joint.release_time > held_after)) continue;
    Eigen::Index nearest = 0;
    (x_W.rowwise() - joint.position.row(0)).rowwise().squaredNorm().minCoeff(&nearest);
    if (std::find(nodes.begin(), nodes.end(), nearest) == nodes.end()) {
      nodes.push_back(nearest);
      if (joint_names != nullptr) joint_names->push_back(joint.name);
    }
  }
  return nodes;
}

const TimedRigidFit::Span& TimedRigidFit::at(double t) const {
  // The last span that starts before t.
  const auto later = std::find_if(spans.begin() + 1, spans.end(), [t](const Span& s) { return !(s.after < t); });
  return *(later - 1);
}

bool TimedRigidFit::any_anchor() const {
  return std::any_of(spans.begin(), spans.end(), [](const Span& s) { return !s.basis.anchors.empty(); });
}

TimedRigidFit timed_rigid_fit(const Results& results, const BodyTrack& body) {
  TimedRigidFit fit;
  if (!body.flexible) return fit;
  // A new span after each release time of the body's joints.
  std::vector<double> starts{-std::numeric_limits<double>::infinity()};
  for (const JointTrack& joint : results.joints) {
    const bool on_body = joint.body_i == body.name || joint.body_j == body.name;
    if (on_body && std::isfinite(joint.release_time)) starts.push_back(joint.release_time);
  }
  std::sort(starts.begin(), starts.end());
  starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  for (double after : starts) {
    TimedRigidFit::Span& span = fit.spans.emplace_back();
    span.after = after;
    span.basis = rigid_fit_basis(body.mesh.nodes, joint_nodes(results, body, &span.joints, after));
  }
  return fit;
}

}  // namespace limber::render
