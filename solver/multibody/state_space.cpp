#include "multibody/state_space.h"

#include <algorithm>
#include <iterator>
#include <optional>

#include <Eigen/SVD>
#include <fmt/format.h>

#include "core/error.h"
#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/linear_reactions.h"
#include "multibody/redundancy.h"

namespace limber::multibody {

namespace {

constexpr const char* kAxisSuffix[] = {".x", ".y", ".z"};

// The unit vectors (columns, ground axes) the three channels of a marker point along.
Eigen::Matrix3d channel_axes(const FrameKinematics& marker, ChannelAxes axes) {
  return axes == ChannelAxes::kMarker ? marker.R_WF : Eigen::Matrix3d::Identity();
}

// The position among tangent.rows of the equation of each driver whose effort is an input
// (released), without repeats. InputError when one is not there (redundant at the point).
std::vector<Eigen::Index> released_positions(const Model& model, const TangentMatrices& tangent,
                                             const std::vector<LinearInput>& inputs) {
  std::vector<Eigen::Index> positions;
  for (const LinearInput& input : inputs) {
    if (input.kind != LinearInputKind::kDriverEffort) continue;
    LIMBER_DEMAND(input.driver >= 0 && input.driver < static_cast<int>(model.drivers.size()));
    const Driver& driver = model.drivers[static_cast<std::size_t>(input.driver)];
    const auto found = std::find(tangent.rows.begin(), tangent.rows.end(), driver.row);
    if (found == tangent.rows.end()) {
      throw InputError(fmt::format(
          "linearize input '{}': expected a driver whose equation holds independently at the "
          "linearization point, got '{}' redundant there (other equations hold its coordinate, so "
          "it has no effort of its own to take as an input)",
          input.name, driver.name));
    }
    const Eigen::Index position = std::distance(tangent.rows.begin(), found);
    if (std::find(positions.begin(), positions.end(), position) == positions.end()) positions.push_back(position);
  }
  return positions;
}

// The rank of the rows of G flagged in `rows`, scaled to unit norm (redundancy.h's threshold).
Eigen::Index rank_of_rows(const Eigen::MatrixXd& G, const std::vector<bool>& rows) {
  Eigen::MatrixXd kept = Eigen::MatrixXd::Zero(G.rows(), G.cols());
  for (Eigen::Index r = 0; r < G.rows(); ++r) {
    if (rows[static_cast<std::size_t>(r)]) kept.row(r) = G.row(r);
  }
  Eigen::BDCSVD<Eigen::MatrixXd> svd(unit_rows(kept));
  svd.setThreshold(kRedundancyThreshold);
  return svd.rank();
}

// A driver's effort is an input only where the driver alone holds its coordinate: the rank of
// the equations active at the point (all but released joints') must fall when its row leaves
// them. Otherwise (its row redundant, or a second driver or joint holding the same coordinate)
// the released model would still hold it: InputError naming the driver.
void check_released_drivers(const Model& model, const State& point, const std::vector<LinearInput>& inputs,
                            Workspace& ws) {
  std::vector<bool> active = rows_released_by(model, point.t);
  if (active.empty()) active.assign(static_cast<std::size_t>(model.num_equations()), false);
  active.flip();
  evaluate_constraints(model, point, Stage::kPosition, ws);
  const Eigen::Index rank = rank_of_rows(ws.G, active);
  for (const LinearInput& input : inputs) {
    if (input.kind != LinearInputKind::kDriverEffort) continue;
    LIMBER_DEMAND(input.driver >= 0 && input.driver < static_cast<int>(model.drivers.size()));
    const Driver& driver = model.drivers[static_cast<std::size_t>(input.driver)];
    std::vector<bool> without = active;
    without[static_cast<std::size_t>(driver.row)] = false;
    if (rank_of_rows(ws.G, without) < rank) continue;
    throw InputError(fmt::format(
        "linearize input '{}': expected a driver that alone holds its coordinate at the linearization "
        "point, got '{}', whose coordinate other equations hold too (its equation is redundant there, "
        "so it has no effort of its own to take as an input)",
        input.name, driver.name));
  }
}

// The tangent matrices with the rows at `positions` released: G, rows and λ0 without them. K and
// C keep their G_dᵀλ0 terms (the effort at the point stays applied).
TangentMatrices without_rows(const TangentMatrices& tangent, const std::vector<Eigen::Index>& positions) {
  TangentMatrices kept = tangent;
  std::vector<Eigen::Index> keep;
  kept.rows.clear();
  for (Eigen::Index k = 0; k < tangent.G.rows(); ++k) {
    if (std::find(positions.begin(), positions.end(), k) != positions.end()) continue;
    keep.push_back(k);
    kept.rows.push_back(tangent.rows[static_cast<std::size_t>(k)]);
  }
  kept.G = tangent.G(keep, Eigen::all);
  kept.lambda = tangent.lambda(keep);
  return kept;
}

// B_ξ (nv x ni): the generalized forces of unit inputs, and the channel names.
Eigen::MatrixXd input_forces(const Model& model, const Workspace& ws, const TangentMatrices& tangent,
                             const std::vector<LinearInput>& inputs, std::vector<std::string>& names) {
  std::vector<Eigen::VectorXd> columns;
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  for (const LinearInput& input : inputs) {
    if (input.kind == LinearInputKind::kDriverEffort) {
      // The driver row's generalized force per unit effort, G_dᵀ (effort = −λ_driver).
      const int row = model.drivers[static_cast<std::size_t>(input.driver)].row;
      const auto position = std::distance(tangent.rows.begin(), std::find(tangent.rows.begin(), tangent.rows.end(), row));
      columns.push_back(tangent.G.row(position).transpose());
      names.push_back(input.name);
      continue;
    }
    if (input.kind == LinearInputKind::kRsdaTorque) {
      // τ on body j about the axis, −τ on body i (dynamics.cpp's RSDA).
      LIMBER_DEMAND(input.force >= 0 && input.force < static_cast<int>(model.forces.size()));
      const Rsda* rsda = std::get_if<Rsda>(&model.forces[static_cast<std::size_t>(input.force)]);
      LIMBER_DEMAND(rsda != nullptr);
      const FrameKinematics& mi = ws.markers[static_cast<std::size_t>(rsda->marker_i)];
      const FrameKinematics& mj = ws.markers[static_cast<std::size_t>(rsda->marker_j)];
      const Eigen::Vector3d u = relative_angle(mi, mj, Stage::kPosition).u;
      Eigen::VectorXd Q = Eigen::VectorXd::Zero(model.nv);
      add_frame_load(mj, zero, u, Q);
      add_frame_load(mi, zero, -u, Q);
      columns.push_back(Q);
      names.push_back(input.name);
      continue;
    }
    LIMBER_DEMAND(input.marker >= 0 && input.marker < static_cast<int>(model.markers.size()));
    const FrameKinematics& marker = ws.markers[static_cast<std::size_t>(input.marker)];
    const Eigen::Matrix3d E = channel_axes(marker, input.axes);
    for (int k = 0; k < 3; ++k) {
      Eigen::VectorXd Q = Eigen::VectorXd::Zero(model.nv);
      const bool force = input.kind == LinearInputKind::kForce;
      add_frame_load(marker, force ? Eigen::Vector3d(E.col(k)) : zero, force ? zero : Eigen::Vector3d(E.col(k)), Q);
      columns.push_back(Q);
      names.push_back(input.name + kAxisSuffix[k]);
    }
  }
  Eigen::MatrixXd B_xi(model.nv, static_cast<Eigen::Index>(columns.size()));
  for (std::size_t c = 0; c < columns.size(); ++c) B_xi.col(static_cast<Eigen::Index>(c)) = columns[c];
  return B_xi;
}

bool is_reaction(LinearOutputKind kind) {
  return kind == LinearOutputKind::kReactionForce || kind == LinearOutputKind::kReactionTorque;
}

bool is_translational(LinearOutputKind kind) {
  return kind == LinearOutputKind::kPosition || kind == LinearOutputKind::kVelocity ||
         kind == LinearOutputKind::kAcceleration;
}

// 0: displacement or rotation (of y), 1: rate (of ẏ), 2: acceleration (of ÿ).
int derivative_order(LinearOutputKind kind) {
  switch (kind) {
    case LinearOutputKind::kPosition:
    case LinearOutputKind::kRotation: return 0;
    case LinearOutputKind::kVelocity:
    case LinearOutputKind::kAngularVelocity: return 1;
    case LinearOutputKind::kAcceleration:
    case LinearOutputKind::kAngularAcceleration:
    case LinearOutputKind::kReactionForce:
    case LinearOutputKind::kReactionTorque: return 2;
  }
  return 0;
}

}  // namespace

StateSpace state_space(const Model& model, const State& point, const TangentMatrices& tangent,
                       const Eigen::MatrixXd& Z, const std::vector<LinearInput>& inputs,
                       const std::vector<LinearOutput>& outputs) {
  StateSpace ss;
  Workspace ws(model);
  update_marker_kinematics(model, point, Stage::kPosition, ws);
  // Drivers whose efforts are inputs are released: their rows leave G and the basis grows.
  check_released_drivers(model, point, inputs, ws);
  const std::vector<Eigen::Index> released = released_positions(model, tangent, inputs);
  const TangentMatrices held = without_rows(tangent, released);
  ss.Z = released.empty() ? Z : null_space_basis(held.G, model.nv);
  const Eigen::Index n = ss.Z.cols();
  const Eigen::MatrixXd B_xi = input_forces(model, ws, tangent, inputs, ss.input_names);
  const Eigen::Index ni = B_xi.cols();

  // ÿ = −Mr⁻¹Kr y − Mr⁻¹Cr ẏ + Mr⁻¹ Zᵀ B_ξ u: the second block row of A and B.
  const Eigen::LLT<Eigen::MatrixXd> Mr = reduced_mass_factor(tangent.M, ss.Z);
  Eigen::MatrixXd accel_x(n, 2 * n);
  accel_x << -Mr.solve(ss.Z.transpose() * tangent.K * ss.Z), -Mr.solve(ss.Z.transpose() * tangent.C * ss.Z);
  const Eigen::MatrixXd accel_u = Mr.solve(ss.Z.transpose() * B_xi);
  ss.A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  ss.A.topRightCorner(n, n).setIdentity();
  ss.A.bottomRows(n) = accel_x;
  ss.B = Eigen::MatrixXd::Zero(2 * n, ni);
  ss.B.bottomRows(n) = accel_u;
  for (Eigen::Index i = 0; i < n; ++i) ss.state_names.push_back(fmt::format("y{}", i + 1));
  for (Eigen::Index i = 0; i < n; ++i) ss.state_names.push_back(fmt::format("y{}_dot", i + 1));

  // Each output: three rows of J Z applied to y, ẏ or ÿ, along the channel axes; a reaction's
  // from the linearized multipliers (solved once for all of them).
  ss.C = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(outputs.size()), 2 * n);
  ss.D = Eigen::MatrixXd::Zero(ss.C.rows(), ni);
  std::optional<LinearMultipliers> multipliers;
  for (std::size_t o = 0; o < outputs.size(); ++o) {
    const LinearOutput& output = outputs[o];
    const auto rows = Eigen::seqN(3 * static_cast<Eigen::Index>(o), 3);
    for (const char* suffix : kAxisSuffix) ss.output_names.push_back(output.name + suffix);
    if (is_reaction(output.kind)) {
      if (!multipliers) multipliers = linear_multipliers(model, point, held, ss.Z, B_xi);
      Eigen::MatrixXd C_rows, D_rows;
      reaction_rows(model, point, held, ss.Z, *multipliers, output, C_rows, D_rows);
      ss.C(rows, Eigen::all) = C_rows;
      ss.D(rows, Eigen::all) = D_rows;
      continue;
    }
    LIMBER_DEMAND(output.marker >= 0 && output.marker < static_cast<int>(model.markers.size()));
    const FrameKinematics& marker = ws.markers[static_cast<std::size_t>(output.marker)];
    const Eigen::MatrixXd& J = is_translational(output.kind) ? marker.J_p : marker.J_w;
    const Eigen::MatrixXd JZ = channel_axes(marker, output.axes).transpose() * J * ss.Z;  // 3 x n
    switch (derivative_order(output.kind)) {
      case 0: ss.C(rows, Eigen::seqN(0, n)) = JZ; break;
      case 1: ss.C(rows, Eigen::seqN(n, n)) = JZ; break;
      default:
        ss.C(rows, Eigen::all) = JZ * accel_x;
        ss.D(rows, Eigen::all) = JZ * accel_u;
    }
  }
  return ss;
}

}  // namespace limber::multibody
