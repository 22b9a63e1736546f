// Beams drawn as solids: each beam element of a flexible body swept along its axis with its
// cross-section outline (results/beam_sections.h), as a polygon surface in the body frame.
// A pure function of the reference mesh, for the scene (scene.cpp), the VTU/PVD export
// (vtk_export.cpp) and any other writer (e.g. an XDMF description).
//
// Beam e from node a to node b: local x = (X_b − X_a)/|X_b − X_a|, y = the file's y axis, z =
// x × y. Its outline point (py, pz) gives one surface point at each end, X_end + py y + pz z.
// Cells: one quad per outline edge on the sides (outward normals) and end caps facing away
// from the beam (a solid outline's polygon cut into triangles by ear clipping, a hollow one's
// ring into quads between the inner and outer polygons).
//
// Deformation: every surface point follows the node at its end, x = x_node + R_WB (P_B −
// X_node,B): it moves with the node's elastic translation (results.h5 stores translations
// only), and the section is NOT turned by the node's small elastic rotation: it keeps its
// undeformed attitude in the body frame. Neighbouring beams' end faces at a shared node stay
// together; a bent beam's sections lean off the normal of its deformed axis by the node's
// rotation (slope), which the deformation scale magnifies as it magnifies the bending.
#pragma once

#include "results_reader.h"

#include <array>
#include <vector>

namespace limber::render {

struct BeamSolids {
  RowMatrix3d points_B;    // np x 3, undeformed surface points, body frame [m]
  std::vector<int> node;   // np: the mesh node each point follows
  std::vector<int> cell_offsets{0};  // nc + 1: cell c is connectivity[cell_offsets[c] .. c + 1)
  std::vector<int> connectivity;     // point indices, counter-clockwise about the outward normal
  std::vector<int> beam;             // nc: the beam (mesh line index) of each cell

  int cell_count() const { return static_cast<int>(beam.size()); }
};

// The swept surface of every line of `mesh` whose sections are present; empty when
// mesh.beam_sections is empty (older files: draw tubes of beam_radius instead).
// Precondition (LIMBER_DEMAND): sections consistent with the mesh (read_beam_sections checks
// them); beams of non-zero length with y axes normal to them (to 1e-6).
BeamSolids beam_solids(const FlexibleMesh& mesh);

// Triangles (index triples into `polygon`) covering a simple polygon given counter-clockwise,
// by ear clipping (Eberly, "Triangulation by Ear Clipping", Geometric Tools, 2002): n − 2
// counter-clockwise triangles, fewer when straight (collinear) corners are dropped.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector2d>& polygon);

}  // namespace limber::render
