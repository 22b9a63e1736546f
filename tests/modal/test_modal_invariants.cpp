// Modal invariants of a beam: closed-form rigid-body inertia (rotary inertia of the
// section included) and the first/second-order inertia terms against J(eta) rebuilt from
// Psi at deformed node positions (second method).
#include <cmath>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "modal/modal_invariants.h"
#include "modal/normal_modes.h"
#include "modal/rigid_body_modes.h"
#include "modal_test_support.h"

namespace limber::modal {
namespace {

// [v]× (cross-product matrix).
Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

TEST(ModalInvariants, BeamMassCentreAndInertiaMatchClosedForms) {
  // Seed paper rod, 100 elements with rotary inertia, along +x from `start`.
  const fe::BeamProperty rod = testing::rod_property(true);
  const double rho = rod.material.density;
  const double length = 1.0;
  const double m = rho * rod.section.area * length;
  const double iy = rod.section.inertia_y;
  const double iz = rod.section.inertia_z;
  for (const Eigen::Vector3d& start : {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.2, 0.1, -0.3)}) {
    const fe::FeModel model = testing::rod_model(100, true, {}, length, start);
    const fe::StructuralMatrices mats = fe::assemble(model);
    const ModalInvariants inv =
        compute_modal_invariants(mats.mass, rigid_body_modes(model), Eigen::MatrixXd(model.dof_count(), 0));
    // Consistent mass integrates rigid motion exactly: round-off of ~1e3 summed terms.
    EXPECT_NEAR(inv.mass / m, 1.0, 1e-12);
    const Eigen::Vector3d c = start + Eigen::Vector3d(0.5 * length, 0.0, 0.0);
    EXPECT_LT((inv.first_moment - m * c).norm() / (m * length), 1e-12);
    // About the centre: rho L (Iy + Iz) about the axis (torsional mass of the section),
    // m L^2 / 12 + rho Iy L and m L^2 / 12 + rho Iz L about y and z (bending rotary inertia);
    // moved to the frame origin by the parallel-axis theorem J_O = J_c + m [c]×^T [c]×.
    Eigen::Matrix3d j_c = Eigen::Matrix3d::Zero();
    j_c.diagonal() << rho * length * (iy + iz), m * length * length / 12.0 + rho * iy * length,
        m * length * length / 12.0 + rho * iz * length;
    const Eigen::Matrix3d j_o = j_c + m * skew(c).transpose() * skew(c);
    EXPECT_LT((inv.inertia - j_o).cwiseAbs().maxCoeff() / j_o.norm(), 1e-12) << inv.inertia;
    // The section terms matter: rho L (Iy + Iz) is 4e-5 of m L^2 / 12 but present exactly.
    if (start.isZero()) {
      EXPECT_NEAR(inv.inertia(0, 0) / (rho * length * (iy + iz)), 1.0, 1e-10);
      EXPECT_NEAR(inv.inertia(1, 1) / (m * length * length / 3.0 + rho * iy * length), 1.0, 1e-12);
    }
  }
}

// J(eta) = Psi_r(x + sum eta_i phi_i,t)^T M Psi_r(...), Psi rebuilt at deformed positions.
Eigen::Matrix3d rebuilt_inertia(const fe::FeModel& model, const Eigen::SparseMatrix<double>& mass,
                                const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> positions = model.node_positions;
  for (std::size_t p = 0; p < positions.size(); ++p) {
    positions[p] += u.segment<3>(fe::kDofsPerNode * static_cast<Eigen::Index>(p));
  }
  const Eigen::MatrixXd psi_r = rigid_body_modes(positions).rightCols(3);
  return psi_r.transpose() * (mass * psi_r);
}

TEST(ModalInvariants, InertiaExpansionMatchesRebuiltRigidBodyModes) {
  // Offset cantilever rod, 20 elements, 4 normal modes (bending in both planes).
  const fe::FeModel model = testing::rod_model(20, true, {0}, 1.0, Eigen::Vector3d(0.2, 0.1, -0.3));
  const fe::StructuralMatrices mats = fe::assemble(model);
  NormalModeRequest request;
  request.count = 4;
  const NormalModes modes =
      compute_normal_modes(mats.stiffness, mats.mass, fe::free_dofs(model), request);
  ASSERT_EQ(modes.status, ModalStatus::kOk);
  const ModalInvariants inv =
      compute_modal_invariants(mats.mass, rigid_body_modes(model), modes.shapes);
  ASSERT_EQ(inv.inertia_first_order.size(), 4u);
  ASSERT_EQ(inv.inertia_second_order.size(), 16u);

  // J is quadratic in eta: central differences are exact up to round-off,
  //   (J(h e_i) - J(-h e_i)) / 2h = J1_i,   J(h e_i) + J(-h e_i) - 2 J0 = 2 h^2 J2_ii.
  // h = 1e-3 kg^1/2 m gives tip deflections of ~1 mm; round-off eps ||J0|| / h ~ 1e-13 ||J0||.
  const double h = 1e-3;
  const double scale = inv.inertia.norm();
  for (int i = 0; i < 4; ++i) {
    const Eigen::VectorXd u = h * modes.shapes.col(i);
    const Eigen::Matrix3d plus = rebuilt_inertia(model, mats.mass, u);
    const Eigen::Matrix3d minus = rebuilt_inertia(model, mats.mass, -u);
    const Eigen::Matrix3d first = (plus - minus) / (2.0 * h);
    const Eigen::Matrix3d second = (plus + minus - 2.0 * inv.inertia) / (2.0 * h * h);
    // The first-order term is not trivially zero here (offset, clamped: J_xz-type terms).
    EXPECT_GT(inv.inertia_first_order[i].norm(), 1e-3 * scale / std::sqrt(inv.mass));
    // Bounds: 1e-9 ||J0|| / h (1e4 x the round-off estimate) and 1e-9 ||J0|| / h^2.
    EXPECT_LT((first - inv.inertia_first_order[i]).cwiseAbs().maxCoeff(), 1e-9 * scale / h)
        << "mode " << i;
    EXPECT_LT((second - inv.inertia_second_order[i * 4 + i]).cwiseAbs().maxCoeff(),
              1e-9 * scale / (h * h))
        << "mode " << i;
  }
  // A mixed second-order term: J(h e_0 + h e_1) expands to J0 + h (J1_0 + J1_1)
  // + h^2 (J2_00 + J2_11 + J2_01 + J2_10).
  const Eigen::Matrix3d mixed = rebuilt_inertia(model, mats.mass, h * (modes.shapes.col(0) + modes.shapes.col(1)));
  const Eigen::Matrix3d expansion =
      inv.inertia + h * (inv.inertia_first_order[0] + inv.inertia_first_order[1]) +
      h * h * (inv.inertia_second_order[0] + inv.inertia_second_order[5] +
               inv.inertia_second_order[1] + inv.inertia_second_order[4]);
  // Exact identity: round-off of J only (eps ||J0||), bound 1e-13 ||J0||.
  EXPECT_LT((mixed - expansion).cwiseAbs().maxCoeff(), 1e-13 * scale);

  // Couplings against their definitions through Psi (second method for the layout):
  // S_t = Psi_t^T M Phi, S_r = Psi_r^T M Phi.
  const Eigen::MatrixXd psi = rigid_body_modes(model);
  const Eigen::MatrixXd s = psi.transpose() * (mats.mass * modes.shapes);
  EXPECT_LT((inv.translation_coupling - s.topRows(3)).cwiseAbs().maxCoeff(), 1e-12 * s.norm());
  EXPECT_LT((inv.rotation_coupling - s.bottomRows(3)).cwiseAbs().maxCoeff(), 1e-12 * s.norm());
}

}  // namespace
}  // namespace limber::modal
