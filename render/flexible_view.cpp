#include "flexible_view.h"

#include <vtkActor.h>
#include <vtkAlgorithmOutput.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTubeFilter.h>

#include <limits>

namespace limber::render {
namespace {

// A per-cell array of `count` values, NaN until the first update.
vtkSmartPointer<vtkDoubleArray> cell_values(Eigen::Index count) {
  auto values = vtkSmartPointer<vtkDoubleArray>::New();
  values->SetName("stress_MPa");
  values->SetNumberOfTuples(static_cast<vtkIdType>(count));
  values->Fill(std::numeric_limits<double>::quiet_NaN());
  return values;
}

// An actor coloured through the shared lookup table, from data or a pipeline output.
vtkSmartPointer<vtkActor> add_colored_actor(vtkRenderer* renderer, const FlexibleColoring& coloring,
                                            vtkPolyData* data, vtkAlgorithmOutput* port) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  if (data != nullptr) mapper->SetInputData(data);
  if (port != nullptr) mapper->SetInputConnection(port);
  mapper->SetLookupTable(coloring.lut);
  mapper->SetScalarRange(0.0, coloring.range_max);
  // Stresses are per element (cell data, which the tube filter passes on); |u| per node.
  if (coloring.by_stress) mapper->SetScalarModeToUseCellData();
  else mapper->SetScalarModeToUsePointData();
  mapper->ScalarVisibilityOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.2);
  renderer->AddActor(actor);
  return actor;
}

// The beams' swept surface: its own points, moved in update() with the nodes they follow.
void add_solids(vtkRenderer* renderer, const FlexibleColoring& coloring, FlexibleView& view) {
  const BeamSolids& solids = view.solid_mesh;
  const auto np = static_cast<vtkIdType>(solids.points_B.rows());
  view.solid_offset_B = solids.points_B;
  for (Eigen::Index k = 0; k < solids.points_B.rows(); ++k) {
    view.solid_offset_B.row(k) -= view.body->mesh.nodes.row(solids.node[static_cast<std::size_t>(k)]);
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(np);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  std::vector<vtkIdType> ids;
  for (int c = 0; c < solids.cell_count(); ++c) {
    ids.assign(solids.connectivity.begin() + solids.cell_offsets[c],
               solids.connectivity.begin() + solids.cell_offsets[c + 1]);
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  view.solids = vtkSmartPointer<vtkPolyData>::New();
  view.solids->SetPoints(points);
  view.solids->SetPolys(cells);
  view.solid_magnitude = vtkSmartPointer<vtkDoubleArray>::New();
  view.solid_magnitude->SetName("displacement_magnitude");
  view.solid_magnitude->SetNumberOfTuples(np);
  view.solids->GetPointData()->SetScalars(view.solid_magnitude);
  if (coloring.by_stress) {
    view.solid_stress = cell_values(solids.cell_count());
    view.solids->GetCellData()->SetScalars(view.solid_stress);
  }
  add_colored_actor(renderer, coloring, view.solids, nullptr);
}

}  // namespace

FlexibleView add_flexible_view(vtkRenderer* renderer, const BodyTrack& body, std::size_t index,
                               const StressTrack* stress, const FlexibleColoring& coloring) {
  FlexibleView view;
  view.body = &body;
  view.index = index;
  view.stress = stress;
  const auto nn = static_cast<vtkIdType>(body.mesh.nodes.rows());
  view.points = vtkSmartPointer<vtkPoints>::New();
  view.points->SetDataTypeToDouble();
  view.points->SetNumberOfPoints(nn);
  view.magnitude = vtkSmartPointer<vtkDoubleArray>::New();
  view.magnitude->SetName("displacement_magnitude");
  view.magnitude->SetNumberOfTuples(nn);

  // Shells: one surface of quads, coloured by |u|.
  if (body.mesh.quads.rows() > 0) {
    auto quads = vtkSmartPointer<vtkCellArray>::New();
    for (Eigen::Index e = 0; e < body.mesh.quads.rows(); ++e) {
      const vtkIdType ids[4] = {body.mesh.quads(e, 0), body.mesh.quads(e, 1),
                                body.mesh.quads(e, 2), body.mesh.quads(e, 3)};
      quads->InsertNextCell(4, ids);
    }
    view.surface = vtkSmartPointer<vtkPolyData>::New();
    view.surface->SetPoints(view.points);
    view.surface->SetPolys(quads);
    view.surface->GetPointData()->SetScalars(view.magnitude);
    if (coloring.by_stress) {
      view.quad_stress = cell_values(body.mesh.quads.rows());
      view.surface->GetCellData()->SetScalars(view.quad_stress);
    }
    add_colored_actor(renderer, coloring, view.surface, nullptr);
  }

  // Beams: swept sections where the file has them (beam_solids.h), else lines swept into
  // tubes of the mesh's beam radius (plain thick lines without one).
  view.solid_mesh = beam_solids(body.mesh);
  if (view.solid_mesh.cell_count() > 0) {
    add_solids(renderer, coloring, view);
  } else if (body.mesh.lines.rows() > 0) {
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (Eigen::Index e = 0; e < body.mesh.lines.rows(); ++e) {
      const vtkIdType ids[2] = {body.mesh.lines(e, 0), body.mesh.lines(e, 1)};
      lines->InsertNextCell(2, ids);
    }
    view.beams = vtkSmartPointer<vtkPolyData>::New();
    view.beams->SetPoints(view.points);
    view.beams->SetLines(lines);
    view.beams->GetPointData()->SetScalars(view.magnitude);
    if (coloring.by_stress) {
      view.line_stress = cell_values(body.mesh.lines.rows());
      view.beams->GetCellData()->SetScalars(view.line_stress);
    }
    if (body.mesh.beam_radius > 0.0) {
      auto tube = vtkSmartPointer<vtkTubeFilter>::New();
      tube->SetInputData(view.beams);
      tube->SetRadius(body.mesh.beam_radius);
      tube->SetNumberOfSides(12);
      tube->CappingOn();
      add_colored_actor(renderer, coloring, nullptr, tube->GetOutputPort());
    } else {
      add_colored_actor(renderer, coloring, view.beams, nullptr)->GetProperty()->SetLineWidth(3.0f);
    }
  }
  return view;
}

void update_flexible_view(FlexibleView& view, const BodyState& state, const RowMatrix3d& x_W,
                          const Eigen::VectorXd& u_norm, double per_unit, double t) {
  for (Eigen::Index k = 0; k < x_W.rows(); ++k) {
    view.points->SetPoint(k, x_W(k, 0), x_W(k, 1), x_W(k, 2));
    view.magnitude->SetValue(k, per_unit * u_norm(k));
  }
  view.points->Modified();
  view.magnitude->Modified();
  // Beam solids: each point at its node, offset by the undeformed section turned with the body.
  if (view.solids) {
    const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
    const RowMatrix3d offset_W = view.solid_offset_B * R.transpose();
    vtkPoints* points = view.solids->GetPoints();
    for (Eigen::Index k = 0; k < offset_W.rows(); ++k) {
      const int node = view.solid_mesh.node[static_cast<std::size_t>(k)];
      points->SetPoint(k, x_W(node, 0) + offset_W(k, 0), x_W(node, 1) + offset_W(k, 1),
                       x_W(node, 2) + offset_W(k, 2));
      view.solid_magnitude->SetValue(k, per_unit * u_norm(node));
    }
    points->Modified();
    view.solid_magnitude->Modified();
  }
  // Element stresses of the history row at or before t [MPa] (lines first, then quads).
  if (view.stress) {
    const int lines = static_cast<int>(view.body->mesh.lines.rows());
    const Eigen::VectorXd values =
        view.stress->element_values(view.stress->row_at(t), lines + static_cast<int>(view.body->mesh.quads.rows())) / 1e6;
    if (view.line_stress) {
      for (int e = 0; e < lines; ++e) view.line_stress->SetValue(e, values(e));
      view.line_stress->Modified();
    }
    if (view.solid_stress) {
      for (int c = 0; c < view.solid_mesh.cell_count(); ++c) {
        view.solid_stress->SetValue(c, values(view.solid_mesh.beam[static_cast<std::size_t>(c)]));
      }
      view.solid_stress->Modified();
    }
    if (view.quad_stress) {
      for (Eigen::Index q = 0; q < view.body->mesh.quads.rows(); ++q) view.quad_stress->SetValue(q, values(lines + q));
      view.quad_stress->Modified();
    }
  }
  if (view.surface) view.surface->Modified();
  if (view.beams) view.beams->Modified();
  if (view.solids) view.solids->Modified();
}

}  // namespace limber::render
