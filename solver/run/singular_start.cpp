#include "run/singular_start.h"

#include <Eigen/SVD>

#include "multibody/body.h"
#include "multibody/constraints.h"

namespace limber::run {
namespace {

// Relative size below which a unit row adds nothing to the rows before it: the redundancy
// threshold (redundancy.h), between a probe's O(ε²) = 1e-8 and its O(ε) = 1e-4.
constexpr double kRowTolerance = multibody::kRedundancyThreshold;

// The frame columns of G (the rigid skeleton), rows scaled to unit norm. Modal columns are
// left out: a flexible body's deformation can make a redundant equation independent at first
// order (the slider-crank rod's R3.rot_x, deformation_redundancy.h), which is no singularity of
// the mechanism.
Eigen::MatrixXd skeleton_rows(const multibody::Model& model, const multibody::State& state,
                              multibody::Workspace& ws) {
  multibody::evaluate_constraints(model, state, multibody::Stage::kPosition, ws);
  Eigen::MatrixXd S(ws.G.rows(), 0);
  for (const multibody::Body& b : model.bodies) {
    if (b.nv < 6) continue;
    S.conservativeResize(Eigen::NoChange, S.cols() + 6);
    S.rightCols<6>() = ws.G.middleCols<6>(b.v_offset);
  }
  return multibody::unit_rows(S);
}

}  // namespace

std::vector<int> rows_lost_at_singular_start(const multibody::Model& model,
                                             const multibody::State& state,
                                             const multibody::ConstraintPartition& partition,
                                             multibody::Workspace& ws) {
  if (partition.redundant.empty()) return {};
  const Eigen::MatrixXd S = skeleton_rows(model, state, ws);
  if (S.cols() == 0) return {};
  // The start's independent rows first, then the rest: the order the analysis chose.
  std::vector<int> order = partition.independent;
  for (const multibody::RedundantEquation& r : partition.redundant) order.push_back(r.row);
  const std::vector<bool> at_start = multibody::rows_adding_directions(S, order, kRowTolerance);

  // Directions the constraints allow to first order: the null space of the skeleton's rows.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(S, Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const int rank = static_cast<int>((sigma.array() > kRowTolerance * sigma(0)).count());
  const int nullity = static_cast<int>(S.cols()) - rank;
  if (nullity == 0) return {};
  const Eigen::MatrixXd null_space = svd.matrixV().rightCols(nullity);

  // A few fixed, generic combinations (a single one could miss the branch's direction).
  std::vector<bool> lost(static_cast<std::size_t>(S.rows()), false);
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd weights(nullity);
    for (int k = 0; k < nullity; ++k) weights(k) = 1.0 + 0.37 * ((k * 7 + trial * 3) % 11) - 0.9 * (k % 2);
    const Eigen::VectorXd step = kSingularStartProbe * (null_space * weights).normalized();
    // The step on the frames only (the modal coordinates stay).
    Eigen::VectorXd dv = Eigen::VectorXd::Zero(model.nv);
    int column = 0;
    for (const multibody::Body& b : model.bodies) {
      if (b.nv < 6) continue;
      dv.segment<6>(b.v_offset) = step.segment<6>(column);
      column += 6;
    }
    multibody::State probe = state;
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      multibody::integrate_body_coordinates(model, static_cast<int>(b), state.q, dv, probe.q);
    }
    const std::vector<bool> near = multibody::rows_adding_directions(skeleton_rows(model, probe, ws), order, kRowTolerance);
    for (std::size_t row = 0; row < near.size(); ++row) {
      if (near[row] && !at_start[row]) lost[row] = true;
    }
  }
  std::vector<int> rows;
  for (std::size_t row = 0; row < lost.size(); ++row) {
    if (lost[row]) rows.push_back(static_cast<int>(row));
  }
  return rows;
}

}  // namespace limber::run
