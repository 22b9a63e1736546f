// Mesh generators that add nodes and elements to a builder. All checks of the builder
// apply (property indices, orientation, degenerate quads); node ids must not collide
// with ids already in the builder.
#pragma once

#include <vector>

#include "fe/fe_model_builder.h"

namespace limber::fe {

struct StraightBeamMesh {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();         // [m]
  Eigen::Vector3d end = Eigen::Vector3d::UnitX();          // [m]
  int elements = 1;                                        // >= 1
  Eigen::Vector3d orientation = Eigen::Vector3d::UnitZ();  // local x-y plane vector
  int property = 0;                                        // beam property index
  int first_node_id = 1;  // ids run first_node_id .. first_node_id + elements
};

// Adds elements + 1 nodes evenly spaced from start to end; returns their indices in order.
// Throws InputError when elements < 1 (and as the builder does).
std::vector<int> add_straight_beam(FeModelBuilder& builder, const StraightBeamMesh& mesh,
                                   const SourceLocation& where = {});

struct RectangularPlateMesh {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d edge_x = Eigen::Vector3d::UnitX();  // first side, full length [m]
  Eigen::Vector3d edge_y = Eigen::Vector3d::UnitY();  // second side, full length [m]
  int elements_x = 1;                                 // nx >= 1
  int elements_y = 1;                                 // ny >= 1
  int property = 0;                                   // shell property index
  int first_node_id = 1;                              // ids row by row, x fastest
};

// Adds (nx+1)(ny+1) nodes and nx*ny quads; returns node indices, row-major (x fastest):
// node (i, j) at origin + edge_x i/nx + edge_y j/ny is entry j (nx+1) + i. Quads run
// counter-clockwise about edge_x × edge_y. Throws InputError when nx or ny < 1, or when
// the edges are parallel (through the builder's quad check).
std::vector<int> add_rectangular_plate(FeModelBuilder& builder, const RectangularPlateMesh& mesh,
                                       const SourceLocation& where = {});

}  // namespace limber::fe
