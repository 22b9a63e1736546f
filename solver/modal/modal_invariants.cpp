#include "modal/modal_invariants.h"

#include <Eigen/Geometry>

#include "core/error.h"
#include "fe/fe_model.h"

namespace limber::modal {

Eigen::MatrixXd rotation_field(const Eigen::VectorXd& shape) {
  LIMBER_DEMAND(shape.size() % fe::kDofsPerNode == 0);
  Eigen::MatrixXd field = Eigen::MatrixXd::Zero(shape.size(), 3);
  for (Eigen::Index row = 0; row < shape.size(); row += fe::kDofsPerNode) {
    const Eigen::Vector3d u = shape.segment<3>(row);
    // Column k at the node's translations: e_k × u.
    for (int k = 0; k < 3; ++k) field.block<3, 1>(row, k) = Eigen::Vector3d::Unit(k).cross(u);
  }
  return field;
}

ModalInvariants compute_modal_invariants(const Eigen::SparseMatrix<double>& mass,
                                         const Eigen::MatrixXd& psi,
                                         const Eigen::MatrixXd& shapes) {
  const Eigen::Index n = mass.rows();
  const Eigen::Index nm = shapes.cols();
  LIMBER_DEMAND(psi.rows() == n && psi.cols() == 6 && shapes.rows() == n);
  ModalInvariants inv;

  // Rigid-body mass matrix Psi^T M Psi: mass, first moment, inertia.
  const Eigen::MatrixXd m_psi = mass * psi;
  const Eigen::Matrix<double, 6, 6> rigid = psi.transpose() * m_psi;
  inv.mass = rigid.topLeftCorner<3, 3>().trace() / 3.0;
  const Eigen::Matrix3d s = rigid.topRightCorner<3, 3>();  // -[m c]×
  inv.first_moment = 0.5 * Eigen::Vector3d(s(1, 2) - s(2, 1), s(2, 0) - s(0, 2), s(0, 1) - s(1, 0));
  inv.inertia = rigid.bottomRightCorner<3, 3>();

  // Frame-mode couplings Psi^T M Phi.
  const Eigen::MatrixXd coupling = m_psi.transpose() * shapes;
  inv.translation_coupling = coupling.topRows(3);
  inv.rotation_coupling = coupling.bottomRows(3);

  // Rotation fields of all modes side by side, W = [Psi_r_1 ... Psi_r_nm], and M W.
  Eigen::MatrixXd w(n, 3 * nm);
  for (Eigen::Index i = 0; i < nm; ++i) w.middleCols(3 * i, 3) = rotation_field(shapes.col(i));
  const Eigen::MatrixXd m_w = mass * w;

  // First order: Psi_r^T M Psi_r_i + transpose; coupling Psi_r_i^T M Phi.
  const Eigen::MatrixXd psi_r_m_w = psi.rightCols(3).transpose() * m_w;
  const Eigen::MatrixXd w_m_phi = m_w.transpose() * shapes;
  for (Eigen::Index i = 0; i < nm; ++i) {
    const Eigen::Matrix3d a = psi_r_m_w.middleCols(3 * i, 3);
    inv.inertia_first_order.push_back(a + a.transpose());
    inv.rotation_coupling_first_order.push_back(w_m_phi.middleRows(3 * i, 3));
  }

  // Second order: Psi_r_i^T M Psi_r_j.
  const Eigen::MatrixXd w_m_w = w.transpose() * m_w;
  for (Eigen::Index i = 0; i < nm; ++i) {
    for (Eigen::Index j = 0; j < nm; ++j) {
      inv.inertia_second_order.push_back(w_m_w.block<3, 3>(3 * i, 3 * j));
    }
  }
  return inv;
}

}  // namespace limber::modal
