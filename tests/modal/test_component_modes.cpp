// compute_component_modes: request validation (InputError with expected/got) and the
// whole pipeline on the seed paper's free rod.
#include <string>

#include <gtest/gtest.h>

#include "modal/component_modes.h"
#include "modal_test_support.h"

namespace limber::modal {
namespace {

using fe::Dof;

std::string input_error_of(const fe::FeModel& model, const ModeRequest& request) {
  try {
    compute_component_modes(model, request);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no InputError";
}

TEST(ComponentModes, RejectsImpossibleRequests) {
  const fe::FeModel model = testing::rod_model(4, true, {0});  // 24 free DOFs
  ModeRequest nothing;
  EXPECT_NE(input_error_of(model, nothing).find("expected normal modes"), std::string::npos);

  ModeRequest too_many;
  too_many.normal_count = 25;
  const std::string many = input_error_of(model, too_many);
  EXPECT_NE(many.find("expected at most 24 normal modes"), std::string::npos) << many;
  EXPECT_NE(many.find("got 25"), std::string::npos) << many;

  ModeRequest on_fixed;
  on_fixed.constraint_sites = {{0, {Dof::kUz}}};
  const std::string fixed = input_error_of(model, on_fixed);
  EXPECT_NE(fixed.find("expected a free DOF, got uz at node 1"), std::string::npos) << fixed;

  ModeRequest unknown_node;
  unknown_node.attachment_sites = {{7, {Dof::kUx}}};
  EXPECT_NE(input_error_of(model, unknown_node).find("expected a node index in [0, 5), got 7"),
            std::string::npos);

  ModeRequest twice;
  twice.attachment_sites = {{4, {Dof::kUx, Dof::kUx}}};
  EXPECT_NE(input_error_of(model, twice).find("expected each DOF once"), std::string::npos);

  ModeRequest no_dofs;
  no_dofs.constraint_sites = {{4, {}}};
  EXPECT_NE(input_error_of(model, no_dofs).find("expected at least one DOF"), std::string::npos);

  ModeRequest bad_tolerance;
  bad_tolerance.normal_count = 2;
  bad_tolerance.dependency_tolerance = 0.0;
  EXPECT_NE(input_error_of(model, bad_tolerance).find("dependency tolerance"), std::string::npos);

  // A free model: 30 DOFs, 6 rigid modes, at most 24 elastic ones.
  const fe::FeModel free_model = testing::rod_model(4, true, {});
  ModeRequest free_too_many;
  free_too_many.normal_count = 25;
  EXPECT_NE(input_error_of(free_model, free_too_many).find("6 rigid-body modes"), std::string::npos);
}

TEST(ComponentModes, FreeRodNormalAndConstraintModesEndToEnd) {
  // Seed paper example 1: the rod with 5 normal modes and X/Z constraint modes at both
  // joints (nodes 0 and 100), as chosen in the paper's procedure.
  const fe::FeModel model = testing::rod_model(100, true, {});
  ModeRequest request;
  request.normal_count = 5;
  request.constraint_sites = {{0, {Dof::kUx, Dof::kUz}}, {100, {Dof::kUx, Dof::kUz}}};
  const ModalResult result = compute_component_modes(model, request);
  ASSERT_EQ(result.status, ModalStatus::kOk) << result.message;
  const ModeSet& set = result.mode_set;

  // Six rigid modes set aside, at near-zero frequency.
  ASSERT_EQ(set.rigid_modes.size(), 6u);
  for (const ModeInfo& rigid : set.rigid_modes) {
    EXPECT_EQ(rigid.kind, ModeKind::kRigid);
    EXPECT_LT(std::abs(rigid.frequency_hz), 0.5);  // first elastic mode: 52 Hz
  }
  // 5 normal + 4 constraint - 3 rigid directions (z translation, y rotation, x translation).
  ASSERT_EQ(set.shapes.cols(), 6);
  ASSERT_EQ(set.modes.size(), 6u);
  int constraint_count = 0;
  for (const ModeInfo& mode : set.modes) constraint_count += mode.kind == ModeKind::kConstraint;
  EXPECT_EQ(constraint_count, 1);  // the axial stretch between the two ends
  const fe::StructuralMatrices mats = fe::assemble(model);
  // Required bounds 1e-10 (round-off ~1e-14).
  EXPECT_LT(testing::orthonormality_error(mats.mass, set.shapes), 1e-10);
  EXPECT_LT(testing::k_diagonality_error(mats.stiffness, set.shapes), 1e-10);
  // The stretch mode's equivalent frequency is the axial free-free one (2571 Hz: the
  // static two-end stretch, linear in x, orthogonalised against rigid motion) to within
  // the Rayleigh-quotient error of a linear shape vs cos(pi x / L): sqrt(12)/pi = +10.3%.
  for (const ModeInfo& mode : set.modes) {
    if (mode.kind != ModeKind::kConstraint) continue;
    const double axial = 0.5 * std::sqrt(206.8e9 / 7820.0);
    EXPECT_NEAR(mode.frequency_hz / axial, std::sqrt(12.0) / std::numbers::pi, 1e-3);
  }
  // Invariants are filled for the final set.
  EXPECT_EQ(set.invariants.translation_coupling.cols(), 6);
  EXPECT_NEAR(set.invariants.mass, 7820.0 * 2e-4, 1e-12);
}

}  // namespace
}  // namespace limber::modal
