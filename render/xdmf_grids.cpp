#include "xdmf_grids.h"

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

// A flexible body's mesh: quads then lines, as in its VTU.
BodyGrid flexible_body_grid(const BodyTrack& body) {
  const FlexibleMesh& mesh = body.mesh;
  BodyGrid grid;
  grid.points_B = mesh.nodes;
  grid.cells = static_cast<int>(mesh.quads.rows() + mesh.lines.rows());
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
    if (n == 3) grid.topology.push_back(xdmf::kTriangle);
    else if (n == 4) grid.topology.push_back(xdmf::kQuadrilateral);
    else grid.topology.insert(grid.topology.end(), {xdmf::kPolygon, n});
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

}  // namespace limber::render
