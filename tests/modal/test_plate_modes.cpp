// Modes and invariants of a free square shell plate (flat quads, 6 DOFs per node): the
// rigid-mode classification and sparse-vs-dense agreement on a 2-D mesh, and the rigid
// inertia including the shell's rotary (rho t^3 / 12) terms.
#include <cmath>

#include <gtest/gtest.h>

#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "modal/component_modes.h"
#include "modal/modal_invariants.h"
#include "modal/normal_modes.h"
#include "modal/rigid_body_modes.h"
#include "modal_test_support.h"

namespace limber::modal {
namespace {

constexpr double kSide = 1.0;
constexpr double kThickness = 0.01;

// Free steel plate kSide x kSide x kThickness in the x-y plane, corner at the origin.
fe::FeModel free_plate(int n) {
  fe::FeModelBuilder builder;
  fe::RectangularPlateMesh mesh;
  mesh.elements_x = n;
  mesh.elements_y = n;
  mesh.edge_x = kSide * Eigen::Vector3d::UnitX();
  mesh.edge_y = kSide * Eigen::Vector3d::UnitY();
  mesh.property = builder.add_shell_property({"plate", testing::paper_steel(), kThickness});
  fe::add_rectangular_plate(builder, mesh);
  return std::move(builder).build();
}

TEST(PlateModes, FreePlateRigidModesAndArpackMatchDenseSolver) {
  const fe::FeModel model = free_plate(10);  // 726 DOFs
  const fe::StructuralMatrices mats = fe::assemble(model);
  NormalModeRequest request;
  request.count = 8;
  request.rigid_count = 6;
  const NormalModes modes =
      compute_normal_modes(mats.stiffness, mats.mass, fe::free_dofs(model), request);
  ASSERT_EQ(modes.status, ModalStatus::kOk) << modes.message;
  EXPECT_TRUE(modes.notices.empty());
  ASSERT_EQ(modes.rigid_eigenvalues.size(), 6);
  ASSERT_EQ(modes.eigenvalues.size(), 8);

  // Second method: dense solution of the same problem (its 6 lowest are the rigid ones).
  const Eigen::VectorXd dense = testing::dense_eigenvalues(mats.stiffness, mats.mass);
  const double lambda_max = dense[dense.size() - 1];
  for (int j = 0; j < 8; ++j) {
    // Backward-stable solvers: relative agreement ~eps lambda_max / lambda_j; bound 100 x.
    EXPECT_NEAR(modes.eigenvalues[j] / dense[6 + j], 1.0, 100.0 * 2.2e-16 * lambda_max / dense[6 + j])
        << "elastic mode " << j + 1;
  }
  // The square plate's 4th and 5th elastic modes are a degenerate pair (symmetry); both
  // solvers must find it (compare frequencies, not vectors: PITFALLS.md).
  EXPECT_NEAR(modes.eigenvalues[3] / modes.eigenvalues[4], 1.0, 1e-9);
  // Rigid modes: two decades (here more than four) below the first elastic mode.
  for (Eigen::Index i = 0; i < 6; ++i) {
    EXPECT_LT(std::abs(frequency_hz(modes.rigid_eigenvalues[i])),
              1e-4 * frequency_hz(modes.eigenvalues[0]));
  }
}

TEST(PlateModes, PlateInertiaIncludesShellRotaryTerms) {
  const fe::FeModel model = free_plate(8);
  const fe::StructuralMatrices mats = fe::assemble(model);
  const ModalInvariants inv = compute_modal_invariants(mats.mass, rigid_body_modes(model),
                                                       Eigen::MatrixXd(model.dof_count(), 0));
  const double rho = testing::paper_steel().density;
  const double m = rho * kThickness * kSide * kSide;
  // Section rotary inertia per unit area rho t^3 / 12 on rx, ry (and on the drilling rz,
  // see shell_element.cpp) times the area.
  const double rotary = rho * std::pow(kThickness, 3) / 12.0 * kSide * kSide;
  // Consistent bilinear mass integrates the rigid fields exactly: round-off only.
  EXPECT_NEAR(inv.mass / m, 1.0, 1e-12);
  EXPECT_LT((inv.first_moment - m * Eigen::Vector3d(0.5, 0.5, 0.0)).norm() / m, 1e-12);
  // About the corner: J_xx = J_yy = m a^2 / 3 + rotary, J_zz = 2 m a^2 / 3 + rotary,
  // J_xy = -m a^2 / 4 (product of inertia, -integral of x y dm).
  Eigen::Matrix3d expected;
  expected << m / 3.0 + rotary, -m / 4.0, 0.0, -m / 4.0, m / 3.0 + rotary, 0.0, 0.0, 0.0,
      2.0 * m / 3.0 + rotary;
  EXPECT_LT((inv.inertia - expected).cwiseAbs().maxCoeff(), 1e-12 * m) << inv.inertia;
  // The rotary terms are resolved: 1e-12 m is 1e-7 of rotary (= 2.5e-5 m here).
  EXPECT_GT(rotary, 1e4 * 1e-12 * m);
}

TEST(PlateModes, FreePlateInertiaReliefAndConstraintModesCombine) {
  // Attachment mode at a corner (uz) and constraint modes at the mid-node of an edge:
  // the full pipeline on a shell model, with the required orthonormality.
  const fe::FeModel model = free_plate(10);
  const fe::StructuralMatrices mats = fe::assemble(model);
  ModeRequest request;
  request.normal_count = 6;
  request.attachment_sites = {{0, {fe::Dof::kUz}}};
  request.constraint_sites = {{5, {fe::Dof::kUz, fe::Dof::kRx}}};
  const ModalResult result = compute_component_modes(model, mats, request);
  ASSERT_EQ(result.status, ModalStatus::kOk) << result.message;
  EXPECT_EQ(result.mode_set.rigid_modes.size(), 6u);
  // Constraint modes at a single node of a free body are rigid motions (uz: translation
  // along z; rx: rotation about the x axis through the node): both are removed.
  EXPECT_EQ(result.mode_set.shapes.cols(), 6 + 1);
  // Required 1e-10; round-off level expected.
  EXPECT_LT(testing::orthonormality_error(mats.mass, result.mode_set.shapes), 1e-10);
  EXPECT_LT(testing::k_diagonality_error(mats.stiffness, result.mode_set.shapes), 1e-10);
  // Inertia-relief and normal modes are free of rigid motion: frame couplings vanish.
  const double coupling =
      std::max(result.mode_set.invariants.translation_coupling.cwiseAbs().maxCoeff(),
               result.mode_set.invariants.rotation_coupling.cwiseAbs().maxCoeff());
  EXPECT_LT(coupling, 1e-8 * std::sqrt(result.mode_set.invariants.mass));
}

}  // namespace
}  // namespace limber::modal
