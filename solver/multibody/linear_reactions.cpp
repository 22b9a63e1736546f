#include "multibody/linear_reactions.h"

#include <algorithm>
#include <iterator>

#include <Eigen/LU>
#include <fmt/format.h>

#include "core/error.h"
#include "multibody/constraints.h"
#include "multibody/reactions.h"

namespace limber::multibody {

namespace {

constexpr double kDifferenceStep = 1e-6;  // ε of the central differences, as linearization.cpp's

// A(q, v) = G_i(q) v̇0 − γ_i(q, v): the acceleration-level constraints at v̇0.
Eigen::VectorXd acceleration_constraints(const Model& model, const State& state, const TangentMatrices& tangent,
                                         Workspace& ws) {
  evaluate_constraints(model, state, Stage::kVelocity, ws);
  return ws.G(tangent.rows, Eigen::all) * tangent.vdot - ws.gamma(tangent.rows);
}

// The joint's reaction force or torque on body j along the output's axes at q, for fixed
// multipliers λ_k of its rows.
Eigen::Vector3d reaction_channels(const Model& model, const State& state, const LinearOutput& output,
                                  const Eigen::VectorXd& lambda_k, Workspace& ws) {
  evaluate_constraints(model, state, Stage::kPosition, ws);
  const Eigen::Matrix<double, 6, 1> wrench = joint_wrench_map(model, ws, output.joint) * lambda_k;
  const Eigen::Vector3d value = output.kind == LinearOutputKind::kReactionForce ? wrench.head<3>() : wrench.tail<3>();
  if (output.axes == ChannelAxes::kGround) return value;
  const Joint& joint = model.joints[static_cast<std::size_t>(output.joint)];
  return ws.markers[static_cast<std::size_t>(joint.marker_j)].R_WF.transpose() * value;
}

}  // namespace

LinearMultipliers linear_multipliers(const Model& model, const State& point, const TangentMatrices& tangent,
                                     const Eigen::MatrixXd& Z, const Eigen::MatrixXd& B_xi) {
  const int nv = model.nv;
  const Eigen::Index n = Z.cols(), nc = tangent.G.rows(), ni = B_xi.cols();
  // A_ξ and A_v by central differences.
  Workspace ws(model);
  Eigen::MatrixXd A_xi(nc, nv), A_v(nc, nv);
  State s = point;
  Eigen::VectorXd xi = Eigen::VectorXd::Zero(nv);
  for (int j = 0; j < nv; ++j) {
    xi(j) = kDifferenceStep;
    s.q = displaced_coordinates(model, point.q, xi);
    const Eigen::VectorXd plus = acceleration_constraints(model, s, tangent, ws);
    xi(j) = -kDifferenceStep;
    s.q = displaced_coordinates(model, point.q, xi);
    A_xi.col(j) = (plus - acceleration_constraints(model, s, tangent, ws)) / (2.0 * kDifferenceStep);
    xi(j) = 0.0;
  }
  s.q = point.q;
  for (int j = 0; j < nv; ++j) {
    s.v = point.v;
    s.v(j) += kDifferenceStep;
    const Eigen::VectorXd plus = acceleration_constraints(model, s, tangent, ws);
    s.v(j) = point.v(j) - kDifferenceStep;
    A_v.col(j) = (plus - acceleration_constraints(model, s, tangent, ws)) / (2.0 * kDifferenceStep);
  }

  // [M G_iᵀ; G_i 0] [δv̇; δλ] = right-hand sides, one column per state and per input.
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(nv + nc, nv + nc);
  kkt.topLeftCorner(nv, nv) = tangent.M;
  kkt.topRightCorner(nv, nc) = tangent.G.transpose();
  kkt.bottomLeftCorner(nc, nv) = tangent.G;
  Eigen::MatrixXd rhs(nv + nc, 2 * n + ni);
  rhs.topLeftCorner(nv, n) = -tangent.K * Z;
  rhs.block(0, n, nv, n) = -tangent.C * Z;
  rhs.topRightCorner(nv, ni) = B_xi;
  rhs.bottomLeftCorner(nc, n) = -A_xi * Z;
  rhs.block(nv, n, nc, n) = -A_v * Z;
  rhs.bottomRightCorner(nc, ni).setZero();
  const Eigen::MatrixXd solved = kkt.partialPivLu().solve(rhs);
  LinearMultipliers out;
  out.of_state = solved.bottomLeftCorner(nc, 2 * n);
  out.of_input = solved.bottomRightCorner(nc, ni);
  return out;
}

void reaction_rows(const Model& model, const State& point, const TangentMatrices& tangent, const Eigen::MatrixXd& Z,
                   const LinearMultipliers& multipliers, const LinearOutput& output, Eigen::MatrixXd& C_rows,
                   Eigen::MatrixXd& D_rows) {
  LIMBER_DEMAND(output.joint >= 0 && output.joint < static_cast<int>(model.joints.size()));
  const Joint& joint = model.joints[static_cast<std::size_t>(output.joint)];
  // The joint's rows among the independent ones: all of them, or its reaction is not determined.
  std::vector<Eigen::Index> positions;
  for (int row = joint.first_row; row < joint.first_row + joint.rows; ++row) {
    const auto found = std::find(tangent.rows.begin(), tangent.rows.end(), row);
    if (found == tangent.rows.end()) {
      throw InputError(fmt::format(
          "linearize output '{}': expected a joint whose equations all hold independently at the "
          "linearization point, got '{}' with equation '{}' redundant or released there (its "
          "reaction is not determined by the linearization)",
          output.name, joint.name, model.equations[static_cast<std::size_t>(row)].name));
    }
    positions.push_back(std::distance(tangent.rows.begin(), found));
  }
  const Eigen::VectorXd lambda_k = tangent.lambda(positions);
  const Eigen::Index n = Z.cols();

  // The conversion at the point, applied to δλ_k.
  Workspace ws(model);
  const auto channels_of = [&](const Eigen::VectorXd& dlambda_k) {
    return reaction_channels(model, point, output, dlambda_k, ws);
  };
  C_rows = Eigen::MatrixXd::Zero(3, 2 * n);
  D_rows = Eigen::MatrixXd::Zero(3, multipliers.of_input.cols());
  for (Eigen::Index c = 0; c < 2 * n; ++c) C_rows.col(c) = channels_of(multipliers.of_state(positions, c));
  for (Eigen::Index c = 0; c < D_rows.cols(); ++c) D_rows.col(c) = channels_of(multipliers.of_input(positions, c));

  // The conversion's own change with the configuration, at λ0, along each free motion.
  State s = point;
  for (Eigen::Index c = 0; c < n; ++c) {
    const Eigen::VectorXd xi = kDifferenceStep * Z.col(c);
    s.q = displaced_coordinates(model, point.q, xi);
    const Eigen::Vector3d plus = reaction_channels(model, s, output, lambda_k, ws);
    s.q = displaced_coordinates(model, point.q, -xi);
    C_rows.col(c) += (plus - reaction_channels(model, s, output, lambda_k, ws)) / (2.0 * kDifferenceStep);
  }
}

}  // namespace limber::multibody
