// Mesh generators (mesh_generators.h): node placement, ids, connectivity, orientation.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "fe/mesh_generators.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

using testing::input_error_of;

ShellProperty plate_property() {
  ShellProperty p;
  p.name = "plate";
  p.material = testing::paper_steel();
  p.thickness = 0.002;
  return p;
}

TEST(MeshGenerators, StraightBeamNodesAreEvenlySpaced) {
  FeModelBuilder builder;
  StraightBeamMesh mesh;
  mesh.start = {1.0, 2.0, 3.0};
  mesh.end = {1.0, 5.0, 7.0};  // length 5
  mesh.elements = 5;
  mesh.orientation = Eigen::Vector3d::UnitX();
  mesh.property = builder.add_beam_property(testing::paper_rod_property());
  mesh.first_node_id = 100;
  const std::vector<int> nodes = add_straight_beam(builder, mesh);
  const FeModel model = std::move(builder).build();

  // 6 nodes, 1 m apart (exact in binary to 1 ulp), ids 100..105, 5 elements in order.
  ASSERT_EQ(nodes.size(), 6u);
  ASSERT_EQ(model.beams.size(), 5u);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(model.node_ids[nodes[i]], 100 + i);
    const Eigen::Vector3d expected = mesh.start + i / 5.0 * (mesh.end - mesh.start);
    EXPECT_LT((model.node_positions[nodes[i]] - expected).norm(), 1e-15);
  }
  for (int e = 0; e < 5; ++e) {
    EXPECT_EQ(model.beams[e].nodes[0], nodes[e]);
    EXPECT_EQ(model.beams[e].nodes[1], nodes[e + 1]);
    EXPECT_EQ(model.beams[e].orientation, Eigen::Vector3d::UnitX());
  }
}

TEST(MeshGenerators, StraightBeamErrors) {
  FeModelBuilder builder;
  StraightBeamMesh mesh;
  mesh.property = builder.add_beam_property(testing::paper_rod_property());
  mesh.elements = 0;
  EXPECT_EQ(input_error_of([&] { add_straight_beam(builder, mesh); }),
            "straight beam mesh: expected at least 1 element, got 0");
  // Orientation along the axis is caught by the builder.
  mesh.elements = 2;
  mesh.orientation = Eigen::Vector3d::UnitX();
  EXPECT_NE(input_error_of([&] {
              add_straight_beam(builder, mesh);
            }).find("expected an orientation vector not parallel to the axis"),
            std::string::npos);
}

TEST(MeshGenerators, RectangularPlateGridAndOrientation) {
  FeModelBuilder builder;
  RectangularPlateMesh mesh;
  mesh.origin = {0.5, 0.0, -1.0};
  mesh.edge_x = {2.0, 0.0, 0.0};
  mesh.edge_y = {0.0, 0.0, 1.5};  // plate in the x-z plane, normal edge_x × edge_y = -y
  mesh.elements_x = 4;
  mesh.elements_y = 3;
  mesh.property = builder.add_shell_property(plate_property());
  mesh.first_node_id = 1;
  const std::vector<int> nodes = add_rectangular_plate(builder, mesh);
  const FeModel model = std::move(builder).build();

  // (4+1)(3+1) nodes row by row, x fastest; 12 quads.
  ASSERT_EQ(nodes.size(), 20u);
  ASSERT_EQ(model.shells.size(), 12u);
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 4; ++i) {
      const int node = nodes[j * 5 + i];
      EXPECT_EQ(model.node_ids[node], 1 + j * 5 + i);
      const Eigen::Vector3d expected =
          mesh.origin + mesh.edge_x * (i / 4.0) + mesh.edge_y * (j / 3.0);
      EXPECT_LT((model.node_positions[node] - expected).norm(), 1e-15);
    }
  }

  // Every quad is counter-clockwise about edge_x × edge_y and has area 0.5 x 0.5 m^2.
  const Eigen::Vector3d normal = mesh.edge_x.cross(mesh.edge_y).normalized();
  for (const ShellElement& quad : model.shells) {
    const auto p = [&](int k) { return model.node_positions[quad.nodes[k]]; };
    const Eigen::Vector3d diagonal_cross = (p(2) - p(0)).cross(p(3) - p(1));
    EXPECT_NEAR(0.5 * diagonal_cross.dot(normal), 0.25, 1e-14);
  }
  // First quad: nodes (0,0), (1,0), (1,1), (0,1).
  EXPECT_EQ(model.shells[0].nodes, (std::array<int, 4>{nodes[0], nodes[1], nodes[6], nodes[5]}));
}

TEST(MeshGenerators, RectangularPlateErrors) {
  FeModelBuilder builder;
  RectangularPlateMesh mesh;
  mesh.property = builder.add_shell_property(plate_property());
  mesh.elements_y = 0;
  EXPECT_EQ(input_error_of([&] { add_rectangular_plate(builder, mesh); }),
            "rectangular plate mesh: expected at least 1 x 1 elements, got 1 x 0");
  // Parallel edges give zero-area quads, caught by the builder.
  mesh.elements_y = 1;
  mesh.edge_y = {2.0, 0.0, 0.0};
  EXPECT_NE(input_error_of([&] {
              add_rectangular_plate(builder, mesh);
            }).find("expected a positive area"),
            std::string::npos);
}

}  // namespace
}  // namespace limber::fe
