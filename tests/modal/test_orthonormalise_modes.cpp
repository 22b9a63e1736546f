// The combined mode set: M-orthonormality, K-diagonality, labels, dropped vectors, and the
// Craig-Bampton check (fixed-interface normal + constraint modes vs the full model).
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "modal/component_modes.h"
#include "modal/dof_selection.h"
#include "modal/normal_modes.h"
#include "modal/orthonormalise_modes.h"
#include "modal/rigid_body_modes.h"
#include "modal/static_modes.h"
#include "modal_test_support.h"

namespace limber::modal {
namespace {

using fe::Dof;

TEST(OrthonormaliseModes, FreeRodMixedSetIsOrthonormalKDiagonalAndLabelled) {
  // Seed paper rod, free: 5 normal modes, constraint modes ux, uz at both ends, an
  // attachment mode uy at mid-span.
  const fe::FeModel model = testing::rod_model(100, true, {});
  const fe::StructuralMatrices mats = fe::assemble(model);
  ModeRequest request;
  request.normal_count = 5;
  request.constraint_sites = {{0, {Dof::kUx, Dof::kUz}}, {100, {Dof::kUx, Dof::kUz}}};
  request.attachment_sites = {{50, {Dof::kUy}}};
  const ModalResult result = compute_component_modes(model, mats, request);
  ASSERT_EQ(result.status, ModalStatus::kOk) << result.message;
  const ModeSet& set = result.mode_set;

  // Rigid content of the span: the two uz modes are rigid (translation z, rotation y) and
  // the two ux modes add up to the x translation: 3 zero-frequency vectors removed.
  EXPECT_EQ(set.rigid_modes.size(), 6u);
  ASSERT_EQ(set.shapes.cols(), 5 + 4 + 1 - 3);
  EXPECT_NE(std::find_if(result.notices.begin(), result.notices.end(),
                         [](const std::string& s) { return s.find("removed 3") != std::string::npos; }),
            result.notices.end());

  // Exactly M-orthonormal and K-diagonal (required: 1e-10; Gram-Schmidt twice and a
  // symmetric eigen-solver leave ~1e-14).
  const double orthonormality = testing::orthonormality_error(mats.mass, set.shapes);
  const double diagonality = testing::k_diagonality_error(mats.stiffness, set.shapes);
  EXPECT_LT(orthonormality, 1e-10);
  EXPECT_LT(diagonality, 1e-10);
  RecordProperty("orthonormality_error", std::to_string(orthonormality));
  RecordProperty("k_diagonality_error", std::to_string(diagonality));

  // Normal modes keep their labels and frequencies (second method: the normal modes alone).
  NormalModeRequest normal_request;
  normal_request.count = 5;
  normal_request.rigid_count = 6;
  const NormalModes normal =
      compute_normal_modes(mats.stiffness, mats.mass, fe::free_dofs(model), normal_request);
  int normal_found = 0;
  for (const ModeInfo& mode : set.modes) {
    if (mode.kind != ModeKind::kNormal) continue;
    const int index = std::stoi(mode.label.substr(mode.label.find(' ') + 1)) - 1;
    // Ritz value of an exact eigenvector in the span: equal up to round-off of the
    // reduced problem (lambda_max / lambda ~ 1e8 conditioning, see the solver tests).
    EXPECT_NEAR(mode.frequency_hz / frequency_hz(normal.eigenvalues[index]), 1.0, 1e-9)
        << mode.label;
    ++normal_found;
  }
  EXPECT_EQ(normal_found, 5);
  // The static modes are there too, labelled by site, and ascending frequencies overall.
  const auto has = [&](const std::string& label) {
    return std::any_of(set.modes.begin(), set.modes.end(),
                       [&](const ModeInfo& m) { return m.label == label; });
  };
  EXPECT_TRUE(has("attachment uy at node 51"));
  for (std::size_t i = 1; i < set.modes.size(); ++i) {
    EXPECT_LE(set.modes[i - 1].frequency_hz, set.modes[i].frequency_hz);
  }
  // modal_stiffness = diag(Phi^T K Phi).
  const Eigen::VectorXd diag = (set.shapes.transpose() * (mats.stiffness * set.shapes)).diagonal();
  EXPECT_LT((diag - set.modal_stiffness).cwiseAbs().maxCoeff() / diag.maxCoeff(), 1e-12);

  // Every final vector is M-orthogonal to all rigid motion here (normal and inertia-relief
  // modes are by construction, constraint modes to the unheld motions, and the span's own
  // rigid directions were removed): the frame couplings vanish to round-off.
  const double coupling = std::max(set.invariants.translation_coupling.cwiseAbs().maxCoeff(),
                                   set.invariants.rotation_coupling.cwiseAbs().maxCoeff());
  EXPECT_LT(coupling, 1e-8 * std::sqrt(set.invariants.mass));
}

TEST(OrthonormaliseModes, NearlyDependentCandidateIsDroppedAndNamed) {
  const fe::FeModel model = testing::rod_model(20, true, {0});
  const fe::StructuralMatrices mats = fe::assemble(model);
  NormalModeRequest normal_request;
  normal_request.count = 2;
  const NormalModes normal =
      compute_normal_modes(mats.stiffness, mats.mass, fe::free_dofs(model), normal_request);
  ASSERT_EQ(normal.status, ModalStatus::kOk);
  // Third candidate: phi_1 + 2 phi_2 (exactly dependent), fourth: a tip attachment mode.
  const StaticModes attachment = compute_attachment_modes(
      mats.stiffness, mats.mass, rigid_body_modes(model), fe::free_dofs(model),
      {fe::FeModel::dof_index(20, Dof::kUz)});
  Eigen::MatrixXd candidates(model.dof_count(), 4);
  candidates << normal.shapes, normal.shapes.col(0) + 2.0 * normal.shapes.col(1), attachment.shapes;
  const std::vector<ModeInfo> info = {{ModeKind::kNormal, 0.0, "normal 1"},
                                      {ModeKind::kNormal, 0.0, "normal 2"},
                                      {ModeKind::kConstraint, 0.0, "combination"},
                                      {ModeKind::kAttachment, 0.0, "tip"}};
  const OrthonormalisedModes result = orthonormalise_modes(
      mats.stiffness, mats.mass, candidates, info, Eigen::MatrixXd(model.dof_count(), 0), 1e-8);
  ASSERT_EQ(result.mode_set.shapes.cols(), 3);
  ASSERT_EQ(result.notices.size(), 1u);
  EXPECT_NE(result.notices[0].find("dropped combination"), std::string::npos) << result.notices[0];
  EXPECT_EQ(result.mode_set.modes[0].label, "normal 1");
  EXPECT_EQ(result.mode_set.modes[1].label, "normal 2");
  EXPECT_EQ(result.mode_set.modes[2].label, "tip");
  EXPECT_EQ(result.mode_set.modes[2].kind, ModeKind::kAttachment);
}

TEST(OrthonormaliseModes, NonFiniteStiffnessGivesNoModeAndSaysWhy) {
  // The reduced eigenproblem is the one step that cannot converge, and only on non-finite
  // values: it returns an empty set with a notice (the caller's status "no mode left"),
  // never an abort.
  const fe::FeModel model = testing::rod_model(20, true, {0});
  const fe::StructuralMatrices mats = fe::assemble(model);
  NormalModeRequest normal_request;
  normal_request.count = 2;
  const NormalModes normal =
      compute_normal_modes(mats.stiffness, mats.mass, fe::free_dofs(model), normal_request);
  ASSERT_EQ(normal.status, ModalStatus::kOk);
  Eigen::SparseMatrix<double> broken = mats.stiffness;
  broken.coeffRef(7, 7) = std::numeric_limits<double>::quiet_NaN();
  const std::vector<ModeInfo> info = {{ModeKind::kNormal, 0.0, "normal 1"},
                                      {ModeKind::kNormal, 0.0, "normal 2"}};
  const OrthonormalisedModes result = orthonormalise_modes(
      broken, mats.mass, normal.shapes, info, Eigen::MatrixXd(model.dof_count(), 0), 1e-8);
  EXPECT_EQ(result.mode_set.shapes.cols(), 0);
  ASSERT_FALSE(result.notices.empty());
  EXPECT_NE(result.notices.back().find("did not converge"), std::string::npos) << result.notices.back();
}

TEST(OrthonormaliseModes, CraigBamptonReproducesTheFullModelsLowestFrequencies) {
  // Cantilever rod, 40 elements; interface: the 6 DOFs of the tip. Craig & Bampton 1968:
  // fixed-interface normal modes (tip held too) + the tip's 6 constraint modes.
  const fe::FeModel model = testing::rod_model(40, true, {0});
  const fe::StructuralMatrices mats = fe::assemble(model);
  const std::vector<int> free = fe::free_dofs(model);
  std::vector<int> tip;
  for (int d = 0; d < 6; ++d) tip.push_back(fe::FeModel::dof_index(40, static_cast<Dof>(d)));
  const std::vector<int> interior = set_difference(free, tip);
  const StaticModes constraint = compute_constraint_modes(mats.stiffness, mats.mass,
                                                          rigid_body_modes(model), free, tip);
  ASSERT_EQ(constraint.status, ModalStatus::kOk);

  // Reduced eigenvalues with `count` fixed-interface modes.
  const auto craig_bampton = [&](int count) {
    NormalModeRequest normal_request;
    normal_request.count = count;
    const NormalModes fixed_interface =
        compute_normal_modes(mats.stiffness, mats.mass, interior, normal_request);
    EXPECT_EQ(fixed_interface.status, ModalStatus::kOk);
    Eigen::MatrixXd candidates(model.dof_count(), count + 6);
    candidates << fixed_interface.shapes, constraint.shapes;
    const std::vector<ModeInfo> info(static_cast<std::size_t>(count + 6),
                                     {ModeKind::kNormal, 0.0, "cb"});
    const OrthonormalisedModes reduced = orthonormalise_modes(
        mats.stiffness, mats.mass, candidates, info, Eigen::MatrixXd(model.dof_count(), 0), 1e-8);
    EXPECT_EQ(reduced.mode_set.shapes.cols(), count + 6);
    return reduced.mode_set.modal_stiffness;
  };

  // Full model (tip free), dense.
  const Eigen::VectorXd full = testing::dense_eigenvalues(submatrix(mats.stiffness, free, free),
                                                          submatrix(mats.mass, free, free));
  const double lambda_max = full[full.size() - 1];
  const Eigen::VectorXd all = craig_bampton(static_cast<int>(interior.size()));
  const Eigen::VectorXd cb20 = craig_bampton(20);
  const Eigen::VectorXd cb40 = craig_bampton(40);
  for (int j = 0; j < 8; ++j) {
    // All interior modes: the span is the whole space, the reduced model is exact up to
    // round-off (~eps lambda_max / lambda_j, bound 100 x; measured <= 6e-9).
    EXPECT_NEAR(all[j] / full[j], 1.0, 100.0 * 2.2e-16 * lambda_max / full[j]) << "mode " << j;
    // 20 modes: Rayleigh-Ritz upper bound (round-off margin as above) and close (measured
    // 2.4e-7 for mode 1 up to 3.6e-4 for mode 8 at 472 Hz; bound 1e-3).
    EXPECT_GT(cb20[j] / full[j], 1.0 - 100.0 * 2.2e-16 * lambda_max / full[j]) << "mode " << j;
    EXPECT_LT(cb20[j] / full[j] - 1.0, 1e-3) << "mode " << j;
    // Convergence: 40 modes are at least 5 times closer for every one of the eight
    // (measured: 10 to 14 times).
    EXPECT_LT(cb40[j] / full[j] - 1.0, 0.2 * (cb20[j] / full[j] - 1.0)) << "mode " << j;
  }
}

}  // namespace
}  // namespace limber::modal
