#include "xdmf_grids.h"

#include "beam_solids.h"
#include "core/error.h"
#include "primitive_source.h"
#include "xdmf_layout.h"

#include <vtkAppendPolyData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <cmath>

namespace limber::render {
namespace {

// The XDMF Mixed cell of a polygon of n points.
void push_polygon(std::vector<int>& topology, int n) {
  if (n == 3) topology.push_back(xdmf::kTriangle);
  else if (n == 4) topology.push_back(xdmf::kQuadrilateral);
  else topology.insert(topology.end(), {xdmf::kPolygon, n});
}

// A flexible body's mesh: quads, lines, then the beams' swept surfaces, as in its VTU.
BodyGrid flexible_body_grid(const BodyTrack& body) {
  const FlexibleMesh& mesh = body.mesh;
  const BeamSolids solids = beam_solids(mesh);
  BodyGrid grid;
  const Eigen::Index nn = mesh.nodes.rows();
  grid.points_B.resize(nn + solids.points_B.rows(), 3);
  grid.points_B.topRows(nn) = mesh.nodes;
  grid.points_B.bottomRows(solids.points_B.rows()) = solids.points_B;
  grid.solid_node = solids.node;
  grid.solid_beam = solids.beam;
  grid.cells = static_cast<int>(mesh.quads.rows() + mesh.lines.rows()) + solids.cell_count();
  grid.beam_radius = Eigen::VectorXd::Zero(grid.cells);
  grid.topology.reserve(5 * mesh.quads.rows() + 4 * mesh.lines.rows());
  for (Eigen::Index e = 0; e < mesh.quads.rows(); ++e) {
    grid.topology.push_back(xdmf::kQuadrilateral);
    for (int k = 0; k < 4; ++k) grid.topology.push_back(mesh.quads(e, k));
  }
  for (Eigen::Index e = 0; e < mesh.lines.rows(); ++e) {
    grid.topology.insert(grid.topology.end(), {xdmf::kPolyline, 2, mesh.lines(e, 0), mesh.lines(e, 1)});
    grid.beam_radius(mesh.quads.rows() + e) = mesh.beam_radius;
  }
  for (int c = 0; c < solids.cell_count(); ++c) {
    push_polygon(grid.topology, solids.cell_offsets[c + 1] - solids.cell_offsets[c]);
    for (int i = solids.cell_offsets[c]; i < solids.cell_offsets[c + 1]; ++i) {
      grid.topology.push_back(static_cast<int>(nn) + solids.connectivity[i]);
    }
  }
  return grid;
}

// A rigid body's primitives in the body frame, merged in shape order (points not merged).
BodyGrid rigid_body_grid(const BodyTrack& body) {
  BodyGrid grid;
  grid.points_B.resize(0, 3);
  grid.beam_radius.resize(0);
  if (body.shapes.empty()) return grid;
  vtkNew<vtkAppendPolyData> append;
  for (const Shape& shape : body.shapes) {
    vtkNew<vtkTransform> transform;
    transform->PostMultiply();
    auto source = primitive_source(shape, transform);
    const Eigen::AngleAxisd rotation(shape.offset_orientation);
    transform->RotateWXYZ(rotation.angle() * 180.0 / M_PI, rotation.axis().data());
    transform->Translate(shape.offset_position.data());
    vtkNew<vtkTransformPolyDataFilter> placed;
    placed->SetInputConnection(source->GetOutputPort());
    placed->SetTransform(transform);
    placed->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    append->AddInputConnection(placed->GetOutputPort());
  }
  append->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  append->Update();
  vtkPolyData* surface = append->GetOutput();
  grid.points_B.resize(surface->GetNumberOfPoints(), 3);
  for (vtkIdType k = 0; k < surface->GetNumberOfPoints(); ++k) {
    surface->GetPoint(k, &grid.points_B(k, 0));
  }
  // The sources make polygons only (quads, triangles, the cylinder's 32-gon caps).
  LIMBER_DEMAND(surface->GetNumberOfVerts() == 0 && surface->GetNumberOfLines() == 0 &&
                surface->GetNumberOfStrips() == 0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c) {
    surface->GetCellPoints(c, ids);
    const auto n = static_cast<int>(ids->GetNumberOfIds());
    push_polygon(grid.topology, n);
    for (int k = 0; k < n; ++k) grid.topology.push_back(static_cast<int>(ids->GetId(k)));
  }
  grid.cells = static_cast<int>(surface->GetNumberOfCells());
  grid.beam_radius = Eigen::VectorXd::Zero(grid.cells);
  return grid;
}

}  // namespace

BodyGrid body_grid(const BodyTrack& body) {
  return body.flexible ? flexible_body_grid(body) : rigid_body_grid(body);
}

RowMatrix3d at_grid_points(const BodyGrid& grid, const RowMatrix3d& per_node) {
  const Eigen::Index nn = per_node.rows();
  RowMatrix3d out(nn + static_cast<Eigen::Index>(grid.solid_node.size()), 3);
  out.topRows(nn) = per_node;
  for (std::size_t k = 0; k < grid.solid_node.size(); ++k) {
    out.row(nn + static_cast<Eigen::Index>(k)) = per_node.row(grid.solid_node[k]);
  }
  return out;
}

}  // namespace limber::render
