#include "fe/mesh_generators.h"

#include <fmt/format.h>

namespace limber::fe {

std::vector<int> add_straight_beam(FeModelBuilder& builder, const StraightBeamMesh& mesh,
                                   const SourceLocation& where) {
  if (mesh.elements < 1) {
    throw InputError(
        fmt::format("straight beam mesh: expected at least 1 element, got {}", mesh.elements),
        where);
  }

  // Nodes evenly spaced along the segment.
  std::vector<int> nodes;
  nodes.reserve(mesh.elements + 1);
  for (int i = 0; i <= mesh.elements; ++i) {
    const double s = static_cast<double>(i) / mesh.elements;
    nodes.push_back(
        builder.add_node(mesh.first_node_id + i, (1.0 - s) * mesh.start + s * mesh.end, where));
  }

  // One element between consecutive nodes.
  for (int i = 0; i < mesh.elements; ++i) {
    builder.add_beam({{nodes[i], nodes[i + 1]}, mesh.orientation, mesh.property}, where);
  }
  return nodes;
}

std::vector<int> add_rectangular_plate(FeModelBuilder& builder, const RectangularPlateMesh& mesh,
                                       const SourceLocation& where) {
  const int nx = mesh.elements_x;
  const int ny = mesh.elements_y;
  if (nx < 1 || ny < 1) {
    throw InputError(fmt::format("rectangular plate mesh: expected at least 1 x 1 elements, "
                                 "got {} x {}",
                                 nx, ny),
                     where);
  }

  // Grid nodes, x fastest.
  std::vector<int> nodes;
  nodes.reserve(static_cast<std::size_t>(nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const Eigen::Vector3d position = mesh.origin + mesh.edge_x * (static_cast<double>(i) / nx) +
                                       mesh.edge_y * (static_cast<double>(j) / ny);
      nodes.push_back(builder.add_node(mesh.first_node_id + j * (nx + 1) + i, position, where));
    }
  }

  // Quads counter-clockwise about edge_x × edge_y.
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int n00 = nodes[j * (nx + 1) + i];
      const int n10 = nodes[j * (nx + 1) + i + 1];
      const int n11 = nodes[(j + 1) * (nx + 1) + i + 1];
      const int n01 = nodes[(j + 1) * (nx + 1) + i];
      builder.add_shell({{n00, n10, n11, n01}, mesh.property}, where);
    }
  }
  return nodes;
}

}  // namespace limber::fe
