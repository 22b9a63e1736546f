#include "run/deformation_redundancy.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <Eigen/Cholesky>

#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/flexible_body.h"

namespace limber::run {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The FE DOF a row constrains at its marker on `body`: a rotation about a × b (dot1), about
// z_i (angle) or a translation along a (dot2), in body axes, named when one axis carries
// at least 90 % of it; "" otherwise.
std::string constrained_dof(const multibody::Model& model, const multibody::ConstraintEquation& eq,
                            const multibody::Workspace& ws, int marker) {
  const multibody::FrameKinematics& mi = ws.markers[static_cast<std::size_t>(eq.marker_i)];
  const multibody::FrameKinematics& mj = ws.markers[static_cast<std::size_t>(eq.marker_j)];
  const Eigen::Vector3d a = mi.R_WF.col(eq.axis_i);
  Eigen::Vector3d direction_W = Eigen::Vector3d::Zero();
  bool rotation = true;
  switch (eq.kind) {
    case multibody::EquationKind::kDot1: direction_W = a.cross(mj.R_WF.col(eq.axis_j)); break;
    case multibody::EquationKind::kAngle: direction_W = mi.R_WF.col(2); break;
    case multibody::EquationKind::kDot2: direction_W = a; rotation = false; break;
  }
  if (direction_W.norm() == 0.0) return "";
  // Body axes: the marker's rotation without its fixed offset (the small elastic rotation of
  // the node is immaterial to naming an axis).
  const multibody::Marker& m = model.markers[static_cast<std::size_t>(marker)];
  const Eigen::Matrix3d R_WB = ws.markers[static_cast<std::size_t>(marker)].R_WF * m.R_BM.transpose();
  const Eigen::Vector3d d = (R_WB.transpose() * direction_W).normalized();
  Eigen::Index axis = 0;
  if (d.cwiseAbs().maxCoeff(&axis) < 0.9) return "";
  return fmt::format("{}{}", rotation ? 'r' : 'u', "xyz"[axis]);
}

// Each mode of the flexible body `body` as a probe: does a redundant row add a direction?
void probe_body(const multibody::Model& model, const multibody::State& state, int body,
                const std::vector<int>& order, const std::vector<bool>& at_start,
                const multibody::ConstraintPartition& partition, multibody::Workspace& ws,
                std::vector<DeformationRedundancy>& found) {
  const multibody::Body& b = model.bodies[static_cast<std::size_t>(body)];
  const multibody::FlexibleBody& flexible = *b.flexible;
  for (int k = 0; k < flexible.mode_count(); ++k) {
    double largest = 0.0;
    for (int node = 0; node < flexible.node_count(); ++node) {
      largest = std::max(largest, flexible.translation_shapes(node).col(k).norm());
    }
    if (largest == 0.0) continue;
    // The probe, halved while the mass matrix there is not positive definite: the floating
    // frame's mass matrix of a slender body loses definiteness at deflections far beyond its
    // section (a 1 km rod of 1 x 2 cm deflected by 1 m; issue 31); none left, no probe.
    multibody::State probe = state;
    double deflection = 2.0 * kDeformationProbe;
    bool definite = false;
    for (int halving = 0; halving <= kMaxProbeHalvings && !definite; ++halving) {
      deflection *= 0.5;
      probe.q(b.q_offset + 7 + k) = state.q(b.q_offset + 7 + k) + deflection * flexible.size / largest;
      multibody::mass_matrix(model, probe, ws);
      definite = Eigen::LLT<Eigen::MatrixXd>(ws.M).info() == Eigen::Success;
    }
    if (!definite) continue;
    const Eigen::MatrixXd S = multibody::mass_metric_rows(model, probe, ws);
    const std::vector<bool> near = multibody::rows_adding_directions(S, order);
    for (const multibody::RedundantEquation& r : partition.redundant) {
      const auto row = static_cast<std::size_t>(r.row);
      if (!near[row] || at_start[row]) continue;
      const bool known = std::any_of(found.begin(), found.end(),
                                     [&](const DeformationRedundancy& d) { return d.row == r.row; });
      if (known) continue;
      DeformationRedundancy d;
      d.row = r.row;
      d.group = r.depends_on;
      d.group.push_back(r.row);
      d.body = body;
      d.mode = k;
      d.deflection = deflection;
      // The direction it gains: its part orthogonal to all rows before it.
      Eigen::MatrixXd before(S.cols(), 0);
      for (int other : order) {
        if (other == r.row) break;
        before.conservativeResize(Eigen::NoChange, before.cols() + 1);
        before.col(before.cols() - 1) = S.row(other).transpose();
      }
      const Eigen::VectorXd s = S.row(r.row).transpose();
      d.pivot = before.cols() == 0 ? s.norm()
                                   : (s - before * before.colPivHouseholderQr().solve(s)).norm();
      found.push_back(d);
    }
  }
}

}  // namespace

std::string DeformationRedundancy::description(const multibody::Model& model) const {
  const multibody::Body& b = model.bodies[static_cast<std::size_t>(body)];
  const double hz = std::sqrt(std::max(0.0, b.flexible->stiffness(mode))) / (2.0 * kPi);
  return fmt::format(
      "{} holds only while '{}' is undeformed: its mode {} ({:.4g} Hz), deflected by {:g} of the "
      "body's size, makes {} independent (pivot {:.2g} against the threshold {:g})",
      model.equations[static_cast<std::size_t>(row)].name, b.name, mode + 1, hz, deflection,
      model.equations[static_cast<std::size_t>(row)].name, pivot, multibody::kRedundancyThreshold);
}

std::string DeformationRedundancy::remedy(const multibody::Model& model) const {
  const std::string& name = model.bodies[static_cast<std::size_t>(body)].name;
  if (node_id == 0 || dof.empty()) {
    return fmt::format("give '{}' the deformation the equation needs (more normal modes, or "
                       "static modes at its joint nodes), or free that motion in the joint",
                       name);
  }
  return fmt::format("give '{}' that freedom: `attachment: [{{nodes: [{}], dofs: [{}]}}]` in its "
                     "modes (or more normal modes, until one gives {} at node {}), or free that "
                     "motion in the joint",
                     name, node_id, dof, dof, node_id);
}

std::vector<DeformationRedundancy> deformation_redundancies(
    const multibody::Model& model, const multibody::State& state,
    const multibody::ConstraintPartition& partition, multibody::Workspace& ws) {
  std::vector<DeformationRedundancy> found;
  if (partition.redundant.empty()) return found;
  // The start's order: independent rows first, then the redundant ones.
  std::vector<int> order = partition.independent;
  for (const multibody::RedundantEquation& r : partition.redundant) order.push_back(r.row);
  const std::vector<bool> at_start =
      multibody::rows_adding_directions(multibody::mass_metric_rows(model, state, ws), order);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (model.bodies[b].kind != multibody::BodyKind::kFlexible) continue;
    probe_body(model, state, static_cast<int>(b), order, at_start, partition, ws, found);
  }
  // Where each acts on its body: the marker there, its node and the DOF the row holds.
  multibody::update_marker_kinematics(model, state, multibody::Stage::kPosition, ws);
  for (DeformationRedundancy& d : found) {
    const multibody::ConstraintEquation& eq = model.equations[static_cast<std::size_t>(d.row)];
    for (const int marker : {eq.marker_i, eq.marker_j}) {
      const multibody::Marker& m = model.markers[static_cast<std::size_t>(marker)];
      if (m.body != d.body || m.node < 0) continue;
      const std::vector<int>& ids = model.bodies[static_cast<std::size_t>(d.body)].flexible->mesh.node_ids;
      d.node_id = ids.empty() ? m.node + 1 : ids[static_cast<std::size_t>(m.node)];
      d.dof = constrained_dof(model, eq, ws, marker);
      break;
    }
  }
  return found;
}

}  // namespace limber::run
