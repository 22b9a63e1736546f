#include "modal/rigid_body_modes.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "core/error.h"

namespace limber::modal {
namespace {

// Psi with every translational row divided by the nodes' extent: dimensionless (a unit rotation
// moves the farthest node by at most about 1), so that rank decisions hold at any model size.
Eigen::MatrixXd dimensionless_rows(const Eigen::MatrixXd& psi, double length) {
  Eigen::MatrixXd scaled = psi;
  // No column (every rigid motion held): a block of an empty matrix offsets a null pointer.
  if (scaled.cols() == 0) return scaled;
  for (Eigen::Index row = 0; row < scaled.rows(); row += fe::kDofsPerNode) {
    scaled.middleRows(row, 3) /= length;
  }
  return scaled;
}

// An orthonormal basis (thin Q) of the columns of dimensionless_rows(motions, length).
Eigen::MatrixXd dimensionless_basis(const Eigen::MatrixXd& motions, double length) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(dimensionless_rows(motions, length));
  return qr.householderQ() * Eigen::MatrixXd::Identity(motions.rows(), motions.cols());
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

double rigid_length_scale(const Eigen::MatrixXd& psi) {
  // Node p's position from its rows of the rotation columns (-[x_p]x); a node with a zeroed row
  // (a DOF made dependent by a multipoint constraint) is skipped.
  std::vector<Eigen::Vector3d> positions;
  for (Eigen::Index row = 0; row < psi.rows(); row += fe::kDofsPerNode) {
    if (psi(row, 0) != 1.0 || psi(row + 1, 1) != 1.0 || psi(row + 2, 2) != 1.0) continue;
    positions.emplace_back(psi(row + 1, 5), psi(row + 2, 3), psi(row, 4));
  }
  if (positions.empty()) return 1.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& x : positions) centre += x;
  centre /= static_cast<double>(positions.size());
  double length = 0.0;
  for (const Eigen::Vector3d& x : positions) length = std::max(length, (x - centre).stableNorm());
  // One node (or all at one point): rotations move no node, any length will do.
  return length > 0.0 ? length : 1.0;
}

Eigen::MatrixXd unrestrained_rigid_motion(const Eigen::MatrixXd& psi,
                                          const std::vector<int>& held_dofs) {
  LIMBER_DEMAND(psi.cols() == 6);
  if (held_dofs.empty()) return psi;
  // An orthonormal basis of the rigid motions in dimensionless rows: the rank test below is
  // then free of units, of the model's size and of its distance from the frame origin.
  const double length = rigid_length_scale(psi);
  const Eigen::MatrixXd basis = dimensionless_basis(psi, length);
  Eigen::MatrixXd held(static_cast<Eigen::Index>(held_dofs.size()), 6);
  for (std::size_t i = 0; i < held_dofs.size(); ++i) {
    held.row(static_cast<Eigen::Index>(i)) = basis.row(held_dofs[i]);
  }
  // Null space of the held rows from the full SVD (right singular vectors).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(held, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  int rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s[i] > kRankTolerance * s[0]) ++rank;
  }
  // Back to metres in the translational rows.
  return dimensionless_rows(basis * svd.matrixV().rightCols(6 - rank), 1.0 / length);
}

std::vector<int> determinate_support(const Eigen::MatrixXd& psi_free,
                                     const std::vector<int>& candidates, double length) {
  const Eigen::Index r = psi_free.cols();
  if (r == 0) return {};
  // The same motions in an orthonormal basis of dimensionless rows, as in the rank test of
  // unrestrained_rigid_motion (psi_free may be Psi itself, whose columns differ by 1/length).
  const Eigen::MatrixXd scaled = dimensionless_basis(psi_free, length);
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
      rows_t.col(static_cast<Eigen::Index>(i)) = scaled.row((*pool)[i]).transpose();
    }
    // Column-pivoted QR: the first r pivots are the best-conditioned DOF choice. They must be
    // of the basis's order (its rows over all candidates have singular values 1), an absolute
    // test: QR's own threshold is relative to the largest pivot, and took round-off for a
    // support (a free beam held at both ends' translations along a skew axis: the rotation
    // about it moves the nodes by ~1e-17, and a translation was chosen to stop it).
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(rows_t);
    if (std::abs(qr.matrixR()(r - 1, r - 1)) <= kRankTolerance) continue;
    std::vector<int> support;
    for (Eigen::Index i = 0; i < r; ++i) {
      support.push_back((*pool)[static_cast<std::size_t>(qr.colsPermutation().indices()[i])]);
    }
    std::sort(support.begin(), support.end());
    return support;
  }
  // Unreachable from any input: the basis's r columns are orthonormal and its rows over the
  // held DOFs are zero to the rank tolerance, so its rows over the remaining DOFs, which the
  // callers pass as candidates, have singular values near 1 whatever the model's size
  // (tests/modal/test_static_modes.cpp checks every held set of a beam and a shell patch, at
  // sizes 1e-12 to 1e12 m and far from the origin).
  LIMBER_DEMAND(false && "no statically determinate support among the candidate DOFs");
  return {};
}

}  // namespace limber::modal
