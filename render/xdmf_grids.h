// The grid of each body in the ParaView scene (render/xdmf_export.h): its points in the body
// frame and its cells as an XDMF Mixed topology, the same points and cells, in the same order,
// as the body's VTU (render/vtk_export.h).
//
// Flexible bodies: the mesh nodes X0 [m], then the beams' swept surface points when the file
// has sections (render/beam_solids.h); the quads, the lines (beams), then the swept surfaces'
// cells. Rigid bodies: the surfaces of their primitives (VTK's cube, 32-sided cylinder and
// sphere sources) placed by their offsets, merged without merging points.
#pragma once

#include "results_reader.h"

#include <Eigen/Core>

#include <vector>

namespace limber::render {

struct BodyGrid {
  RowMatrix3d points_B;           // np x 3, body frame [m]
  std::vector<int> topology;      // XDMF Mixed (render/xdmf_layout.h), nt entries
  int cells = 0;                  // nc
  Eigen::VectorXd beam_radius;    // nc [m]: section radius on lines, 0 on surfaces
  std::vector<int> solid_node;    // the mesh node each swept-surface point follows (after the nodes)
  std::vector<int> solid_beam;    // the line of each swept-surface cell (after the lines)
};

// Per-node rows of a flexible body's grid extended to its swept-surface points: each takes its
// node's row.
RowMatrix3d at_grid_points(const BodyGrid& grid, const RowMatrix3d& per_node);

BodyGrid body_grid(const BodyTrack& body);

}  // namespace limber::render
