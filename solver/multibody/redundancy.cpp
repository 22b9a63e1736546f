#include "multibody/redundancy.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "core/error.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"

namespace limber::multibody {

namespace {

// Coefficients below this (rows have unit norm) are rounding or a mode set's spurious
// content (redundancy.h), not dependence: true dependencies combine rows with O(1) weights.
constexpr double kCoefficientTolerance = 1e-4;

void mark_indeterminate(const Model& model, ConstraintPartition& p) {
  p.row_indeterminate.assign(model.num_equations(), false);
  p.joint_indeterminate.assign(model.joints.size(), false);
  for (const RedundantEquation& r : p.redundant) {
    p.row_indeterminate[r.row] = true;
    for (int k : r.depends_on) p.row_indeterminate[k] = true;
  }
  for (int row = 0; row < model.num_equations(); ++row) {
    const int joint = model.equations[row].joint;
    if (p.row_indeterminate[row] && joint >= 0) p.joint_indeterminate[joint] = true;
  }
}

}  // namespace

Eigen::MatrixXd unit_rows(Eigen::MatrixXd A) {
  for (Eigen::Index row = 0; row < A.rows(); ++row) {
    const double norm = A.row(row).norm();
    if (norm > 0.0) A.row(row) /= norm;
  }
  return A;
}

Eigen::MatrixXd mass_metric_rows(const Model& model, const State& state, Workspace& ws) {
  evaluate_constraints(model, state, Stage::kPosition, ws);
  mass_matrix(model, state, ws);
  const Eigen::LLT<Eigen::MatrixXd> mass(ws.M);
  LIMBER_DEMAND(mass.info() == Eigen::Success);
  return unit_rows(mass.matrixL().solve(ws.G.transpose()).transpose());
}

std::vector<bool> rows_adding_directions(const Eigen::MatrixXd& S, const std::vector<int>& order,
                                         double tolerance) {
  std::vector<bool> adds(static_cast<std::size_t>(S.rows()), false);
  Eigen::MatrixXd basis(S.cols(), 0);  // orthonormal columns
  for (int row : order) {
    Eigen::VectorXd r = S.row(row).transpose();
    if (r.norm() == 0.0) continue;
    r -= basis * (basis.transpose() * r);
    r -= basis * (basis.transpose() * r);  // twice: orthogonal to rounding
    if (r.norm() <= tolerance) continue;
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = r.normalized();
    adds[static_cast<std::size_t>(row)] = true;
  }
  return adds;
}

std::vector<std::string> ConstraintPartition::describe(const Model& model) const {
  std::vector<std::string> lines;
  for (const RedundantEquation& r : redundant) {
    std::string line = model.equations[r.row].name + " is redundant";
    for (size_t k = 0; k < r.depends_on.size(); ++k) {
      line += (k == 0 ? " with " : ", ") + model.equations[r.depends_on[k]].name;
    }
    lines.push_back(line);
  }
  return lines;
}

ConstraintPartition full_partition(const Model& model) {
  ConstraintPartition p;
  for (int row = 0; row < model.num_equations(); ++row) p.independent.push_back(row);
  mark_indeterminate(model, p);
  return p;
}

std::vector<bool> rows_released_by(const Model& model, double t) {
  std::vector<bool> released(static_cast<std::size_t>(model.num_equations()), false);
  bool any = false;
  for (const Joint& joint : model.joints) {
    if (joint.release_time > t) continue;
    any = true;
    for (int row = joint.first_row; row < joint.first_row + joint.rows; ++row) {
      released[static_cast<std::size_t>(row)] = true;
    }
  }
  return any ? released : std::vector<bool>{};
}

ConstraintPartition analyse_redundancy(const Model& model, const State& state, Workspace& ws,
                                       double relative_threshold, const std::vector<int>& keep,
                                       const std::vector<bool>& released) {
  const int m = model.num_equations();
  ConstraintPartition p;
  p.relative_threshold = relative_threshold;
  p.row_released = released;
  // Released rows as zero rows: pivoted last, below the rank, and then set aside.
  const auto without_released = [&](Eigen::MatrixXd A) {
    for (int row = 0; row < m; ++row) {
      if (p.released(row)) A.row(row).setZero();
    }
    return A;
  };
  // No equations (free bodies only): nothing to factorise (Eigen's QR of a 0-column matrix fails).
  if (m == 0) {
    mark_indeterminate(model, p);
    return p;
  }
  // The rank in the mass metric: rows of G L⁻ᵀ (M = L Lᵀ), whose products are G M⁻¹ Gᵀ.
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> weighted(
      without_released(mass_metric_rows(model, state, ws)).transpose());
  weighted.setThreshold(relative_threshold);
  const int rank = static_cast<int>(weighted.rank());
  // Which rows: the first `rank` pivots of G itself, whose order keeps whole joints where it
  // can (the mass metric would pick a set that turns singular as a slider-crank moves).
  const Eigen::MatrixXd S = without_released(unit_rows(ws.G));
  Eigen::MatrixXd S_pivoting = S;
  for (int row : keep) S_pivoting.row(row) *= 2.0;  // larger norms are pivoted first
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(S_pivoting.transpose());
  const auto& perm = qr.colsPermutation().indices();
  for (int k = 0; k < rank; ++k) p.independent.push_back(perm(k));
  std::sort(p.independent.begin(), p.independent.end());
  // Express each redundant row over the independent ones (least squares, exact up to rounding).
  Eigen::MatrixXd S_ind(rank, model.nv);
  for (int k = 0; k < rank; ++k) S_ind.row(k) = S.row(p.independent[k]);
  const Eigen::HouseholderQR<Eigen::MatrixXd> basis(S_ind.transpose());
  std::vector<int> redundant_rows;
  for (int k = rank; k < m; ++k) {
    if (!p.released(perm(k))) redundant_rows.push_back(perm(k));
  }
  std::sort(redundant_rows.begin(), redundant_rows.end());
  for (int row : redundant_rows) {
    RedundantEquation r{row, {}};
    if (rank > 0) {
      const Eigen::VectorXd c = basis.solve(Eigen::VectorXd(S.row(row).transpose()));
      for (int k = 0; k < rank; ++k) {
        if (std::abs(c(k)) > kCoefficientTolerance) r.depends_on.push_back(p.independent[k]);
      }
    }
    p.redundant.push_back(r);
  }
  mark_indeterminate(model, p);
  return p;
}

}  // namespace limber::multibody
