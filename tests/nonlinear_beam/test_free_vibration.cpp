// Small-amplitude free vibration of the co-rotational structure: the tangent stiffness and the
// co-rotational consistent mass (beam_structure.h) linearised about a state give the natural
// frequencies of limber's linear modal analysis (modal/normal_modes.h on fe::assemble) -- at the
// undeformed state, and after any rigid rotation of the whole clamped beam (objectivity of both
// matrices).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iostream>

#include "fe/assembly.h"
#include "fe/beam_section.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "modal/normal_modes.h"
#include "nonlinear_beam/beam_structure.h"
#include "nonlinear_beam/rotation.h"

namespace limber::nonlinear_beam {
namespace {

constexpr int kModes = 8;

// A 1 m steel cantilever, 20 Timoshenko elements, unequal section (distinct frequencies in the
// two bending planes), axis and orientation along no global axis, clamped at its first node.
struct Model {
  fe::FeModel model;
  int root = 0;
};

Model steel_cantilever() {
  fe::FeModelBuilder builder;
  fe::BeamProperty property;
  property.name = "bar";
  property.material = {"steel", 210e9, 0.3, 7850.0};
  property.section = fe::rectangle_section(0.01, 0.02);
  property.timoshenko = true;
  builder.add_beam_property(property);
  fe::StraightBeamMesh mesh;
  mesh.start = Eigen::Vector3d(0.1, -0.2, 0.3);
  mesh.end = mesh.start + Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
  mesh.orientation = Eigen::Vector3d(0.2, -0.4, 1.0);
  mesh.elements = 20;
  const std::vector<int> nodes = fe::add_straight_beam(builder, mesh);
  for (int d = 0; d < fe::kDofsPerNode; ++d) builder.fix(nodes.front(), static_cast<fe::Dof>(d));
  Model out;
  out.model = std::move(builder).build();
  out.root = nodes.front();
  return out;
}

Eigen::VectorXd frequencies(const fe::SparseMatrix& k, const fe::SparseMatrix& m,
                            const std::vector<int>& free) {
  modal::NormalModeRequest request;
  request.count = kModes;
  const modal::NormalModes modes = modal::compute_normal_modes(k, m, free, request);
  EXPECT_EQ(modes.status, modal::ModalStatus::kOk) << modes.message;
  return modes.eigenvalues.cwiseSqrt() / (2.0 * 3.14159265358979323846);
}

// Frequencies to 1e-6 relative (the brief's figure): the tangent at the undeformed state equals
// the linear stiffness to ~1e-11 and the mass is the same consistent mass, so only the
// eigen-solver's convergence (ARPACK to machine precision) separates the two; a wrong frame in
// the mass or a missing rotation of the tangent would move them by O(1).
TEST(CorotationalVibration, UndeformedAndRigidlyRotatedStatesHaveTheLinearFrequencies) {
  const Model m = steel_cantilever();
  const std::vector<int> free = fe::free_dofs(m.model);
  const fe::StructuralMatrices linear = fe::assemble(m.model);
  const Eigen::VectorXd f_linear = frequencies(linear.stiffness, linear.mass, free);

  const BeamStructure structure = build_beam_structure(m.model);

  // Undeformed state.
  const BeamState reference = reference_state(structure);
  const Eigen::VectorXd f_reference = frequencies(
      internal_force_and_tangent(structure, reference).tangent, corotational_mass(structure, reference),
      free);

  // The whole beam rotated rigidly by ~1.9 rad about its clamped root (the clamp holds all six
  // DOFs of the root node, so the boundary conditions rotate with it).
  const Eigen::Matrix3d rotation = exp_so3(Eigen::Vector3d(0.9, -1.1, 1.3));
  const Eigen::Vector3d root = structure.reference_positions[m.root];
  BeamState rotated = reference;
  for (int i = 0; i < structure.node_count(); ++i) {
    rotated.positions[i] = root + rotation * (structure.reference_positions[i] - root);
    rotated.rotations[i] = Eigen::Quaterniond(rotation);
  }
  const Eigen::VectorXd f_rotated = frequencies(
      internal_force_and_tangent(structure, rotated).tangent, corotational_mass(structure, rotated),
      free);

  for (int i = 0; i < kModes; ++i) {
    std::cout << "mode " << i + 1 << ": linear " << f_linear(i) << " Hz, co-rotational "
              << f_reference(i) << " Hz (rel " << f_reference(i) / f_linear(i) - 1.0
              << "), rotated " << f_rotated(i) << " Hz (rel " << f_rotated(i) / f_linear(i) - 1.0
              << ")\n";
    EXPECT_NEAR(f_reference(i) / f_linear(i), 1.0, 1e-6) << "mode " << i + 1;
    EXPECT_NEAR(f_rotated(i) / f_linear(i), 1.0, 1e-6) << "mode " << i + 1;
  }
}

}  // namespace
}  // namespace limber::nonlinear_beam
