#include "modal/rigid_body_modes.h"

#include <algorithm>

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "core/error.h"

namespace limber::modal {
namespace {

// Scale of the rotation columns: the largest node coordinate magnitude, at least 1 m.
double rotation_scale(const Eigen::MatrixXd& psi) {
  const double scale = psi.rightCols(3).cwiseAbs().maxCoeff();
  return std::max(scale, 1.0);
}

}  // namespace

Eigen::MatrixXd rigid_body_modes(const std::vector<Eigen::Vector3d>& node_positions) {
  const int nodes = static_cast<int>(node_positions.size());
  Eigen::MatrixXd psi = Eigen::MatrixXd::Zero(fe::kDofsPerNode * nodes, 6);
  for (int p = 0; p < nodes; ++p) {
    const Eigen::Vector3d& x = node_positions[static_cast<std::size_t>(p)];
    const int row = fe::kDofsPerNode * p;
    for (int k = 0; k < 3; ++k) {
      // Translation k.
      psi(row + k, k) = 1.0;
      // Small rotation k: u = e_k × x, theta = e_k.
      psi.block<3, 1>(row, 3 + k) = Eigen::Vector3d::Unit(k).cross(x);
      psi(row + 3 + k, 3 + k) = 1.0;
    }
  }
  return psi;
}

Eigen::MatrixXd rigid_body_modes(const fe::FeModel& model) {
  return rigid_body_modes(model.node_positions);
}

Eigen::MatrixXd unrestrained_rigid_motion(const Eigen::MatrixXd& psi,
                                          const std::vector<int>& held_dofs) {
  LIMBER_DEMAND(psi.cols() == 6);
  if (held_dofs.empty()) return psi;
  // Scale rotations to the model size so that the rank test is unit-free.
  Eigen::VectorXd column_scale = Eigen::VectorXd::Ones(6);
  column_scale.tail(3).setConstant(1.0 / rotation_scale(psi));
  Eigen::MatrixXd held(static_cast<Eigen::Index>(held_dofs.size()), 6);
  for (std::size_t i = 0; i < held_dofs.size(); ++i) {
    held.row(static_cast<Eigen::Index>(i)) = psi.row(held_dofs[i]).cwiseProduct(column_scale.transpose());
  }
  // Null space of the held rows from the full SVD (right singular vectors).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(held, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  int rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s[i] > kRankTolerance * s[0]) ++rank;
  }
  const Eigen::MatrixXd null_space = svd.matrixV().rightCols(6 - rank);
  return psi * column_scale.asDiagonal() * null_space;
}

std::vector<int> determinate_support(const Eigen::MatrixXd& psi_free,
                                     const std::vector<int>& candidates) {
  const Eigen::Index r = psi_free.cols();
  if (r == 0) return {};
  // Translational candidates first (a rotational support on a shell's drilling DOF
  // would be weak), then all of them.
  std::vector<int> translational;
  for (int dof : candidates) {
    if (dof % fe::kDofsPerNode < 3) translational.push_back(dof);
  }
  const std::vector<int>* pools[] = {&translational, &candidates};
  for (const std::vector<int>* pool : pools) {
    if (static_cast<Eigen::Index>(pool->size()) < r) continue;
    Eigen::MatrixXd rows_t(r, static_cast<Eigen::Index>(pool->size()));
    for (std::size_t i = 0; i < pool->size(); ++i) {
      rows_t.col(static_cast<Eigen::Index>(i)) = psi_free.row((*pool)[i]).transpose();
    }
    // Column-pivoted QR: the first r pivots are the best-conditioned DOF choice.
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(rows_t);
    qr.setThreshold(kRankTolerance);
    if (qr.rank() < r) continue;
    std::vector<int> support;
    for (Eigen::Index i = 0; i < r; ++i) {
      support.push_back((*pool)[static_cast<std::size_t>(qr.colsPermutation().indices()[i])]);
    }
    std::sort(support.begin(), support.end());
    return support;
  }
  // Unreachable from any input: psi_free's r columns are independent (psi holds a unit row
  // per translation and rotation) and its rows over the held DOFs are zero to the rank
  // tolerance, so its rows over the remaining DOFs, which the callers pass as candidates,
  // have rank r (tests/modal/test_static_modes.cpp checks every held set of a beam and a
  // shell node).
  LIMBER_DEMAND(false && "no statically determinate support among the candidate DOFs");
  return {};
}

}  // namespace limber::modal
