// Global assembly (assembly.h) against a dense scatter of the element matrices, point masses
// through the rigid-body mass matrix, free_dofs and restrict_to.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "fe/assembly.h"
#include "fe/beam_element.h"
#include "fe/mesh_generators.h"
#include "fe/shell_element.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

using Eigen::MatrixXd;

// A beam frame (3 elements, bent) sharing node 3 with a 2 x 1 plate, plus a point mass.
FeModel mixed_model() {
  FeModelBuilder b;
  const int beam = b.add_beam_property(testing::paper_rod_property(/*timoshenko=*/true));
  ShellProperty plate;
  plate.name = "plate";
  plate.material = testing::paper_steel();
  plate.thickness = 0.003;
  const int shell = b.add_shell_property(plate);
  RectangularPlateMesh mesh;
  mesh.edge_x = {0.4, 0.0, 0.0};
  mesh.edge_y = {0.0, 0.3, 0.0};
  mesh.elements_x = 2;
  mesh.elements_y = 1;
  mesh.property = shell;
  mesh.first_node_id = 1;
  const std::vector<int> plate_nodes = add_rectangular_plate(b, mesh);
  const int n1 = b.add_node(11, {0.4, 0.3, 0.5});
  const int n2 = b.add_node(12, {0.9, 0.1, 0.6});
  b.add_beam({{plate_nodes[5], n1}, Eigen::Vector3d::UnitX(), beam});
  b.add_beam({{n1, n2}, Eigen::Vector3d::UnitZ(), beam});
  b.add_beam({{n2, plate_nodes[0]}, Eigen::Vector3d::UnitZ(), beam});
  PointMass m;
  m.node = n2;
  m.mass = 1.5;
  m.inertia = Eigen::Vector3d(0.01, 0.02, 0.03).asDiagonal();
  m.inertia(0, 1) = m.inertia(1, 0) = 0.004;
  b.add_point_mass(m);
  b.fix(plate_nodes[0], Dof::kUz);
  b.fix(n1, Dof::kRx);
  b.fix(n1, Dof::kUx);
  return std::move(b).build();
}

// Dense reference: element matrices scattered one entry at a time.
void dense_assembly(const FeModel& model, MatrixXd& k, MatrixXd& m) {
  k = MatrixXd::Zero(model.dof_count(), model.dof_count());
  m = k;
  const auto scatter = [&](const auto& nodes, const auto& ke, const auto& me) {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      for (std::size_t j = 0; j < nodes.size(); ++j) {
        k.block<6, 6>(6 * nodes[i], 6 * nodes[j]) += ke.template block<6, 6>(6 * i, 6 * j);
        m.block<6, 6>(6 * nodes[i], 6 * nodes[j]) += me.template block<6, 6>(6 * i, 6 * j);
      }
    }
  };
  for (const BeamElement& e : model.beams) {
    const BeamElementMatrices em =
        beam_element_matrices(model.node_positions[e.nodes[0]], model.node_positions[e.nodes[1]],
                              e.orientation, model.beam_properties[e.property]);
    scatter(e.nodes, em.stiffness, em.mass);
  }
  for (const ShellElement& e : model.shells) {
    std::array<Eigen::Vector3d, 4> corners;
    for (int i = 0; i < 4; ++i) corners[i] = model.node_positions[e.nodes[i]];
    const ShellElementMatrices em =
        shell_element_matrices(corners, model.shell_properties[e.property]);
    scatter(e.nodes, em.stiffness, em.mass);
  }
  for (const PointMass& p : model.point_masses) {
    m.block<3, 3>(6 * p.node, 6 * p.node) += p.mass * Eigen::Matrix3d::Identity();
    m.block<3, 3>(6 * p.node + 3, 6 * p.node + 3) += p.inertia;
  }
}

TEST(Assembly, MatchesDenseScatterOfElementMatrices) {
  // Same sums in a different order: round-off only (1e-13 of the largest entry).
  const FeModel model = mixed_model();
  const StructuralMatrices s = assemble(model);
  MatrixXd k, m;
  dense_assembly(model, k, m);
  ASSERT_EQ(s.stiffness.rows(), model.dof_count());
  EXPECT_TRUE(s.stiffness.isCompressed());
  EXPECT_TRUE(s.mass.isCompressed());
  EXPECT_LT((MatrixXd(s.stiffness) - k).cwiseAbs().maxCoeff(), 1e-13 * k.cwiseAbs().maxCoeff());
  EXPECT_LT((MatrixXd(s.mass) - m).cwiseAbs().maxCoeff(), 1e-13 * m.cwiseAbs().maxCoeff());

  // Row indices strictly ascending within every column (required by sparse solvers).
  for (int j = 0; j < s.stiffness.outerSize(); ++j) {
    int previous = -1;
    for (SparseMatrix::InnerIterator it(s.stiffness, j); it; ++it) {
      EXPECT_GT(it.row(), previous);
      previous = static_cast<int>(it.row());
    }
  }
}

TEST(Assembly, PointMassEntersTheRigidBodyMass) {
  // Psi_t^T M Psi_t = (sum of element masses + point mass) I for the translations: the beam
  // and shell consistent masses reproduce their rho A L and rho t area exactly (round-off,
  // 1e-12); the shell's is its own element's business, so it is taken from its matrix.
  const FeModel model = mixed_model();
  const StructuralMatrices s = assemble(model);
  MatrixXd psi = MatrixXd::Zero(model.dof_count(), 3);
  for (int n = 0; n < model.node_count(); ++n) psi.block<3, 3>(6 * n, 0).setIdentity();
  const MatrixXd rigid = psi.transpose() * (s.mass * psi);
  double expected = 1.5;
  for (const BeamElement& e : model.beams) {
    const BeamProperty& p = model.beam_properties[e.property];
    expected += p.material.density * p.section.area *
                (model.node_positions[e.nodes[1]] - model.node_positions[e.nodes[0]]).norm();
  }
  const ShellProperty& plate = model.shell_properties[0];
  expected += plate.material.density * plate.thickness * 0.4 * 0.3;
  EXPECT_LT((rigid - expected * Eigen::Matrix3d::Identity()).norm(), 1e-12 * expected);
}

TEST(Assembly, FreeDofsAndRestriction) {
  const FeModel model = mixed_model();
  const std::vector<int> dofs = free_dofs(model);
  ASSERT_EQ(static_cast<int>(dofs.size()), model.dof_count() - 3);
  EXPECT_TRUE(std::is_sorted(dofs.begin(), dofs.end()));
  for (const FixedDof& f : model.fixed_dofs) {
    EXPECT_FALSE(std::binary_search(dofs.begin(), dofs.end(), FeModel::dof_index(f.node, f.dof)));
  }

  // restrict_to equals the dense submatrix, also for an unsorted selection (exact copy).
  const StructuralMatrices s = assemble(model);
  const MatrixXd k = MatrixXd(s.stiffness);
  const std::vector<int> picks{40, 3, 17, 0, 45};
  for (const std::vector<int>* selection : {&dofs, &picks}) {
    const SparseMatrix sub = restrict_to(s.stiffness, *selection);
    ASSERT_EQ(sub.rows(), static_cast<Eigen::Index>(selection->size()));
    const MatrixXd dense = MatrixXd(sub);
    for (std::size_t i = 0; i < selection->size(); ++i) {
      for (std::size_t j = 0; j < selection->size(); ++j) {
        EXPECT_EQ(dense(i, j), k((*selection)[i], (*selection)[j]));
      }
    }
  }
}

}  // namespace
}  // namespace limber::fe
